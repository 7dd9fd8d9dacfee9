#pragma once
// Runner<D>::settle_start: the method's settling before t = 0 (app/settle.hpp), timed and logged;
// its steps leave nothing in the profile or the solver's statistics (they are not the run's).
#include <chrono>

#include "app/runner.hpp"

namespace ryushi {

template <int D>
void Runner<D>::settle_start() {
  if (settled_.requested <= 0) return;
  if (!opt_.quiet) spdlog::info("settling the start: up to {} steps before t = 0", settled_.requested);
  const auto begin = std::chrono::steady_clock::now();
  const long requested = settled_.requested;
  // A line every 10 s of wall time: a large scene's settle takes minutes before its first frame.
  auto last = begin;
  auto report_progress = [&](const SettleReport& r) {
    const auto now = std::chrono::steady_clock::now();
    if (opt_.quiet || now - last < std::chrono::seconds(10)) return;
    last = now;
    spdlog::info("settling: step {} of {}, particles moved up to {:.3f} spacings", r.steps + 1, requested,
                 r.largest_displacement);
  };
  settled_ = settle<D>(*scheduler_, world_, res_, SettleSettings{requested}, scene_.spacing, report_progress);
  settled_.requested = requested;
  settled_.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  profiler_.clear_times();
  if (res_.has(solve_statistics_resource.name)) res_.get(solve_statistics_resource) = LinearSolveStatistics{};
  if (opt_.quiet) return;
  if (settled_.at_rest)
    spdlog::info("settled in {} steps ({:.2f} s): particles moved up to {:.3f} spacings", settled_.steps,
                 settled_.wall_s, settled_.largest_displacement);
  else
    spdlog::info("not settled after {} steps ({}): the run starts as the scene made it", settled_.steps,
                 settled_.refused);
}

}  // namespace ryushi
