#pragma once
// Progress while a run goes: a one-line bar (simulated time, steps/s, ETA) redrawn in place
// when stdout is a terminal; otherwise a plain log line every few seconds, so CI logs and
// files stay readable.
#include <chrono>
#include <string>

namespace ryushi {

class Progress {
 public:
  Progress(double end_time, bool quiet);
  void update(double time, long long steps);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  double end_;
  bool quiet_, tty_;
  Clock::time_point start_, last_;
  bool drawn_ = false;
};

}  // namespace ryushi
