#pragma once
// Profiler: wall time per system, recorded by the scheduler (never by the systems), plus an
// optional Chrome trace (one span per system run, on the thread that ran it).
#include <tbb/concurrent_vector.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ryushi {

class Profiler {
 public:
  using Clock = std::chrono::steady_clock;

  struct Entry {
    std::string name;
    std::int64_t calls = 0;
    double total_s = 0;
  };

  explicit Profiler(bool trace = false) : trace_(trace), origin_(Clock::now()) {}

  // Registers (or finds) the slot for a name. Not thread-safe: call while building pipelines.
  std::size_t slot(const std::string& name);
  // Adds one timed call to a slot. A slot is only ever timed by one running node at a time.
  void record(std::size_t slot, Clock::time_point begin, Clock::time_point end);
  void add_step_time(double s) { step_total_s_ += s; }
  double step_total_s() const { return step_total_s_; }
  // Adds the calls and seconds of an earlier segment of the run (a checkpoint's), by name.
  void restore(const std::vector<Entry>& earlier, double step_total_s);
  // Forgets every slot's calls and time (the steps that settled the start are not the run's).
  void clear_times() {
    for (auto& e : entries_) e.calls = 0, e.total_s = 0;
    step_total_s_ = 0;
  }

  const std::vector<Entry>& entries() const { return entries_; }
  double accounted_s() const;
  bool tracing() const { return trace_; }

  // Table sorted by total time (the end-of-run table).
  std::string table() const;
  std::string json() const;
  std::string trace_json() const;

  // RAII timer for work done by the driver (output, probes, reordering).
  class Scope {
   public:
    Scope(Profiler& p, std::size_t slot) : p_(p), slot_(slot), begin_(Clock::now()) {}
    ~Scope() { p_.record(slot_, begin_, Clock::now()); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    Profiler& p_;
    std::size_t slot_;
    Clock::time_point begin_;
  };

 private:
  struct Span {
    std::size_t slot;
    std::int64_t begin_us, dur_us;
    std::size_t thread;
  };
  bool trace_;
  Clock::time_point origin_;
  std::vector<Entry> entries_;
  std::map<std::string, std::size_t> index_;
  double step_total_s_ = 0;
  tbb::concurrent_vector<Span> spans_;
};

}  // namespace ryushi
