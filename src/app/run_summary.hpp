#pragma once
// Runner<D>::write_summary: summary.json, written with every frame and at the end (status,
// particles, steps, times, speed, bytes per particle, the solver's figures, diagnostics,
// metrics); docs/output.md lists its keys.
#include <sys/resource.h>

#include "app/runner.hpp"

namespace ryushi {

template <int D>
void Runner<D>::write_summary(const std::string& status, const std::string& message) {
  auto now = diagnose(world_, context_.rho0);
  double wall = wall_elapsed();
  // A method without a neighbour search (a plugin's) has no list to report.
  static const NeighbourList empty_list;
  const auto& nl = res_.has(neighbours_resource.name) ? res_.get(neighbours_resource) : empty_list;
  JsonWriter w;
  w.begin_object();
  w.key("scene").value(scene_.name);
  w.key("scene_file").value(scene_.path);
  w.key("method").value(scene_.method);
  w.key("dimension").value(std::int64_t{D});
  w.key("status").value(status);
  w.key("message").value(message);
  w.key("particles").value(static_cast<std::int64_t>(world_.size()));
  w.key("fluid_particles").value(static_cast<std::int64_t>(now.fluid));
  w.key("wall_particles").value(static_cast<std::int64_t>(now.walls));
  w.key("steps").value(static_cast<std::int64_t>(step_));
  w.key("simulated_time").value(time_);
  w.key("end_time").value(scene_.end_time);
  w.key("wall_time_s").value(wall);
  w.key("particle_steps_per_second").value(wall > 0 ? world_.size() * double(step_) / wall : 0.0);
  w.key("frames").value(static_cast<std::int64_t>(frames_.size()));
  // Steps per build tell whether a Verlet skin pays ([particles] neighbour_skin).
  w.key("neighbour_list_builds").value(static_cast<std::int64_t>(nl.builds));
  w.key("bytes_per_particle").begin_object();
  w.key("columns").value(static_cast<std::int64_t>(world_.bytes_per_particle()));
  w.key("neighbour_list").value(world_.size() ? double(nl.bytes()) / world_.size() : 0.0);
  if (res_.has(solve_statistics_resource.name) && world_.size()) {
    // The pressure solve's memory at its largest step, per particle of the world (MPS, ISPH).
    const auto& st = res_.get(solve_statistics_resource);
    const double n = double(world_.size());
    w.key("pressure_matrix").value(st.max_matrix_bytes / n);
    w.key("pressure_preconditioner").value(st.max_preconditioner_bytes / n);
    w.key("pressure_krylov_vectors").value(st.max_krylov_bytes / n);
  }
  w.end_object();
  // The memory guard's estimate made before the run allocated (app/memory_estimate.hpp) beside
  // the process's peak resident set so far: how far the estimate is off for this scene.
  w.key("memory").begin_object();
  w.key("estimated_bytes").value(estimated_bytes_);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  w.key("peak_resident_bytes").value(1024.0 * usage.ru_maxrss);
  w.end_object();
  if (settled_.requested > 0) {  // the start's settling (app/settle.hpp), before t = 0
    w.key("settle").begin_object();
    w.key("steps").value(static_cast<std::int64_t>(settled_.steps));
    w.key("at_rest").value(settled_.at_rest);
    w.key("largest_displacement").value(settled_.largest_displacement);
    w.key("wall_time_s").value(settled_.wall_s);
    w.key("refused").value(settled_.refused);
    w.end_object();
  }
  w.key("parameters").begin_object();
  w.key("spacing").value(scene_.spacing);
  for (auto& [name, value] : method_parameters_) w.key(name).value(value);
  w.key("last_dt").value(dt_used_);
  w.end_object();
  w.key("diagnostics").begin_object();
  w.key("fluid_mass_initial").value(initial_.fluid_mass);
  w.key("fluid_mass").value(now.fluid_mass);
  w.key("fluid_mass_relative_change")
      .value(initial_.fluid_mass > 0 ? (now.fluid_mass - initial_.fluid_mass) / initial_.fluid_mass : 0.0);
  w.key("fluid_volume").value(now.fluid_volume);
  w.key("fluid_volume_relative_change")
      .value(initial_.fluid_volume > 0 ? (now.fluid_volume - initial_.fluid_volume) / initial_.fluid_volume
                                       : 0.0);
  if (scene_.outflow_removes) {
    w.key("removed_particles").value(static_cast<std::int64_t>(removed_));
    w.key("removed_mass").value(removed_mass_);
  }
  w.key("kinetic_energy").value(now.kinetic_energy);
  for (int a = 0; a < D; ++a) w.key(std::string("momentum_") + "xyz"[a]).value(now.momentum[a]);
  w.key("momentum_scale").value(now.momentum_scale);
  w.key("max_speed").value(now.max_speed);
  w.key("max_density_deviation").value(now.max_density_deviation);
  // Over every step of the run so far, not this state alone (health_monitor.hpp); not where the
  // density column may vanish (MPS: an isolated particle's number density is 0, a deviation of 1).
  if (!density_may_vanish_) {
    const auto& extremes = health_.extremes();
    w.key("run_max_density_deviation").value(extremes.density_deviation);
    w.key("run_max_density_deviation_time").value(extremes.density_time);
    w.key("run_max_fluid_volume_change").value(extremes.volume_change);
    w.key("run_max_fluid_volume_change_time").value(extremes.volume_time);
  }
  if (method_diagnostics_)
    for (auto& [name, value] : method_diagnostics_(world_, res_)) {
      w.key(name).value(value);
      if (step_ == 0) continue;  // before the first step the method has computed nothing yet
      auto [it, first] = diagnostic_range_.try_emplace(name, value, value);
      if (!first) it->second = {std::min(it->second.first, value), std::max(it->second.second, value)};
    }
  w.end_object();
  // The method's diagnostics at every summary of this process after its first step (each frame
  // and the end): their least and largest, [min, max].
  w.key("diagnostics_range").begin_object();
  for (auto& [name, range] : diagnostic_range_) {
    w.key(name).begin_array();
    w.value(range.first);
    w.value(range.second);
    w.end_array();
  }
  w.end_object();
  w.key("metrics").begin_object();
  for (auto& [name, value] : metrics()) w.key(name).value(value);
  w.end_object();
  w.key("run_id").value(run_id_hex(run_id_));
  w.key("health").begin_object();
  w.key("action").value(std::string(scene_.health.warn ? "warn" : "stop"));
  w.key("pressure_scale").value(health_.pressure_scale());
  w.key("energy_scale").value(health_.energy_scale());  // 0: the energy is not checked
  w.key("warnings").begin_array();
  for (auto& text : health_warnings_) w.value(text);
  w.end_array();
  w.end_object();
  if (res_.has(solve_statistics_resource.name)) {
    const auto& st = res_.get(solve_statistics_resource);
    w.key("linear_solver").begin_object();
    w.key("krylov").value(st.krylov.empty() ? scene_.solver.krylov : st.krylov);
    w.key("preconditioner").value(scene_.solver.preconditioner);
    w.key("cycle").value(scene_.solver.cycle);
    w.key("precision").value(scene_.solver.precision);
    w.key("tolerance").value(scene_.solver.tolerance);
    w.key("solves").value(static_cast<std::int64_t>(st.solves));
    w.key("mean_iterations").value(st.solves ? double(st.iterations) / st.solves : 0.0);
    w.key("max_iterations").value(static_cast<std::int64_t>(st.max_iterations));
    w.key("max_relative_residual").value(st.max_relative_residual);
    w.key("max_unknowns").value(static_cast<std::int64_t>(st.max_rows));
    w.key("max_nonzeros").value(static_cast<std::int64_t>(st.max_nonzeros));
    w.key("preconditioner_fallbacks").value(static_cast<std::int64_t>(st.preconditioner_fallbacks));
    w.end_object();
  }
  w.end_object();
  write_text_atomic(out_ / "summary.json", w.str());
}

}  // namespace ryushi
