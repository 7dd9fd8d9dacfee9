// 30% initial disorder (issue 9): the shipped resting tanks (0.5 m of water, d = 0.0125 m, 1600
// particles) start with every fluid particle displaced by up to 0.3 d on each axis
// ([particles] disorder = 0.3) and run to t = 1 s. The disorder starts the particles off the
// lattice the kernels and the reference densities were set up on; each method must settle it:
//   - the run completes and keeps every particle;
//   - the energy ends within M g d / 2 of its start (15.3 J/m): the start's positions are
//     uncertain by 0.3 d, and the volume each method assigns them may move the surface, and the
//     centre of mass, by a fraction of a spacing (measured: WCSPH -10.7 J/m, MPS +5.3, ISPH +4.9);
//   - the tank is at rest again: the rms speed at the end below 5% of the wave speed sqrt(g H)
//     (0.11 m/s; measured WCSPH 0.002, MPS 0.087, ISPH 0.016 m/s).
#include <doctest/doctest.h>

#include <cmath>

#include "stability_util.hpp"

using namespace ryushi;

namespace {

constexpr double kMass = 1000 * 0.5 * 0.5, kG = 9.81, kDepth = 0.5, kSpacing = 0.0125;

void check_disordered_tank(const std::string& label, const std::string& scene,
                           std::vector<std::string> sets) {
  sets.insert(sets.end(), {"particles.disorder=0.3", "time.end=1.0", "output.probe_interval=0.01"});
  auto o = test::run_shipped("disorder_" + label, scene, sets);
  INFO(label);
  test::require_completed(o);
  CHECK(test::json_number(o.summary, "fluid_particles") == 1600);
  auto e = test::energy(o);
  const double change = e.total.back() - e.total.front();
  const double rms_speed = std::sqrt(2 * e.kinetic.back() / kMass);
  MESSAGE(label, ": energy change ", change, " J/m, rms speed at the end ", rms_speed, " m/s");
  CHECK(std::abs(change) <= kMass * kG * kSpacing / 2);
  CHECK(rms_speed < 0.05 * std::sqrt(kG * kDepth));
}

}  // namespace

TEST_CASE("stability: a WCSPH tank started with 30% disorder settles") {
  check_disordered_tank("wcsph", "hydrostatic_2d.toml", {});
}
TEST_CASE("stability: an MPS tank started with 30% disorder settles") {
  check_disordered_tank("mps", "hydrostatic_mps_2d.toml", {});
}
TEST_CASE("stability: an ISPH tank with Fickian shifting started with 30% disorder settles") {
  check_disordered_tank("isph_fickian", "hydrostatic_isph_2d.toml", {"shifting.model=fickian"});
}
// Four times the paper's shifting coefficient (0.02 against 0.005) undoes the disorder before the
// pressure noise grows (measured: energy -0.8 J/m, rms speed 0.010 m/s at the end).
TEST_CASE("stability: an ISPH tank with density shifting at C = 0.02 started with 30% disorder settles") {
  check_disordered_tank("isph_density_c002", "hydrostatic_isph_2d.toml", {"shifting.coefficient=0.02"});
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
