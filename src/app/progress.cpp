#include "app/progress.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdio>

namespace ryushi {

Progress::Progress(double end_time, bool quiet)
    : end_(end_time), quiet_(quiet), tty_(isatty(STDOUT_FILENO) != 0), start_(Clock::now()), last_(start_) {}

void Progress::update(double time, long long steps) {
  if (quiet_) return;
  auto now = Clock::now();
  double since_last = std::chrono::duration<double>(now - last_).count();
  if (since_last < (tty_ ? 0.1 : 5.0)) return;
  last_ = now;
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double frac = end_ > 0 ? std::min(1.0, time / end_) : 1.0;
  double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0;
  double rate = elapsed > 0 ? steps / elapsed : 0;
  if (tty_) {
    constexpr int kWidth = 30;
    int filled = static_cast<int>(frac * kWidth);
    std::string bar(filled, '#');
    bar.append(kWidth - filled, '-');
    std::printf("\r[%s] %5.1f%%  t=%.4g/%.4g s  step %lld  %.0f steps/s  ETA %02d:%02d ", bar.c_str(),
                100 * frac, time, end_, steps, rate, static_cast<int>(eta) / 60, static_cast<int>(eta) % 60);
    std::fflush(stdout);
    drawn_ = true;
  } else {
    spdlog::info("t = {:.4g} / {:.4g} s ({:.1f}%), step {}, {:.0f} steps/s, ETA {:.0f} s", time, end_,
                 100 * frac, steps, rate, eta);
  }
}

void Progress::finish() {
  if (drawn_) {
    std::printf("\n");
    std::fflush(stdout);
  }
}

}  // namespace ryushi
