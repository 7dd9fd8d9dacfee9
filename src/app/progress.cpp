#include "app/progress.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ryushi {

ProgressRate progress_rate(double start_time, long long start_step, double time, long long steps,
                           double elapsed, double end_time) {
  // Simulated time advanced by this process, extrapolated at its mean rate so far.
  const double advanced = time - start_time;
  return {elapsed > 0 ? static_cast<double>(steps - start_step) / elapsed : 0,
          advanced > 0 ? elapsed * std::max(0.0, end_time - time) / advanced : 0};
}

Progress::Progress(double start_time, long long start_step, double end_time, bool quiet)
    : start_time_(start_time),
      end_(end_time),
      start_step_(start_step),
      quiet_(quiet),
      tty_(isatty(STDOUT_FILENO) != 0),
      start_(Clock::now()),
      last_(start_) {}

void Progress::update(double time, long long steps) {
  if (quiet_) return;
  auto now = Clock::now();
  double since_last = std::chrono::duration<double>(now - last_).count();
  if (since_last < (tty_ ? 0.1 : 5.0)) return;
  last_ = now;
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double frac = end_ > 0 ? std::min(1.0, time / end_) : 1.0;
  const auto [rate, eta] = progress_rate(start_time_, start_step_, time, steps, elapsed, end_);
  if (tty_) {
    constexpr int kWidth = 30;
    int filled = static_cast<int>(frac * kWidth);
    std::string bar(filled, '#');
    bar.append(kWidth - filled, '-');
    const long long seconds = std::llround(eta);
    std::printf("\r[%s] %5.1f%%  t=%.4g/%.4g s  step %lld  %.3g steps/s  ETA %lld:%02lld:%02lld ",
                bar.c_str(), 100 * frac, time, end_, steps, rate, seconds / 3600, seconds / 60 % 60,
                seconds % 60);
    std::fflush(stdout);
    drawn_ = true;
  } else {
    spdlog::info("t = {:.4g} / {:.4g} s ({:.1f}%), step {}, {:.3g} steps/s, ETA {:.0f} s", time, end_,
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
