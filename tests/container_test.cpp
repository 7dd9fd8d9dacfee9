// [[solid]] container = true: walls outside a round or box shape, the fluid inside. The layers lie
// on the fluid's lattice (src/geometry/solid_shape.cpp, container_shell), so fluid and wall
// partition it: water at rest in a round tank is then as hydrostatic as in a box tank.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "geometry/solid_shape.hpp"
#include "h5_read.hpp"
#include "scene_error.hpp"
#include "shipped_scene_run.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

constexpr double kPi = std::numbers::pi;

SolidSpec container_spec(const std::string& shape, const std::vector<double>& centre, double radius, int layers) {
  SolidSpec s;
  s.shape = shape, s.centre = centre, s.radius = radius, s.layers = layers, s.container = true;
  s.min = s.max = centre;
  for (std::size_t a = 0; a < centre.size(); ++a) s.min[a] -= radius, s.max[a] += radius;
  return s;
}

}  // namespace

TEST_CASE("container: a ball's layers lie outside it on the lattice, with outward normals") {
  const double d = 0.01, R = 0.1;  // R = 10 d, as the STL sphere of the mesh test
  const SolidShape<3> ball(container_spec("sphere", {0.5, 0.5, 0.5}, R, 3));
  const Vec<3> origin(0.0, 0.0, 0.0), centre(0.5, 0.5, 0.5);
  auto layers = ball.shell(d, &origin);
  REQUIRE(!layers.empty());
  for (auto& q : layers) {
    const Vec<3> r = q.position - centre;
    CHECK(r.norm() > R);
    CHECK(r.norm() <= R + 3 * d + 1e-12);
    CHECK(q.layer == int(std::ceil((r.norm() - R) / d - 1e-9)));
    CHECK((q.normal - r.normalized()).norm() < 1e-12);  // out of the fluid: +r / |r|
    const Vec<3> cell = q.position / d - Vec<3>::Constant(0.5);  // on the lattice (k + 1/2) d
    CHECK((cell - cell.array().round().matrix()).norm() < 1e-9);
  }
  // What the container holds: the lattice points inside, 4/3 pi R^3 / d^3 = 4,189 within 2% (the
  // lattice count of a ball converges as the surface's share, ~3 d / R).
  std::size_t inside = 0;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j)
      for (int k = 0; k < 100; ++k) {
        const Vec<3> x = (Vec<3>(i, j, k) + Vec<3>::Constant(0.5)) * d;
        inside += !ball.within(x, 0.0);
      }
  MESSAGE("lattice points inside: ", inside, " of 4/3 pi R^3 / d^3 = ", 4 * kPi * R * R * R / (3 * d * d * d));
  CHECK(std::abs(inside / (4 * kPi * R * R * R / (3 * d * d * d)) - 1) < 0.02);
  // Not a point both fluid and wall, and none of the lattice within 3 layers outside is missing.
  std::size_t expected_layers = 0;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j)
      for (int k = 0; k < 100; ++k) {
        const double r = ((Vec<3>(i, j, k) + Vec<3>::Constant(0.5)) * d - centre).norm();
        expected_layers += r > R && r <= R + 3 * d + 1e-12;
      }
  CHECK(layers.size() == expected_layers);
}

TEST_CASE("container: a round tank's fluid and walls partition the lattice (check --write-initial)") {
  auto dir = test::unique_scratch("container_round");
  auto r = test::run_command(std::string(RYUSHI_BINARY) + " check " + test::scene_path("round_tank_2d.toml") +
                             " --write-initial " + (dir / "init").string());
  REQUIRE_MESSAGE(r.code == 0, r.output);
  const auto frame = dir / "init" / "frames" / "frame_00000.h5";
  auto kind = test::read_dataset(frame, "kind").values, x = test::read_dataset(frame, "position").values;
  const double d = 0.025, R = 0.5, xc = 0.5, yc = 0.5;
  std::vector<std::size_t> fluid, wall;
  for (std::size_t i = 0; i < kind.size(); ++i) (kind[i] == 0 ? fluid : wall).push_back(i);
  auto radius = [&](std::size_t i) { return std::hypot(x[3 * i] - xc, x[3 * i + 1] - yc); };
  for (auto f : fluid) CHECK(radius(f) <= R);
  for (auto w : wall) CHECK(radius(w) > R);
  double nearest = 1e9;
  for (auto f : fluid)
    for (auto w : wall) nearest = std::min(nearest, std::hypot(x[3 * f] - x[3 * w], x[3 * f + 1] - x[3 * w + 1]));
  CHECK(nearest == doctest::Approx(d).epsilon(1e-9));  // a spacing: no overlap, no gap wider than the lattice's
  // The lower half disc: pi R^2 / 2 / d^2 = 628.3; the lattice holds 632 (+0.6%).
  MESSAGE("fluid particles: ", fluid.size(), " of pi R^2 / (2 d^2) = ", kPi * R * R / (2 * d * d));
  CHECK(std::abs(fluid.size() / (kPi * R * R / (2 * d * d)) - 1) < 0.02);
}

// Water at rest in the round tank (scenes/round_tank_2d.toml, R / d = 20) after the start-up
// waves: WCSPH's pressure against rho g depth as in the box tank (validation_hydrostatic_test.cpp,
// 1% at its probes; the box tank at this resolution: 0.61% relative L2 over the whole fluid at
// t = 3 s). Measured here at t = 2 s: L2 0.63%, probes +0.38% and +0.45%.
TEST_CASE("container: water at rest in a round tank keeps rho g depth (WCSPH)") {
  auto out = test::scratch("container_round_wcsph");
  RunOptions opt;
  opt.scene = test::scene_path("round_tank_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.sets = {"time.end=2"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto summary = test::read_text(out / "summary.json");
  const double error = test::json_number(summary, "hydrostatic");
  MESSAGE("relative L2 error against rho g depth: ", error);
  CHECK(error < 0.01);
  auto probes = test::read_csv(out / "probes.csv");
  const double rho_g = 1000 * 9.81;
  CHECK(std::abs(probes["p_depth_0.25"].back() / (rho_g * 0.25) - 1) < 0.01);
  CHECK(std::abs(probes["p_depth_0.40"].back() / (rho_g * 0.40) - 1) < 0.01);
  CHECK(std::abs(test::json_number(summary, "fluid_volume_relative_change")) < 1e-3);
}

// MPS in the same tank: its pressure is noisy from step to step (3-7% at the box tank's probes,
// mps_test.cpp), so the probes are averaged over the second second. Measured: -3.7% at depth
// 0.25 m and -2.1% at 0.40 m, against the box tank's slope within 1%: the zigzag wall on the
// lattice leaves the pressure-solved first wall layer with number densities that differ from the
// flat wall's n0 by up to one particle. Asserted within 5%.
TEST_CASE("container: water at rest in a round tank keeps rho g depth on average (MPS)") {
  auto out = test::scratch("container_round_mps");
  RunOptions opt;
  opt.scene = test::scene_path("round_tank_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.sets = {"time.end=2", "method.name=mps"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto probes = test::read_csv(out / "probes.csv");
  const double rho_g = 1000 * 9.81;
  for (auto [name, depth] : {std::pair{"p_depth_0.25", 0.25}, std::pair{"p_depth_0.40", 0.40}}) {
    double sum = 0;
    int samples = 0;
    for (std::size_t k = 0; k < probes["time"].size(); ++k)
      if (probes["time"][k] >= 1.0) sum += probes[name][k], ++samples;
    REQUIRE(samples >= 90);
    const double error = sum / samples / (rho_g * depth) - 1;
    MESSAGE(std::string(name), ": mean over t >= 1 s ", error * 100, "% from rho g depth");
    CHECK(std::abs(error) < 0.05);
  }
}

// ISPH's own walls are one layer with normals (Neumann rows); around a curve that layer is not
// stable (a zigzag on the lattice blew up at t = 0.6 s, a ring at R + d/2 grew tenfold per second
// and stopped at t = 4 s; docs/isph.md, "Round and mesh containers"). A round container under ISPH
// takes the lattice's layers and Adami's wall pressure as its rows instead (wall_rows = "adami",
// the default there). Measured at t = 2 s: relative L2 0.014% over the fluid, probes -0.016% /
// -0.017%, the force on the tank over t = 1-2 s 0.35% above rho g pi R^2 / 2 (the 632 particles'
// weight to 0.24%; the ring's 612 had held 2.6% less). Bounds: 0.5% (the ISPH box tank of
// isph_test.cpp is asserted to 0.5% too), 1% on the force.
namespace {
// scenes/round_tank_2d.toml under ISPH with one more probe; returns the run's folder.
std::filesystem::path run_round_tank_isph(const std::string& name, const std::string& probe,
                                          std::vector<std::string> sets) {
  sets.push_back("method.name=isph");
  return test::run_shipped_scene(name, "round_tank_2d.toml", "[[probe]]\n" + probe, std::move(sets));
}
}  // namespace

TEST_CASE("container: water at rest in a round tank keeps rho g depth (ISPH, Adami walls)") {
  const auto out = run_round_tank_isph("container_round_isph",
                                       "name = \"fy\"\ntype = \"force\"\nsolid = \"tank\"\naxis = 1\n",
                                       {"time.end=2", "output.probe_interval=0.01"});
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_number(summary, "hydrostatic") < 0.005);
  auto probes = test::read_csv(out / "probes.csv");
  const double rho_g = 1000 * 9.81;
  CHECK(std::abs(probes["p_depth_0.25"].back() / (rho_g * 0.25) - 1) < 0.005);
  CHECK(std::abs(probes["p_depth_0.40"].back() / (rho_g * 0.40) - 1) < 0.005);
  double force = 0;
  int samples = 0;
  for (std::size_t k = 0; k < probes["time"].size(); ++k)
    if (probes["time"][k] >= 1.0) force += probes["fy"][k], ++samples;
  REQUIRE(samples >= 90);
  CHECK(std::abs(-force / samples / (rho_g * kPi * 0.5 * 0.5 / 2) - 1) < 0.01);
}

// The same tank over a longer time stays at rest. With the one-layer ring it did not: its kinetic
// energy grew about tenfold per second from beside the ring (3.5e-4 J/m at t = 1 s, 0.033 at 3 s)
// and the run stopped at t = 4.0-4.1 s; at R / d = 40 at 0.8 s. With Adami walls (measured
// 2026-11-27) it holds 1.8e-5 .. 6.2e-5 J/m to t = 5 s without a trend, and at R / d = 40
// 3.3e-6 .. 7.1e-6 J/m (the box tank: 1.5e-6 J/m).
TEST_CASE("container: water in a round tank stays at rest to t = 5 s (ISPH, Adami walls)") {
  const auto out =
      run_round_tank_isph("container_round_isph_long", "name = \"ke\"\ntype = \"kinetic_energy\"\n",
                          {"time.end=5", "output.interval=1", "output.probe_interval=0.05"});
  // At rest: the kinetic energy no more than 1e-3 J/m at any sample after the start (rms speed
  // 1.6 mm/s over the 395 kg/m of water), and no growth: the last second's largest sample within
  // 1e-4 J/m.
  auto probes = test::read_csv(out / "probes.csv");
  double largest = 0, last_second = 0;
  for (std::size_t k = 0; k < probes["time"].size(); ++k) {
    largest = std::max(largest, probes["ke"][k]);
    if (probes["time"][k] >= 4.0) last_second = std::max(last_second, probes["ke"][k]);
  }
  MESSAGE("kinetic energy: largest ", largest, " J/m, over t = 4-5 s ", last_second, " J/m");
  CHECK(largest < 1e-3);
  CHECK(last_second < 1e-4);
}

// A half-full ball (R / d = 8) at rest under ISPH: before Adami walls the loader refused it (with
// a Fibonacci shell at R + d/2 it blew up at t = 0.36 s; as the full ball it grew x1.04 per step
// from round-off). Measured 2026-11-27 to t = 2 s: kinetic energy at most 7.6e-5 J (of 17 kg;
// to 3 s likewise), the force on the ball 167.5 N against the 1,088 particles' weight 166.8 N
// (+0.44%), the pressure 0.1 m below the nominal surface 0.6-0.8% under rho g 0.1 (the water
// settles into the lattice's gaps at the wall), relative L2 over the fluid 0.43%.
TEST_CASE("container: water at rest in a half-full ball stays at rest and weighs its weight (ISPH, 3D)") {
  const std::string scene =
      "[scene]\ndimension = 3\nname = \"ball\"\n[domain]\nmin = [-0.1, -0.1, -0.1]\nmax = [0.5, 0.5, 0.5]\n"
      "[particles]\nspacing = 0.025\n[material]\ndensity = 1000.0\nviscosity = 1.0e-3\n[method]\nname = \"isph\"\n"
      "[time]\nend = 2.0\n[output]\ninterval = 1.0\nprobe_interval = 0.05\n[[fluid]]\nmin = [0.0, 0.0, 0.0]\n"
      "max = [0.4, 0.4, 0.2]\n[[solid]]\nname = \"ball\"\nshape = \"sphere\"\ncentre = [0.2, 0.2, 0.2]\n"
      "radius = 0.2\ncontainer = true\n[[probe]]\nname = \"p\"\ntype = \"pressure\"\nposition = [0.2, 0.2, 0.1]\n"
      "[[probe]]\nname = \"ke\"\ntype = \"kinetic_energy\"\n[[probe]]\nname = \"fz\"\ntype = \"force\"\n"
      "solid = \"ball\"\naxis = 2\n";
  const auto out = test::scratch("container_ball_isph");
  test::write_text(out / "ball.toml", scene);
  RunOptions opt;
  opt.scene = (out / "ball.toml").string();
  opt.out_dir = (out / "run").string();
  opt.quiet = true;
  REQUIRE(run_scene(opt) == kExitDone);
  auto probes = test::read_csv(out / "run" / "probes.csv");
  const auto summary = test::read_text(out / "run" / "summary.json");
  const double weight = test::json_number(summary, "fluid_mass") * 9.81;
  double largest = 0, force = 0;
  int samples = 0;
  for (std::size_t k = 0; k < probes["time"].size(); ++k) {
    largest = std::max(largest, probes["ke"][k]);
    if (probes["time"][k] >= 1.0) force += probes["fz"][k], ++samples;
  }
  REQUIRE(samples >= 10);
  MESSAGE("kinetic energy at most ", largest, " J; force ", -force / samples, " N against the weight ", weight,
          " N; pressure ", probes["p"].back(), " Pa against rho g 0.1 = 981 Pa");
  CHECK(largest < 1e-3);  // rms speed 1 cm/s over the 17 kg
  CHECK(std::abs(-force / samples / weight - 1) < 0.01);
  CHECK(std::abs(probes["p"].back() / (1000 * 9.81 * 0.1) - 1) < 0.015);  // 1%, and the level's settling
}

TEST_CASE("container: bad containers are bad input naming the solid and the problem") {
  const std::string base =
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.2, -0.2]\nmax = [1.2, 1.2]\n[particles]\nspacing = 0.025\n"
      "[time]\nend = 0.1\n[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, 0.5]\n";
  const std::string tank = "[[solid]]\nname = \"tank\"\nshape = \"cylinder\"\ncentre = [0.5, 0.5]\nradius = 0.5\ncontainer = true\n";
  CHECK(test::scene_error(base + tank) == "");
  CHECK(test::scene_error(base + "[[solid]]\nshape = \"cylinder\"\ncentre = [0.5, 0.5]\nradius = 0.65\n"
                                 "container = true\n") ==
        "bad.toml:15:10: [[solid]] #0 lies (partly) outside the domain with its layers");
  CHECK(test::scene_error(base + tank + "[[solid]]\nshape = \"box\"\nmin = [0.8, 0.1]\nmax = [0.95, 0.3]\n") ==
        "bad.toml:20:9: [[solid]] #1 lies (partly) outside container 'tank' (bodies must lie inside a "
        "container, clear of its wall)");
  CHECK(test::scene_error(base + "[method]\nname = \"isph\"\n" + tank) == "");  // Adami walls
  const std::string base3 =
      "[scene]\ndimension = 3\n[domain]\nmin = [-0.1, -0.1, -0.1]\nmax = [0.5, 0.5, 0.5]\n[particles]\n"
      "spacing = 0.025\n[method]\nname = \"isph\"\n[time]\nend = 0.1\n[[fluid]]\nmin = [0.0, 0.0, 0.0]\n"
      "max = [0.4, 0.4, 0.2]\n";
  // A ball takes Adami walls under isph; asked for one layer with normals, it is refused.
  const std::string ball_tank = "[[solid]]\nshape = \"sphere\"\ncentre = [0.2, 0.2, 0.2]\nradius = 0.2\ncontainer = true\n";
  CHECK(test::scene_error(base3 + ball_tank) == "");
  std::string one_layer = base3;
  one_layer.replace(one_layer.find("name = \"isph\"\n"), 14, "name = \"isph\"\nwall_rows = \"corrected\"\n");
  CHECK(test::scene_error(one_layer + ball_tank) ==
        "bad.toml:10:13: wall_rows = \"corrected\" keeps one wall layer with normals, which a round or mesh container "
        "does not hold stably (a half-full ball at rest blew up at t = 0.36 s); leave wall_rows out or set \"adami\"");
  // Eulerian ISPH keeps its particles in place: a full round container (a pipe) is allowed, confined
  // (no free surface), with or without a fixed pressure (without one the gauge sets the level).
  std::string eulerian = base3;
  eulerian.replace(eulerian.find("name = \"isph\"\n"), 14, "name = \"isph\"\ndescription = \"eulerian\"\n");
  const std::string ball = "[[solid]]\nshape = \"sphere\"\ncentre = [0.2, 0.2, 0.2]\nradius = 0.2\ncontainer = true\n";
  const std::string level = "[[fixed_pressure]]\nmin = [0.0, 0.0, 0.0]\nmax = [0.4, 0.4, 0.05]\npressure = 0.0\n";
  CHECK(test::scene_error(eulerian + ball + level) == "");
  std::string confined = eulerian;
  confined.replace(confined.find("description"), 0, "confined = true\n");
  CHECK(test::scene_error(confined + ball + level) == "");
  CHECK(test::scene_error(confined + ball) == "");
  CHECK(test::scene_error(base + "[method]\nconfined = true\n" + tank)
            .rfind("bad.toml:14:1: [method] confined is for method isph, not for wcsph", 0) == 0);
  // A body inside is fine, and cuts its own hole in the fluid.
  CHECK(test::scene_error(base + tank + "[[solid]]\nshape = \"box\"\nmin = [0.4, 0.1]\nmax = [0.6, 0.3]\n") == "");
}

// A closed tank accelerating upwards at a = g/2 (container with displacement y = a t^2 / 2) is,
// in its own frame, a tank at rest under gravity g + a: Adami's wall pressure takes the wall's
// acceleration, (g - a_w) . sum rho_f (x_w - x_f) W. Both start hydrostatic under g + a and run
// 1 s with the same fixed step; the water must end in the same place with the same pressure.
// Measured: particles within 0.013 d of each other, pressure within 0.26% of rho (g + a) H (max;
// rms 0.08%), the force on the tank -3,652 N/m against the water's weight m (g + a) = 3,679 N/m.
// Without a_w in the wall pressure: 0.072 d and 0.64% (rms 0.21%).
TEST_CASE("container: a tank accelerating upwards is the tank at rest under g + a (WCSPH wall acceleration)") {
  auto dir = test::unique_scratch("container_accelerated");
  const std::string scene =
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.2, -0.2]\nmax = [0.7, 3.6]\n[particles]\nspacing = 0.025\n"
      "[material]\ndensity = 1000.0\nviscosity = 1.0e-3\n"
      "[method]\nartificial_viscosity = 1.0\nartificial_viscosity_quadratic = 1.0\n"
      "[time]\nend = 1.0\ndt = 1e-4\n[output]\ninterval = 0.5\n"
      "[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\npressure = \"1000*14.715*(0.5 - y)\"\n"
      "[[solid]]\nname = \"tank\"\nshape = \"box\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.7]\ncontainer = true\n"
      "[[probe]]\nname = \"force\"\ntype = \"force\"\nsolid = \"tank\"\naxis = 1\n";
  test::write_text(dir / "moving.toml", scene.substr(0, scene.find("[[probe]]")) +
                                            "displacement = [\"0\", \"0.5*4.905*t^2\"]\n" +
                                            scene.substr(scene.find("[[probe]]")));
  test::write_text(dir / "static.toml", scene + "[physics]\ngravity = [0.0, -14.715]\n");
  for (const char* name : {"moving", "static"}) {
    RunOptions opt;
    opt.scene = (dir / (std::string(name) + ".toml")).string();
    opt.out_dir = (dir / name).string();
    opt.quiet = true;
    REQUIRE(run_scene(opt) == kExitDone);
  }
  auto by_id = [&](const char* name) {
    const auto frame = dir / name / "frames" / "frame_00002.h5";
    auto id = test::read_dataset(frame, "id").values, kind = test::read_dataset(frame, "kind").values,
         x = test::read_dataset(frame, "position").values, p = test::read_dataset(frame, "pressure").values;
    std::vector<std::array<double, 3>> fluid(id.size(), {0, 0, -1});  // x, y, p by id; p = -1: not fluid
    for (std::size_t i = 0; i < id.size(); ++i)
      if (kind[i] == 0) fluid[static_cast<std::size_t>(id[i])] = {x[3 * i], x[3 * i + 1], p[i]};
    return fluid;
  };
  const auto moving = by_id("moving"), still = by_id("static");
  REQUIRE(moving.size() == still.size());
  const double d = 0.025, lift = 0.5 * 4.905 * 1.0 * 1.0, scale = 1000 * 14.715 * 0.5;
  double offset = 0, dp = 0;
  std::size_t compared = 0;
  for (std::size_t i = 0; i < moving.size(); ++i) {
    if (still[i][2] < 0 && moving[i][2] < 0) continue;
    ++compared;
    offset = std::max(offset, std::hypot(moving[i][0] - still[i][0], moving[i][1] - lift - still[i][1]));
    dp = std::max(dp, std::abs(moving[i][2] - still[i][2]));
  }
  MESSAGE("largest position difference ", offset / d, " d, pressure ", dp / scale, " of rho (g + a) H");
  CHECK(compared == 400);
  CHECK(offset < 0.03 * d);
  CHECK(dp < 0.004 * scale);
  auto probes = test::read_csv(dir / "moving" / "probes.csv");
  const double weight = 1000 * 0.25 * 14.715;
  CHECK(std::abs(-probes["force"].back() / weight - 1) < 0.02);
}

// The force on a closed box tank holding water at rest is the water's weight, for every method:
// WCSPH the reaction to its pair forces, MPS and ISPH the pressure of the first wall layer
// brought to the surface (p_w - rho g . n d/2) times each particle's share of it (the box's
// edge particles outside two faces have none). Mean over t = 1-2 s; measured (H / d = 20):
// WCSPH +0.25%, ISPH -0.011%, MPS +1.7% (its pressure jitters by 4% from step to step; its
// probes in a tank at rest are within 1% on the slope, 2-4% at single points). Bounds: 1%
// (WCSPH, the hydrostatic test's), 0.5% (ISPH, whose tank at rest is exact to 0.01%), 5% (MPS).
TEST_CASE("container: the force on a tank of water at rest is the water's weight (WCSPH, MPS, ISPH)") {
  const std::string scene =
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.2, -0.2]\nmax = [0.7, 1.0]\n[particles]\nspacing = 0.025\n"
      "[material]\ndensity = 1000.0\nviscosity = 1.0e-3\n"
      "[method.wcsph]\nartificial_viscosity = 1.0\nartificial_viscosity_quadratic = 1.0\n"  // read under wcsph only
      "[time]\nend = 2.0\n[output]\ninterval = 1.0\nprobe_interval = 0.01\n[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n"
      "[[solid]]\nname = \"tank\"\nshape = \"box\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.7]\ncontainer = true\n"
      "[[probe]]\nname = \"fy\"\ntype = \"force\"\nsolid = \"tank\"\naxis = 1\n"
      "[[probe]]\nname = \"fx\"\ntype = \"force\"\nsolid = \"tank\"\naxis = 0\n";
  const double weight = 1000 * 9.81 * 0.5 * 0.5;
  for (auto [method, bound] : {std::pair{"wcsph", 0.01}, std::pair{"mps", 0.05}, std::pair{"isph", 0.005}}) {
    CAPTURE(method);
    auto dir = test::unique_scratch(std::string("container_weight_") + method);
    test::write_text(dir / "tank.toml", scene);
    RunOptions opt;
    opt.scene = (dir / "tank.toml").string();
    opt.out_dir = (dir / "out").string();
    opt.quiet = true;
    opt.sets = {std::string("method.name=") + method};
    REQUIRE(run_scene(opt) == kExitDone);
    auto probes = test::read_csv(dir / "out" / "probes.csv");
    double fy = 0, fx = 0;
    int samples = 0;
    for (std::size_t k = 0; k < probes["time"].size(); ++k)
      if (probes["time"][k] >= 1.0) fy += probes["fy"][k], fx += probes["fx"][k], ++samples;
    REQUIRE(samples >= 90);
    fy /= samples, fx /= samples;
    MESSAGE(std::string(method), ": force ", fy, " N/m against the weight ", -weight, " (",
            (-fy / weight - 1) * 100, "%)");
    CHECK(std::abs(-fy / weight - 1) < bound);
    CHECK(std::abs(fx) < 0.01 * weight);  // the side walls' pushes cancel
  }
}
