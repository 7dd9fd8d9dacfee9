// The water_height probe measures the water column standing on its base, not the highest fluid
// particle near its line (systems/probes/probes.hpp).
#include <doctest/doctest.h>

#include <filesystem>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "shipped_scene_run.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

// Runs `scene` (TOML text) in a scratch directory named `label` and returns its probes.csv.
auto probes_of_run(const std::string& label, const std::string& scene) {
  auto dir = test::scratch(label);
  test::write_text(dir / "scene.toml", scene);
  RunOptions opt;
  opt.scene = (dir / "scene.toml").string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  REQUIRE(run_scene(opt) == kExitDone);
  return test::read_csv(dir / "out" / "probes.csv");
}

// `ryushi check` on `scene` written as DIR/bad.toml exits 2 with `expected` in its message.
void check_bad_scene(const std::filesystem::path& dir, const std::string& scene,
                     const std::string& expected) {
  test::write_text(dir / "bad.toml", scene);
  auto r = test::run_command(std::string(RYUSHI_BINARY) + " check " + (dir / "bad.toml").string());
  CHECK(r.code == kExitBadInput);
  CHECK_MESSAGE(r.output.find(expected) != std::string::npos, r.output);
}

// Water 0.5 m deep in a 0.5 m wide tank; three particles (one column) cling to the left wall
// 0.2 m above the surface, where the old probe (highest particle + d/2) read 0.7375 m.
// Probes on the wall (the dam-break probe's place), at mid-tank and in the far corner. Each method
// at its own kernel radius (mps: r_e = 3.1 l0, which needs 4 wall layers).
std::string tank_with_stray_particles(const std::string& method) {
  return R"([scene]
dimension = 2
[domain]
min = [-0.1, -0.1]
max = [0.6, 1.0]
[particles]
spacing = 0.0125
[material]
density = 1000.0
[method]
name = ")" +
         method + R"("
[time]
end = 0.001
[output]
interval = 0.001
[[fluid]]
min = [0.0, 0.0]
max = [0.5, 0.5]
[[fluid]]
min = [0.0, 0.7]
max = [0.0125, 0.7375]
[[wall]]
min = [0.0, 0.0]
max = [0.5, 0.9]
layers = 4
[[probe]]
name = "at_wall"
type = "water_height"
position = [0.0025, 0.0]
[[probe]]
name = "mid"
type = "water_height"
position = [0.25, 0.0]
[[probe]]
name = "corner"
type = "water_height"
position = [0.4975, 0.0]
[[probe]]
name = "dry"
type = "water_height"
position = [0.25, 0.6]
)";
}

}  // namespace

TEST_CASE("probes: water_height reads the water surface, not particles clinging to the wall above it") {
  for (std::string method : {"wcsph", "mps"}) {
    CAPTURE(method);
    auto probes = probes_of_run("probe_height_" + method, tank_with_stray_particles(method));
    for (auto name : {"at_wall", "mid", "corner", "dry"}) REQUIRE_MESSAGE(probes[name].size() >= 1, name);
    // At t = 0 the surface is the top row's edge, 0.5 m. The fill fraction's 1/2 level lies
    // within a quarter spacing of it on the lattice (measured: see the printed values).
    const double d = 0.0125;
    for (std::string name : {"at_wall", "mid", "corner"}) {
      MESSAGE(name << ": " << probes[name].front());
      CHECK_MESSAGE(std::abs(probes[name].front() - 0.5) < 0.25 * d, name);
    }
    // A base above the water: no column stands there, the probe reads its own base.
    CHECK(probes["dry"].front() == doctest::Approx(0.6));
  }
}

namespace {

// Water 0.25 m deep in a 0.5 m tank (WCSPH, three wall layers) with one wall pressure sensor,
// given as the lines of its [[probe]] table after `type` (line 25 on).
std::string tank_with_sensor(const std::string& sensor_lines) {
  return R"([scene]
dimension = 2
[domain]
min = [-0.1, -0.1]
max = [0.6, 0.6]
[particles]
spacing = 0.025
[material]
density = 1000.0
[method]
name = "wcsph"
[time]
end = 0.001
[[fluid]]
min = [0.0, 0.0]
max = [0.5, 0.25]
[[wall]]
min = [0.0, 0.0]
max = [0.5, 0.5]
layers = 3
[[probe]]
name = "sensor"
type = "wall_pressure"
diameter = 0.005
)" + sensor_lines;
}

}  // namespace

// Issue 57, acceptance 4: a sensor off any wall, a normal into the wall, a zero diameter: exit 2
// with the place of the key at fault (the first two need the particles: `ryushi check` builds them).
TEST_CASE("probes: bad wall sensor definitions exit 2 at the key's line and column") {
  auto dir = test::scratch("probe_wall_sensor_bad");
  auto check = [&](const std::string& text, const std::string& expected) {
    check_bad_scene(dir, text, expected);
  };
  const std::string on_left_wall = "position = [0.0, 0.1]\n";
  // The good one passes (so that the others fail for their own reason).
  test::write_text(dir / "good.toml", tank_with_sensor(on_left_wall + "normal = [1.0, 0.0]\n"));
  CHECK(test::run_command(std::string(RYUSHI_BINARY) + " check " + (dir / "good.toml").string()).code == 0);
  check(tank_with_sensor("position = [0.2, 0.1]\nnormal = [1.0, 0.0]\n"),
        "bad.toml:25:12: [[probe]] 'sensor': the sensor lies off any wall: the nearest wall particle is");
  check(tank_with_sensor(on_left_wall + "normal = [-1.0, 0.0]\n"),
        "bad.toml:26:10: [[probe]] 'sensor': the sensor's normal points into the wall or along it");
  check(tank_with_sensor(on_left_wall + "normal = [0.0, 1.0]\n"),
        "bad.toml:26:10: [[probe]] 'sensor': the sensor's normal");
  check(tank_with_sensor(on_left_wall + "normal = [0.0, 0.0]\n"),
        "bad.toml:26:10: [[probe]] 'sensor' of type wall_pressure: the normal must not be zero");
  check(tank_with_sensor(on_left_wall), "[[probe]] 'sensor' of type wall_pressure needs a normal");
  auto zero = tank_with_sensor(on_left_wall + "normal = [1.0, 0.0]\n");
  zero.replace(zero.find("diameter = 0.005"), 16, "diameter = 0.0");
  check(zero, "bad.toml:24:12: 'diameter' in [[probe]] #0 is 0; it must be > 0");
  check(tank_with_sensor("normal = [1.0, 0.0]\n"),
        "[[probe]] 'sensor' of type wall_pressure needs a position");
}

namespace {

// A 0.5 m block turning rigidly at omega = 2 rad/s about its centre (0.25, 0.25), no walls: the
// velocity is linear in x, v = (omega (y - yc), -omega (x - xc)), which the Shepard interpolation
// reproduces inside the block to the lattice's first moment about the probe (a fraction of a
// percent of omega r at these offsets). The probes sample t = 0 before the first step.
std::string turning_block(const std::string& method, const std::string& extra_probe = "") {
  return R"([scene]
dimension = 2
[domain]
min = [-0.5, -0.5]
max = [1.0, 1.0]
[particles]
spacing = 0.0125
[material]
density = 1000.0
[method]
name = ")" +
         method + R"("
[time]
end = 0.0005
[[fluid]]
min = [0.0, 0.0]
max = [0.5, 0.5]
angular_velocity = 2.0
[[probe]]
name = "vy_east"
type = "velocity"
position = [0.4, 0.25]
axis = 1
[[probe]]
name = "vx_north"
type = "velocity"
position = [0.25, 0.37]
[[probe]]
name = "vx_off"
type = "velocity"
position = [0.181, 0.093]
axis = 0
[[probe]]
name = "vy_off"
type = "velocity"
position = [0.181, 0.093]
axis = 1
)" + extra_probe;
}

}  // namespace

// Issue 56: `type = "velocity"` reads component `axis` of the fluid velocity at a point.
TEST_CASE("probes: velocity reads a rigid rotation's velocity at a point, component by component") {
  for (std::string method : {"wcsph", "mps"}) {
    CAPTURE(method);
    auto probes = probes_of_run("probe_velocity_" + method, turning_block(method));
    REQUIRE(probes["time"].front() == 0.0);
    const double omega = 2.0, xc = 0.25, yc = 0.25;
    auto near = [&](const std::string& name, double expected) {
      const double got = probes[name].front();
      MESSAGE(name << ": " << got << " against " << expected);
      CHECK_MESSAGE(std::abs(got - expected) < 5e-3 * std::abs(expected), name);
    };
    near("vy_east", -omega * (0.4 - xc));   // v_y = -omega (x - xc)
    near("vx_north", omega * (0.37 - yc));  // axis 0 by default
    near("vx_off", omega * (0.093 - yc));
    near("vy_off", -omega * (0.181 - xc));
  }
}

TEST_CASE("probes: a velocity probe without a position or with an axis beyond the dimension exits 2") {
  auto dir = test::scratch("probe_velocity_bad");
  auto check = [&](const std::string& probe, const std::string& expected) {
    check_bad_scene(dir, turning_block("wcsph", probe), expected);
  };
  check("[[probe]]\nname = \"v\"\ntype = \"velocity\"\n", "[[probe]] 'v' of type velocity needs a position");
  check("[[probe]]\nname = \"v\"\ntype = \"velocity\"\nposition = [0.2, 0.2]\naxis = 2\n",
        "bad.toml:41:8: [[probe]] 'v': axis must be below the dimension");
}

// A line of velocity probes (`end`, `points`): the profile of u_x along the block's vertical
// centreline, u_x = omega (y - yc), at nine points from y = 0.05 to 0.45, each within 0.5% of
// omega r (the single probes' bound above) and the columns named in order.
TEST_CASE("probes: a line of velocity probes reads a rigid rotation's profile point by point") {
  auto probes = probes_of_run("probe_velocity_line", turning_block("wcsph", R"([[probe]]
name = "u_centre"
type = "velocity"
position = [0.25, 0.05]
end = [0.25, 0.45]
points = 9
)"));
  const double omega = 2.0, yc = 0.25;
  for (int k = 0; k < 9; ++k) {
    const std::string name = "u_centre_" + std::to_string(k);
    REQUIRE_MESSAGE(probes.count(name) == 1, name);
    const double y = 0.05 + 0.05 * k, expected = omega * (y - yc), got = probes[name].front();
    CAPTURE(name);
    CHECK(std::abs(got - expected) < 5e-3 * omega * 0.2);  // 0.5% of the speed 0.2 m from the centre
  }
}

TEST_CASE("probes: a line without points, with points but no end, or ending outside the domain exits 2") {
  auto dir = test::scratch("probe_line_bad");
  auto check = [&](const std::string& probe, const std::string& expected) {
    check_bad_scene(dir, turning_block("wcsph", probe), expected);
  };
  const std::string head = "[[probe]]\nname = \"u\"\ntype = \"velocity\"\nposition = [0.25, 0.05]\n";
  check(head + "end = [0.25, 0.45]\n", "bad.toml:41:7: [[probe]] 'u': a line needs `points`");
  check(head + "points = 5\n", "bad.toml:41:10: [[probe]] 'u': points needs `end`, the line's other end");
  check(head + "end = [0.25, 4.0]\npoints = 5\n",
        "bad.toml:41:7: [[probe]] 'u': end lies outside the domain");
  check(head + "end = [0.25, 0.45]\npoints = 1\n", "points");
  check(
      "[[probe]]\nname = \"h\"\ntype = \"water_height\"\nposition = [0.25, 0.05]\nend = [0.3, 0.05]\npoints "
      "= 3\n",
      "a line (`end`) is for pressure and velocity probes");
}

// A force probe with reference_speed U and reference_length L reads the coefficient F / (rho0 U^2
// L / 2) (2D): beside the raw force on the same body, sample by sample, the ratio is rho0 U^2 L / 2
// = 1000 (U = 2 m/s, L = 0.5 m) to round-off; one of the two keys alone, or on another probe type,
// exits 2 at the key.
TEST_CASE("probes: a force probe with a reference speed and length reads the force coefficient") {
  const std::string probes =
      "[[probe]]\nname = \"fy\"\ntype = \"force\"\nsolid = \"tank\"\naxis = 1\n"
      "[[probe]]\nname = \"cy\"\ntype = \"force\"\nsolid = \"tank\"\naxis = 1\n"
      "reference_speed = 2.0\nreference_length = 0.5\n";
  const auto out = test::run_shipped_scene("probe_force_coefficient", "round_tank_2d.toml", probes,
                                           {"time.end=0.01", "output.probe_interval=0.002"});
  auto csv = test::read_csv(out / "probes.csv");
  REQUIRE(csv["fy"].size() >= 5);
  for (std::size_t k = 0; k < csv["fy"].size(); ++k) {
    CAPTURE(k);
    REQUIRE(std::abs(csv["fy"][k]) > 100);  // the water's weight on the tank, about 1 kN/m
    CHECK(csv["cy"][k] * 1000 == doctest::Approx(csv["fy"][k]).epsilon(1e-12));
  }
  auto dir = test::scratch("probe_force_coefficient_bad");
  const auto scene = test::read_text(test::scene_path("round_tank_2d.toml"));
  check_bad_scene(
      dir, scene + "\n[[probe]]\nname = \"c\"\ntype = \"force\"\nsolid = \"tank\"\nreference_speed = 2.0\n",
      "a force coefficient needs both reference_speed and reference_length");
  check_bad_scene(dir,
                  scene + "\n[[probe]]\nname = \"c\"\ntype = \"kinetic_energy\"\nreference_length = 0.5\n",
                  "reference_speed and reference_length are for force probes");
}
