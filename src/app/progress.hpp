#pragma once
// Progress while a run goes: a one-line bar (simulated time, steps/s, ETA) redrawn in place
// when stdout is a terminal; otherwise a plain log line every few seconds, so CI logs and
// files stay readable. The rate and the ETA count from where this process started (a resumed
// run starts part-way: its earlier steps and simulated time took another process's wall time).
#include <chrono>
#include <string>

namespace ryushi {

// Steps per second and the seconds left, from what this process did: it started at
// (start_time, start_step) and after `elapsed` seconds stands at (time, steps).
struct ProgressRate {
  double steps_per_second, eta_s;
};
ProgressRate progress_rate(double start_time, long long start_step, double time, long long steps,
                           double elapsed, double end_time);

class Progress {
 public:
  Progress(double start_time, long long start_step, double end_time, bool quiet);
  void update(double time, long long steps);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  double start_time_, end_;
  long long start_step_;
  bool quiet_, tty_;
  Clock::time_point start_, last_;
  bool drawn_ = false;
};

}  // namespace ryushi
