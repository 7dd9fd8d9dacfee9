#pragma once
// Runner<D>'s checkpoints (docs/output.md): the whole state (columns, time, step, frames, probe
// rows, the cell order, each system's own state) written atomically to OUT/checkpoint.h5, and
// the restore that continues a run bit for bit.
#include "app/runner.hpp"

namespace ryushi {

template <int D>
Checkpoint Runner<D>::checkpoint_state() const {
  Checkpoint c;
  auto& k = c.clock;
  k.time = time_, k.step = step_, k.dt = res_.get(resources::dt),
  k.dt_chosen = res_.get(resources::dt_chosen);
  k.next_output = next_output_, k.next_probe = next_probe_, k.next_checkpoint = next_checkpoint_;
  k.initial_fluid_mass = initial_.fluid_mass, k.initial_fluid_volume = initial_.fluid_volume;
  k.removed = (long long)removed_, k.removed_mass = removed_mass_;
  k.wall_time_s = wall_elapsed(), k.profile_step_total_s = profiler_.step_total_s();
  c.profile = profiler_.entries();
  c.scene.path = fs::absolute(scene_.path).string();
  c.scene.text = scene_text_;
  c.scene.overrides = with_end_time(opt_);
  // The resolved frame and probe intervals: their defaults follow time.end, and a resume with
  // --end-time must keep the run's own.
  char b[80];
  std::snprintf(b, sizeof b, "output.interval=%.17g", scene_.output_interval);
  c.scene.overrides.push_back(b);
  std::snprintf(b, sizeof b, "output.probe_interval=%.17g", scene_.probe_interval);
  c.scene.overrides.push_back(b);
  // And the checkpoint interval, which `run --checkpoint-interval` may have set outside the
  // scene: without it a resumed run wrote no checkpoint, and its next stop lost the segment.
  std::snprintf(b, sizeof b, "output.checkpoint_interval=%.17g", checkpoint_interval_);
  c.scene.overrides.push_back(b);
  c.scene.version = "ryushi 0.1.0";
  c.scene.dimension = D;
  c.scene.run_id = run_id_;
  c.frames = frames_;
  c.probe_rows = probe_rows_;
  if (res_.has(cell_grid_resource<D>.name)) {  // a method without a neighbour search has none
    auto order = res_.get(cell_grid_resource<D>).sorted();
    c.cell_order.assign(order.begin(), order.end());
  }
  for (auto& system : scheduler_->pipeline())
    c.system_states.push_back({system->name(), system->checkpoint_state(world_, res_)});
  c.monitor_state = health_.state();
  return c;
}

// The run's wall time: this segment's plus those before a resume.

template <int D>
void Runner<D>::write_checkpoint_now() {
  Profiler::Scope t(profiler_, slot_output_);
  next_checkpoint_ = (std::floor(time_ / checkpoint_interval_ + 1e-9) + 1) * checkpoint_interval_;
  write_checkpoint<D>(out_ / "checkpoint.h5", world_, checkpoint_state());
}

// The state of the checkpoint replaces the freshly built world and the driver's clock.

template <int D>
void Runner<D>::restore() {
  auto c = read_checkpoint_header(resume_);
  restore_checkpoint_columns<D>(resume_, world_);
  auto& k = c.clock;
  time_ = k.time, step_ = k.step;
  res_.get(resources::dt) = k.dt;
  res_.get(resources::dt_chosen) = k.dt_chosen;
  res_.get(resources::time) = time_;
  res_.get(resources::step) = step_;
  next_output_ = k.next_output, next_probe_ = k.next_probe, next_checkpoint_ = k.next_checkpoint;
  initial_.fluid_mass = k.initial_fluid_mass, initial_.fluid_volume = k.initial_fluid_volume;
  removed_ = std::size_t(k.removed), removed_mass_ = k.removed_mass;
  wall_before_ = k.wall_time_s;
  profiler_.restore(c.profile, k.profile_step_total_s);
  frames_ = c.frames;
  probe_rows_ = c.probe_rows;
  // The frames the checkpoint lists must be this run's: a fresh run into the folder since (or a
  // copy of another run's frames) would otherwise mix two runs in one particles.xdmf.
  run_id_ = c.scene.run_id;
  const fs::path dir = resume_.parent_path();
  for (auto& f : frames_) {
    const fs::path file = dir / f.file;
    if (!fs::exists(file))
      throw SceneError(resume_.string() + ": its frame " + file.string() + " is missing");
    std::uint64_t id = 0;
    try {
      id = frame_run_id(file);
    } catch (const std::runtime_error& e) {
      throw SceneError(resume_.string() + ": " + e.what());
    }
    if (run_id_ && id != run_id_)
      throw SceneError(resume_.string() + ": its frame " + file.string() +
                       " belongs to another run (run id " + run_id_hex(id) + ", the checkpoint's " +
                       run_id_hex(run_id_) + ")");
  }
  restored_monitor_ = c.monitor_state;
  restored_order_ = c.cell_order;
  auto& pipeline = scheduler_->pipeline();
  if (c.system_states.size() != pipeline.size())
    throw SceneError(resume_.string() + ": the checkpoint's pipeline has " +
                     std::to_string(c.system_states.size()) + " systems, this build's " +
                     std::to_string(pipeline.size()));
  for (std::size_t k = 0; k < pipeline.size(); ++k) {
    if (c.system_states[k].first != pipeline[k]->name())
      throw SceneError(resume_.string() + ": system " + std::to_string(k) + " is '" +
                       c.system_states[k].first + "' in the checkpoint, '" + pipeline[k]->name() + "' here");
    pipeline[k]->restore_state(world_, res_, c.system_states[k].second);
  }
}

}  // namespace ryushi
