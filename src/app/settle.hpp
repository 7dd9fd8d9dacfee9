#pragma once
// Settling before t = 0 (a method's settle_steps, docs/isph.md, "Settling before t = 0"): the
// scene's lattice is not the discrete equilibrium everywhere (where a free surface meets a wall
// the symmetric pressure force pushes the corner particle at 0.03 g), and an undamped method
// carries that start-up through the run. So the step graph runs `steps` times with the clock held
// at t = 0 and every fluid velocity scaled by `factor` after each step, a damped descent into the
// nearest equilibrium. A fluid that is not at rest in its start (a dam-break column, a stirred
// tank) moves further than `max_displacement` spacings from the lattice: the settle stops, the
// start is restored as the scene made it, and the run begins from there. A fluid that starts
// moving is not settled at all.
#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "ecs/component.hpp"
#include "ecs/resources.hpp"
#include "ecs/scheduler.hpp"
#include "ecs/system.hpp"
#include "ecs/world.hpp"

namespace ryushi {

struct SettleSettings {
  long steps = 0;                 // 0: no settling
  double factor = 0.99;           // each fluid velocity scaled by this after every step
  double max_displacement = 0.5;  // spacings: a particle moved further was not at rest
};

struct SettleReport {
  long requested = 0;               // the method's settle_steps (0: the method does not settle)
  long steps = 0;                   // settling steps taken (those of a refused settle included)
  bool at_rest = false;             // false: the start was restored as the scene made it
  double largest_displacement = 0;  // spacings, at the end (or where the settle stopped)
  double wall_s = 0;
  std::string refused;  // why the start was restored: "" when it settled
};

// progress (may be empty): called after each step with the steps taken and the report so far.
template <int D>
SettleReport settle(Scheduler<D>& scheduler, World<D>& world, Resources& res, const SettleSettings& s,
                    double spacing, const std::function<void(const SettleReport&)>& progress = {}) {
  SettleReport report;
  if (s.steps <= 0) return report;
  // The columns a step writes that decide the next one: restored if the fluid was not at rest.
  const auto& kind = world.column(components::kind);  // no step changes it
  const auto x0 = world.column(components::position);
  const auto v0 = world.column(components::velocity);
  const bool has_pressure = world.has(components::pressure.name);
  const std::vector<double> p0 = has_pressure ? world.column(components::pressure) : std::vector<double>{};
  const double dt0 = res.get(resources::dt), limit = s.max_displacement * spacing;
  // A fluid given a velocity (a rotating square, an inflow) is not at rest, and the damping would
  // take its motion away.
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == kFluid && v0[i].squaredNorm() > 0) {
      report.refused = "the fluid starts moving";
      return report;
    }
  bool moved_away = false;
  for (; report.steps < s.steps && !moved_away; ++report.steps) {
    try {
      scheduler.step();
    } catch (const std::exception& e) {  // the run's first step will meet it again, if it is real
      report.refused = std::string("a settling step failed: ") + e.what();
      moved_away = true;
      break;
    }
    res.get(resources::time) = 0.0;
    // A particle that would leave or come (an outflow, a split): not a start to settle, and the
    // change must not reach the run's first step.
    if (res.has(structural_changes_resource<D>.name) && !res.get(structural_changes_resource<D>).empty()) {
      res.get(structural_changes_resource<D>) = CommandBuffer<D>{};
      report.refused = "particles would leave or come";
      moved_away = true;
      break;
    }
    auto& x = world.column(components::position);
    auto& v = world.column(components::velocity);
    double largest = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (kind[i] != kFluid) continue;
      v[i] *= s.factor;
      largest = std::max(largest, (x[i] - x0[i]).norm());
    }
    report.largest_displacement = largest / spacing;
    moved_away = largest > limit;
    if (moved_away) {
      char why[120];
      std::snprintf(why, sizeof why, "not at rest: a particle moved %.3g spacings (the limit %.3g)",
                    report.largest_displacement, s.max_displacement);
      report.refused = why;
    }
    if (progress) progress(report);
  }
  report.at_rest = !moved_away;
  if (!report.at_rest) {
    world.column(components::position) = x0;
    world.column(components::velocity) = v0;
    if (has_pressure) world.column(components::pressure) = p0;
    res.get(resources::dt) = dt0;
  }
  res.get(resources::time) = 0.0;
  return report;
}

}  // namespace ryushi
