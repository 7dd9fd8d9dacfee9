#include "ecs/profiler.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <sstream>
#include <thread>

#include "io/json.hpp"

namespace ryushi {

std::size_t Profiler::slot(const std::string& name) {
  auto it = index_.find(name);
  if (it != index_.end()) return it->second;
  entries_.push_back({name, 0, 0.0});
  index_[name] = entries_.size() - 1;
  return entries_.size() - 1;
}

void Profiler::record(std::size_t s, Clock::time_point begin, Clock::time_point end) {
  auto& e = entries_[s];
  e.calls += 1;
  e.total_s += std::chrono::duration<double>(end - begin).count();
  if (trace_) {
    auto us = [&](Clock::time_point t) {
      return std::chrono::duration_cast<std::chrono::microseconds>(t - origin_).count();
    };
    spans_.push_back({s, us(begin), us(end) - us(begin),
                      std::hash<std::thread::id>{}(std::this_thread::get_id())});
  }
}

void Profiler::restore(const std::vector<Entry>& earlier, double step_total_s) {
  for (auto& e : earlier) {
    auto& mine = entries_[slot(e.name)];
    mine.calls += e.calls;
    mine.total_s += e.total_s;
  }
  step_total_s_ += step_total_s;
}

double Profiler::accounted_s() const {
  double t = 0;
  for (auto& e : entries_) t += e.total_s;
  return t;
}

std::string Profiler::table() const {
  std::vector<Entry> sorted = entries_;
  std::sort(sorted.begin(), sorted.end(),
            [](const Entry& a, const Entry& b) { return a.total_s > b.total_s; });
  double total = accounted_s();
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "%-40s %10s %11s %11s %7s\n", "system", "calls", "total_s",
                "mean_us", "share");
  out << line;
  for (auto& e : sorted) {
    std::snprintf(line, sizeof line, "%-40s %10lld %11.3f %11.1f %6.1f%%\n", e.name.c_str(),
                  static_cast<long long>(e.calls), e.total_s,
                  e.calls ? 1e6 * e.total_s / e.calls : 0.0,
                  total > 0 ? 100.0 * e.total_s / total : 0.0);
    out << line;
  }
  return out.str();
}

std::string Profiler::json() const {
  double total = accounted_s();
  JsonWriter w;
  w.begin_object();
  w.key("accounted_s").value(total);
  w.key("step_wall_s").value(step_total_s_);
  w.key("systems").begin_array();
  for (auto& e : entries_) {
    w.begin_object();
    w.key("name").value(e.name);
    w.key("calls").value(e.calls);
    w.key("total_s").value(e.total_s);
    w.key("mean_s").value(e.calls ? e.total_s / e.calls : 0.0);
    w.key("share").value(total > 0 ? e.total_s / total : 0.0);
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return w.str();
}

std::string Profiler::trace_json() const {
  // Chrome trace event format; thread hashes are mapped to small ids for readability.
  std::map<std::size_t, int> tids;
  JsonWriter w;
  w.begin_object();
  w.key("traceEvents").begin_array();
  for (auto& s : spans_) {
    auto [it, _] = tids.emplace(s.thread, static_cast<int>(tids.size()));
    w.begin_object();
    w.key("name").value(entries_[s.slot].name);
    w.key("ph").value("X");
    w.key("ts").value(s.begin_us);
    w.key("dur").value(s.dur_us);
    w.key("pid").value(std::int64_t{1});
    w.key("tid").value(std::int64_t{it->second});
    w.end_object();
  }
  w.end_array();
  w.key("displayTimeUnit").value("ms");
  w.end_object();
  return w.str();
}

}  // namespace ryushi
