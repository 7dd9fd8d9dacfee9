// 30% initial disorder (issue 9): the shipped resting tanks (0.5 m of water, d = 0.0125 m, 1600
// particles) start with every fluid particle displaced by up to 0.3 d on each axis
// ([particles] disorder = 0.3). The disorder starts the particles off the lattice the kernels and
// the reference densities were set up on; a resting tank is a stable equilibrium, so what the
// disorder releases must die away:
//   - the run completes and keeps every particle;
//   - the energy ends within M g d / 2 of its start (15.3 J/m): the start's positions are
//     uncertain by 0.3 d, and the volume each method assigns them may move the surface, and the
//     centre of mass, by a fraction of a spacing (measured: WCSPH -10.7 J/m, MPS +5.3);
//   - the motion decays: the rms speed at the end is below a tenth of its largest value in the
//     run (for a method whose resting tank is never still: the part above that tank's rms speed,
//     in quadrature), and below 1% of the wave speed sqrt(g H) (0.022 m/s), or, for that method,
//     below 1.5x its own undisturbed tank's rms speed at the same time.
// Until 2026-11-29 "settles" meant an rms speed below 5% of sqrt(g H) at t = 1 s (audit row 33):
// 0.11 m/s, room for MPS's 0.087 and for two ISPH set-ups whose motion was growing (below).
// Measured (2026-11-29): WCSPH to 1 s, rms speed 0.0545 m/s at 0.05 s, 0.0022 at the end. MPS to
// 2 s: 0.56 m/s at its largest, 0.085 at 2 s against the undisturbed MPS tank's 0.073 (0.043 above
// it in quadrature): MPS's pressure
// noise keeps a resting tank moving at 0.075-0.080 m/s rms from t = 1.5 s (3.4% of sqrt(g H);
// docs/mps.md), and the disorder decays to that floor.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "stability_util.hpp"

using namespace ryushi;

namespace {

constexpr double kMass = 1000 * 0.5 * 0.5, kG = 9.81, kDepth = 0.5, kSpacing = 0.0125;

double rms_speed(double kinetic) {
  return std::sqrt(2 * kinetic / kMass);
}

// The rms speed at the first probe row at or after t.
double rms_speed_at(const test::EnergySeries& e, double t) {
  for (std::size_t k = 0; k < e.time.size(); ++k)
    if (e.time[k] >= t - 1e-9) return rms_speed(e.kinetic[k]);
  return rms_speed(e.kinetic.back());
}

// Runs the disordered tank to `end`; the checks of the comment at the top. `floor` > 0: the
// method's undisturbed tank's rms speed at `end` (its resting noise), the end's bound 1.5x it.
void check_disordered_tank(const std::string& label, const std::string& scene, std::vector<std::string> sets,
                           double end = 1.0, double floor = 0) {
  sets.insert(sets.end(),
              {"particles.disorder=0.3", "time.end=" + std::to_string(end), "output.probe_interval=0.01"});
  auto o = test::run_shipped("disorder_" + label, scene, sets);
  INFO(label);
  test::require_completed(o);
  CHECK(test::json_number(o.summary, "fluid_particles") == 1600);
  auto e = test::energy(o);
  const double change = e.total.back() - e.total.front();
  const double end_speed = rms_speed(e.kinetic.back());
  const double peak = rms_speed(*std::max_element(e.kinetic.begin(), e.kinetic.end()));
  MESSAGE(label, ": energy change ", change, " J/m, rms speed largest ", peak, " m/s, at the end ", end_speed,
          " m/s", (floor > 0 ? " (undisturbed tank " + std::to_string(floor) + " m/s)" : std::string()));
  CHECK(std::abs(change) <= kMass * kG * kSpacing / 2);
  // The disorder's share: the kinetic energy above the resting noise (energies add; rms speeds in
  // quadrature), at most 1% of its largest value.
  const double excess = std::sqrt(std::max(0.0, end_speed * end_speed - floor * floor));
  CHECK(excess < 0.1 * peak);
  if (floor > 0)
    CHECK(end_speed < 1.5 * floor);
  else
    CHECK(end_speed < 0.01 * std::sqrt(kG * kDepth));
}

// The undisturbed shipped tank's rms speed at `end`.
double resting_noise(const std::string& label, const std::string& scene, double end) {
  auto o = test::run_shipped("resting_" + label, scene, {"time.end=" + std::to_string(end)});
  test::require_completed(o);
  return rms_speed(test::energy(o).kinetic.back());
}

// A known failure to settle (the pattern of the paper's shifting below): the run completes and
// the rms speed at t = 2 s is more than `growth` times its value at 0.4 s, or it stops cleanly
// (exit 3). A run that completes without the growth turns the case red: the defect may be fixed.
void check_growing_tank(const std::string& label, std::vector<std::string> sets, double growth) {
  sets.insert(sets.end(), {"particles.disorder=0.3", "time.end=2.0", "output.probe_interval=0.01"});
  auto o = test::run_shipped("disorder_" + label, "hydrostatic_isph_2d.toml", sets);
  INFO(label);
  if (o.code != kExitDone) {
    test::check_clean_failure(o, label);
    return;
  }
  auto e = test::energy(o);
  const double early = rms_speed_at(e, 0.4), late = rms_speed(e.kinetic.back());
  MESSAGE(label, ": rms speed ", early, " m/s at t = 0.4 s, ", late, " m/s at 2 s");
  CHECK_MESSAGE(late > growth * early, label << ": the rms speed no longer grows " << growth
                                             << "x from t = 0.4 to 2 s: the tank may settle now; if it does, "
                                                "make this case check_disordered_tank");
}

}  // namespace

TEST_CASE("stability: a WCSPH tank started with 30% disorder settles") {
  check_disordered_tank("wcsph", "hydrostatic_2d.toml", {});
}
TEST_CASE("stability: an MPS tank started with 30% disorder settles to MPS's own resting noise") {
  const double floor = resting_noise("mps", "hydrostatic_mps_2d.toml", 2.0);
  check_disordered_tank("mps", "hydrostatic_mps_2d.toml", {}, 2.0, floor);
}
// Two ISPH set-ups that looked settled at t = 1 s (rms 0.016 and 0.010 m/s, under the old bound)
// and grow: measured to 3 s (2026-11-29), Fickian shifting 0.009 m/s at 0.4 s, 0.018 at 1 s, 0.049
// at 2 s, 0.26 at 3 s; density shifting at C = 0.02 (4x the paper's) 0.007, 0.011, 0.131 at 2 s,
// and a particle out of the tank at t = 2.14 s (exit 3). The undisturbed ISPH tank stays below
// 2e-4 m/s. Issue 49 (a set-up that rests) owns the defect.
TEST_CASE(
    "stability: an ISPH tank with Fickian shifting started with 30% disorder does not settle (known: it "
    "grows)") {
  check_growing_tank("isph_fickian", {"shifting.model=fickian"}, 3.0);
}
TEST_CASE(
    "stability: an ISPH tank with density shifting at C = 0.02 started with 30% disorder does not settle "
    "(known: it "
    "grows)") {
  check_growing_tank("isph_density_c002", {"shifting.coefficient=0.02"}, 3.0);
}

// The paper's density-based shifting moves a particle by C h (...) per step with C = 0.005,
// which at CFL 0.2 does not undo a 30% disorder before the pressure noise grows: the kinetic
// energy doubles every ~0.05 s from t = 0.15 s and a particle leaves the tank at t = 0.55 s. It
// settles at 20% disorder, or at 30% with time.cfl = 0.05 (four times the shifting per second),
// with C = 0.02 or with Fickian shifting (above). What is asserted is that it stops cleanly: exit
// 3 with the step, the particle and the system, and the frames before it whole. A run that
// completes must have settled, and then the known failure is fixed: the case turns red to say so
// (as a should_fail case would; one run serves both, where two cases ran the same 16 s twice).
TEST_CASE(
    "stability: an ISPH tank with the paper's density shifting started with 30% disorder stops cleanly (known "
    "not to settle)") {
  auto o = test::run_shipped("disorder_isph_density", "hydrostatic_isph_2d.toml",
                             {"particles.disorder=0.3", "time.end=1.0", "output.probe_interval=0.01"});
  if (o.code == kExitDone) {
    auto e = test::energy(o);
    CHECK(std::abs(e.total.back() - e.total.front()) <= kMass * kG * kSpacing / 2);
    CHECK(std::sqrt(2 * e.kinetic.back() / kMass) < 0.05 * std::sqrt(kG * kDepth));
    FAIL_CHECK("the paper's density shifting now completes a 30% disorder: if it settled (the checks above), the "
               "known failure is fixed: make this case check_disordered_tank like the others");
  } else {
    test::check_clean_failure(o, "isph density shifting, 30% disorder");
  }
}

// ISPH's implicit density formulation with its particle-scale damping at 0.2 (issue 49). Measured
// 2026-11-29 (1 thread, 8.9 s to 3 s): rms speed 0.025 m/s at 0.2 s, 0.0138 at 1 s, 0.0083 at 2 s.
// Its default is undamped since the settle before t = 0 (which gives up on a 30% disorder: a
// particle moves half a spacing within 27 steps): undamped the disorder's energy stays, rms 0.18 m/s
// at its largest and 0.078 at 2 s (energy -13.0 J/m): bounded, but not settling. The formulation
// does no work on the fluid and water's viscosity takes a particle-scale mode's energy at nu (pi /
// d)^2 = 0.06 /s, so a start this far from equilibrium needs the damping (docs/isph.md).
TEST_CASE(
    "stability: an ISPH tank under the implicit density formulation with its particle-scale damping started "
    "with 30% disorder settles") {
  check_disordered_tank("isph_implicit_density", "hydrostatic_isph_2d.toml",
                        {"method.formulation=\"implicit_density\"", "method.particle_damping=0.2"}, 2.0);
}
