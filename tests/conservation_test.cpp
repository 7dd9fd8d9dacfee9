// Conservation that can fail: total momentum in a closed periodic box (issue 15). Two layers of
// water slide past each other (u = +-0.5 m/s, v = +-0.1 m/s: zero total momentum) in a box
// periodic on both axes, no walls, no gravity. WCSPH's pair forces (pressure, artificial and
// laminar viscosity) are antisymmetric pair by pair, so the total stays zero to round-off while
// the shear layer mixes; an asymmetric pair term (a force computed with i and j swapped
// differently) shows up at once. MPS and ISPH solve a pressure equation without any Dirichlet
// value here (no surface, no wall): pressure_gauge.hpp pins it.
#include <doctest/doctest.h>

#include <cmath>

#include "app/exit_codes.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

struct ShearRun {
  double steps, scale, px, py, kinetic_energy, solves, max_iterations;
};

// The shear layer under `method_keys` (TOML lines for [method] and after) to t = 0.1 s.
ShearRun run_periodic_shear(const std::string& name, const std::string& method_keys) {
  auto dir = test::scratch("conservation_" + name);
  test::write_text(dir / "shear.toml", R"([scene]
dimension = 2
name = "periodic_shear"
[domain]
min = [0.0, 0.0]
max = [0.5, 0.5]
periodic = [true, true]
[particles]
spacing = 0.0125
[material]
density = 1000.0
viscosity = 1.0e-3
[physics]
gravity = [0.0, 0.0]
[time]
end = 0.1
[output]
interval = 0.1
[[fluid]]
min = [0.0, 0.0]
max = [0.5, 0.25]
velocity = [0.5, 0.1]
[[fluid]]
min = [0.0, 0.25]
max = [0.5, 0.5]
velocity = [-0.5, -0.1]
)" + method_keys);
  auto r = test::run_command(std::string(RYUSHI_BINARY) + " run --quiet --out " + (dir / "out").string() + " " +
                             (dir / "shear.toml").string());
  REQUIRE_MESSAGE(r.code == kExitDone, r.output);
  auto summary = test::read_text(dir / "out" / "summary.json");
  ShearRun run{test::json_number(summary, "steps"),
               test::json_number(summary, "momentum_scale"),
               test::json_number(summary, "momentum_x"),
               test::json_number(summary, "momentum_y"),
               test::json_number(summary, "kinetic_energy"),
               method_keys.empty() ? 0.0 : test::json_number(summary, "solves"),
               method_keys.empty() ? 0.0 : test::json_number(summary, "max_iterations")};
  MESSAGE(name, ": ", run.steps, " steps, total momentum (", run.px, ", ", run.py, ") against sum m|v| = ",
          run.scale, ", kinetic energy ", run.kinetic_energy, " J");
  // sum m |v| is about 125 kg m/s; the layers did interact: the kinetic energy fell from
  // 32.5 J (viscosity and the shear's mixing), so momentum was exchanged, not merely left alone.
  CHECK(run.scale > 100);
  const double initial_energy = 0.5 * 1000 * 0.25 * (0.25 + 0.01);
  CHECK(run.kinetic_energy < 0.98 * initial_energy);
  return run;
}

}  // namespace

TEST_CASE("conservation: WCSPH keeps the total momentum of a periodic shear layer to round-off") {
  auto run = run_periodic_shear("wcsph", "");
  CHECK(run.steps > 100);
  // Measured 6e-16 of the scale after 281 steps to t = 0.1 s: 1,600 particles summing terms of
  // order m |v| with double round-off (1e-16 each) give at most ~1e-13; 1e-12 leaves room.
  CHECK(std::hypot(run.px, run.py) < 1e-12 * run.scale);
}

// The projection methods' momentum is exact up to what the linear solver leaves of the pressure
// equation: measured 1.0e-11 (MPS, 40 steps) and 1.4e-11 (ISPH, 21 steps) of sum m|v| at the
// default tolerance 1e-8; 2.7e-15 (MPS, 1e-11) and 9.5e-14 (ISPH, 1e-10) with tighter solves: the
// drift falls with the tolerance, at about 1e-3 tol. 0.1 tol (1e-9) is a hundred times the measured: a gradient that is not consistent
// with the solved pressure, or an unpinned (singular) solve, is far above it.
TEST_CASE("conservation: MPS and ISPH keep the momentum of a periodic shear layer to the solver's tolerance") {
  for (auto method : {"mps", "isph"}) {
    CAPTURE(method);
    auto run = run_periodic_shear(method, std::string("[method]\nname = \"") + method +
                                              "\"\n[solver]\npreconditioner = \"jacobi\"\ntolerance = 1e-8\n");
    CHECK(run.steps >= 20);
    // The residual is the solver's own stopping test (a miss stops the run): check instead that
    // every step solved, and did work.
    CHECK(run.solves >= run.steps);
    CHECK(run.max_iterations >= 1);
    CHECK(std::hypot(run.px, run.py) < 1e-9 * run.scale);
  }
}
