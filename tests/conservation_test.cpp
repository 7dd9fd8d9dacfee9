// Conservation that can fail: total momentum in a closed periodic box (issue 15). Two layers of
// water slide past each other (u = +-0.5 m/s, v = +-0.1 m/s: zero total momentum) in a box
// periodic on both axes, no walls, no gravity. WCSPH's pair forces (pressure, artificial and
// laminar viscosity) are antisymmetric pair by pair, so the total stays zero to round-off while
// the shear layer mixes; an asymmetric pair term (a force computed with i and j swapped
// differently) shows up at once.
#include <doctest/doctest.h>

#include <cmath>

#include "app/exit_codes.hpp"
#include "test_util.hpp"

using namespace ryushi;

TEST_CASE("conservation: WCSPH keeps the total momentum of a periodic shear layer to round-off") {
  auto dir = test::scratch("conservation_shear");
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
)");
  auto r = test::run_command(std::string(RYUSHI_BINARY) + " run --quiet --out " + (dir / "out").string() + " " +
                             (dir / "shear.toml").string());
  REQUIRE_MESSAGE(r.code == kExitDone, r.output);
  auto summary = test::read_text(dir / "out" / "summary.json");
  CHECK(test::json_number(summary, "steps") > 100);
  const double scale = test::json_number(summary, "momentum_scale");  // sum m |v|, about 125 kg m/s
  const double px = test::json_number(summary, "momentum_x"), py = test::json_number(summary, "momentum_y");
  MESSAGE("total momentum (", px, ", ", py, ") against sum m|v| = ", scale);
  // Measured 6e-16 of the scale after 281 steps to t = 0.1 s: 1,600 particles summing terms of
  // order m |v| with double round-off (1e-16 each) give at most ~1e-13; 1e-12 leaves room.
  CHECK(scale > 100);
  CHECK(std::hypot(px, py) < 1e-12 * scale);
  // The layers did interact: the kinetic energy fell from 32.5 J (measured 30.6 J: viscosity and
  // the shear's mixing), so the momentum was exchanged, not merely left alone.
  const double initial_energy = 0.5 * 1000 * 0.25 * (0.25 + 0.01);
  CHECK(test::json_number(summary, "kinetic_energy") < 0.98 * initial_energy);
}
