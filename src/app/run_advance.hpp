#pragma once
// Runner<D>::advance: one step of the run (app/runner.hpp).
#include "app/runner.hpp"

namespace ryushi {

template <int D>
void Runner<D>::advance() {
  // Also before the first step: the scene's blocks come in lattice order, walls after the fluid,
  // a whole block apart in index until the first reorder (which keeps WCSPH's each-pair-once pass
  // from running in parallel blocks). It sorts by a grid of the neighbour search's cell (or of the
  // kernel's support, two spacings at least), since no search has run yet: in another grid's order
  // every row of the first list is sorted (3D MPS at 1M particles: 3 s of the first step), and so
  // is every row rebuilt until the next reorder. It once followed the first step, which ran on
  // the unsorted lattice and rebuilt the list a second time (MPS at 1.36M particles: 1.0 s).
  if (scene_.reorder_interval > 0 && step_ % scene_.reorder_interval == 0) {
    Profiler::Scope t(profiler_, slot_reorder_);
    CellGrid<D> start_grid;
    std::span<const std::uint32_t> order;
    if (!restored_order_.empty()) {
      order = restored_order_;                                         // the first step after a resume
    } else if (step_ == 0 || !res_.has(cell_grid_resource<D>.name)) {  // (no search: every time)
      start_grid.build(
          context_.domain,
          search_cell_ > 0 ? search_cell_ : std::max(context_.kernel.support(), 2 * context_.spacing),
          world_.column(components::position));
      order = start_grid.sorted();
    } else {
      order = res_.get(cell_grid_resource<D>).sorted();
    }
    if (order.size() == world_.size()) {
      CommandBuffer<D> cb;
      cb.permute({order.begin(), order.end()});
      cb.apply(world_);
    }
  }
  restored_order_.clear();
  double& dt = res_.get(resources::dt);
  if (scene_.fixed_dt > 0)
    dt = scene_.fixed_dt;
  else if (res_.has(resources::dt_limit.name))
    dt = std::min(dt, res_.get(resources::dt_limit));
  if (!(dt >= scene_.dt_min))
    throw NumericalFailure("step " + std::to_string(step_) + " (t = " + fmt(time_) + " s): time step " +
                           fmt(dt) + " s fell below time.dt_min = " + fmt(scene_.dt_min) +
                           " s (system 'time_step_control')");
  // Land exactly on the next output time (or time.end) without a sliver of a last step: when
  // less than two steps remain, split the rest evenly. dt_chosen keeps the control's step.
  res_.get(resources::dt_chosen) = dt;
  const double target = std::min(next_output_, scene_.end_time);
  const double rest = target - time_;
  const bool lands = dt * (1 + 1e-9) >= rest;  // a fixed dt that divides the interval lands
  if (lands)
    dt = rest;
  else if (2 * dt > rest)
    dt = 0.5 * rest;
  dt_used_ = dt;
  res_.get(resources::step) = step_;
  auto begin = std::chrono::steady_clock::now();
  try {
    scheduler_->step();
  } catch (const AccessViolation&) {
    throw;
  } catch (const std::exception& e) {
    throw NumericalFailure("step " + std::to_string(step_) + ": " + e.what());
  }
  if (res_.has(structural_changes_resource<D>.name)) {
    auto& changes = res_.get(structural_changes_resource<D>);
    if (!changes.empty()) changes.apply(world_);
  }
  profiler_.add_step_time(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
  time_ = lands ? target : time_ + dt_used_;  // frame times exactly as asked, no round-off
  res_.get(resources::time) = time_;
  ++step_;
  check_state();
  check_health();
}

}  // namespace ryushi
