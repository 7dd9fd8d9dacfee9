// Linear-elastic solids under WCSPH (issue 14, seed 002 section 2.2; docs/multiphysics.md): the
// oscillating clamped plate of Gray, Monaghan & Swift (2001) against Euler-Bernoulli, its energy
// over ten periods, a block at rest on a wall, the momentum that water and a solid exchange, and
// the errors of bad solid input.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "h5_read.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

std::string bin() {
  return RYUSHI_BINARY;
}

std::string run(const std::string& scene, const std::string& sets, const std::string& name) {
  auto dir = test::unique_scratch(name);
  auto r = test::run_command(bin() + " run " + scene + " --quiet --out " + dir.string() + " " + sets);
  REQUIRE_MESSAGE(r.code == 0, r.output);
  return dir.string();
}

// The plate of scenes/elastic_plate_2d.toml: E = 2 MPa, nu = 0.3975, rho = 1000, H = 0.02 m,
// L = 0.2 m, kL = 1.875; plane strain.
double euler_bernoulli_period() {
  const double E = 2e6, nu = 0.3975, rho = 1000, H = 0.02, k = 1.875 / 0.2;
  return 2 * std::numbers::pi / std::sqrt(E * H * H * std::pow(k, 4) / (12 * rho * (1 - nu * nu)));
}

// The first time after t = 0.02 s that the tip, swinging up from rest, comes back down through 0.
double first_return(const std::filesystem::path& probes) {
  auto csv = test::read_csv(probes);
  const auto &t = csv["time"], &y = csv["tip_y"];
  for (std::size_t k = 0; k + 1 < t.size(); ++k)
    if (t[k] > 0.02 && y[k] > 0 && y[k + 1] <= 0) return t[k] - y[k] * (t[k + 1] - t[k]) / (y[k + 1] - y[k]);
  FAIL("the tip never came back through zero");
  return 0;
}

// No gravity, no walls: a water block at 1 m/s runs into an elastic block at rest.
const std::string kWaterIntoBlock = R"([scene]
dimension = 2
[domain]
min = [-0.2, -0.2]
max = [0.4, 0.3]
[particles]
spacing = 0.005
[material]
sound_speed = 20.0
[physics]
gravity = [0.0, 0.0]
[method]
name = "wcsph"
[time]
end = 0.06
[output]
interval = 0.03
fields = ["mass"]
[[fluid]]
min = [0.0, 0.0]
max = [0.05, 0.05]
velocity = [1.0, 0.0]
[[elastic]]
name = "block"
min = [0.06, 0.0]
max = [0.11, 0.05]
density = 1100.0
youngs_modulus = 1.0e6
poisson_ratio = 0.3
)";

// A 5 x 5 cm block (E = 1 MPa, nu = 0.3, rho = 1000) on the floor of a tank, under gravity.
const std::string kBlockOnWall = R"([scene]
dimension = 2
[domain]
min = [-0.05, -0.05]
max = [0.15, 0.15]
[particles]
spacing = 0.005
[method]
name = "wcsph"
[time]
end = 0.5
[output]
interval = 0.25
probe_interval = 0.01
[[wall]]
min = [0.0, 0.0]
max = [0.1, 0.1]
[[elastic]]
name = "block"
min = [0.025, 0.0]
max = [0.075, 0.05]
density = 1000.0
youngs_modulus = 1.0e6
poisson_ratio = 0.3
[[probe]]
name = "top_y"
type = "solid_displacement"
position = [0.05, 0.05]
axis = 1
)";

// The block's displacement scale rho g H^2 / E', E' = E / (1 - nu^2): 2.24e-5 m, twice the top's
// analytic settlement. "Keeps its shape" bounds every particle's displacement by a few times it
// (test audit round three, issue 50, row 26: 1% of the height, 5e-4 m, was 22 times it).
const double kBlockScale = 1000 * 9.81 * 0.05 * 0.05 / (1e6 / (1 - 0.09));

// The largest displacement of the elastic (kind 3) particles in a run's last frame.
double largest_block_displacement(const std::string& out) {
  const auto frame = test::last_frame(out);
  auto u = test::read_dataset(frame, "displacement").values;
  auto kind = test::read_dataset(frame, "kind").values;  // the frame's own order
  double largest = 0;
  int count = 0;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 3) largest = std::max(largest, std::hypot(u[3 * i], u[3 * i + 1])), ++count;
  REQUIRE(count == 100);  // 10 x 10 particles
  return largest;
}

}  // namespace

TEST_CASE("elastic: a clamped plate swings at the Euler-Bernoulli period within 5% at H/d = 16 and 20") {
  // The tip comes back through its rest position after half a period. Measured: +3.7% at H/d =
  // 16, +2.8% at 20; +7.6% (full period) at 10, +5.7% at 12, 26% at 5: the error falls as
  // (h/H)^2 (h = 1.5 d), the smoothing rounding off the bending strain across the thickness.
  const double half = 0.5 * euler_bernoulli_period();
  double previous = 1;
  for (int cells : {16, 20}) {
    char sets[160];
    std::snprintf(sets, sizeof sets, "--set particles.spacing=%.9g --set time.end=0.15", 0.02 / cells);
    const auto out = run(test::scene_path("elastic_plate_2d.toml"), sets, "plate");
    const double error = first_return(std::filesystem::path(out) / "probes.csv") / half - 1;
    MESSAGE("H/d = ", cells, ": half period ", half * (1 + error), " s against ", half, " s: ", 100 * error,
            "%");
    CHECK(std::abs(error) < 0.05);
    CHECK(std::abs(error) < previous);
    previous = std::abs(error);
  }
}

TEST_CASE("elastic: the plate keeps its energy over ten periods") {
  // H/d = 5, no artificial viscosity: velocity Verlet is symplectic and the total Lagrangian
  // forces derive from the strain energy, so kinetic + strain energy stays (measured within
  // 1e-5 of E0 over 2.6 s); the seed's artificial viscosity (A = B = 1) only takes energy out.
  const double T = euler_bernoulli_period();
  for (const char* viscosity : {"0", "1"}) {
    const auto out =
        run(test::scene_path("elastic_plate_2d.toml"),
            std::string("--set particles.spacing=0.004 --set time.end=") + std::to_string(10 * T) +
                " --set output.interval=1.0 --set output.probe_interval=0.01" +
                " --set method.solid_artificial_viscosity=" + viscosity +
                " --set method.solid_artificial_viscosity_quadratic=" + viscosity,
            "plate_energy");
    auto csv = test::read_csv(std::filesystem::path(out) / "probes.csv");
    const auto& E = csv["energy"];
    double low = 1e300, high = 0;
    for (double e : E) low = std::min(low, e), high = std::max(high, e);
    MESSAGE("artificial viscosity ", std::string(viscosity), ": energy ", E.front(), " J/m, between ",
            low / E.front(), " and ", high / E.front(), " of it over ", csv["time"].back(), " s");
    CHECK(csv["time"].back() >= 10 * T - 0.01);  // the last probe sample, every 0.01 s
    CHECK(high <= E.front() * (1 + 1e-3));
    if (std::string(viscosity) == "0") CHECK(low >= E.front() * (1 - 1e-3));
  }
}

TEST_CASE("elastic: a block at rest on a wall settles by its own weight and keeps its shape") {
  // A 5 x 5 cm block (E = 1 MPa, nu = 0.3, rho = 1000) on the floor of a tank, under gravity. Its
  // top settles by rho g H^2 / (2 E'), E' = E / (1 - nu^2) (plane strain, free sides): 1.12e-5 m.
  const std::string text = kBlockOnWall;
  auto dir = test::unique_scratch("elastic_block");
  test::write_text(dir / "block.toml", text);
  const auto out = run((dir / "block.toml").string(), "", "elastic_block_run");
  auto csv = test::read_csv(std::filesystem::path(out) / "probes.csv");
  const double expected = 1000 * 9.81 * 0.05 * 0.05 / (2 * 1e6 / (1 - 0.09));
  MESSAGE("top settles by ", -csv["top_y"].back(), " m (rho g H^2 / 2E' = ", expected, " m)");
  // Within 5% of it, relatively (test::within_relative: Approx's epsilon is absolute at this scale).
  CHECK_MESSAGE(test::within_relative(-csv["top_y"].back(), expected, 0.05),
                "top settles by " << -csv["top_y"].back() << " m against " << expected << " m");
  const double largest = largest_block_displacement(out);
  MESSAGE("largest displacement ", largest, " m, ", largest / kBlockScale, " x rho g H^2 / E'");
  // Keeps its shape: no particle moves more than rho g H^2 / E' (2.24e-5 m), twice the analytic
  // settlement; measured 0.51 of it (1.139e-5 m, the top's settlement: nothing else moves more).
  CHECK(largest < kBlockScale);
}

TEST_CASE(
    "elastic: seed 002's updated form keeps a block on a wall and swings the plate, softer than the total "
    "Lagrangian form") {
  // The seed's own form (continuity, Jaumann rate, artificial stress; updated_lagrangian_elastic.hpp)
  // at H/d = 10, against the analytic block (the total Lagrangian form: within 2%) and against the
  // total Lagrangian plate run here at the same spacing (measured 7.6% long).
  // Measured: the block's top settles 1.19x the analytic 1.12e-5 m (its shape kept: largest
  // displacement 0.60 rho g H^2 / E', 1.3e-5 m), the plate's half period is 16.9% long: the sums, cut at
  // the free surfaces, lose stiffness there (11.3% at H/d = 20, docs/multiphysics.md).
  auto dir = test::unique_scratch("elastic_updated");
  test::write_text(dir / "block.toml", kBlockOnWall);
  const std::string updated = "--set method.solid_formulation=\"updated\"";
  const auto block = run((dir / "block.toml").string(), updated, "elastic_updated_block");
  auto csv = test::read_csv(std::filesystem::path(block) / "probes.csv");
  const double settle = -csv["top_y"].back() / (1000 * 9.81 * 0.05 * 0.05 / (2 * 1e6 / (1 - 0.09)));
  const double largest = largest_block_displacement(block);
  const auto plate = run(test::scene_path("elastic_plate_2d.toml"), updated + " --set time.end=0.15",
                         "elastic_updated_plate");
  const double error =
      first_return(std::filesystem::path(plate) / "probes.csv") / (0.5 * euler_bernoulli_period()) - 1;
  // The total Lagrangian plate at the same spacing, run here (audit row 13; it measured 7.6%).
  const auto tl_plate =
      run(test::scene_path("elastic_plate_2d.toml"), "--set time.end=0.15", "elastic_tl_plate");
  const double tl_error =
      first_return(std::filesystem::path(tl_plate) / "probes.csv") / (0.5 * euler_bernoulli_period()) - 1;
  MESSAGE("block settles ", settle, " x the analytic, largest displacement ", largest / kBlockScale,
          " x rho g H^2 / E'; plate half period ", 100 * error, "% long (total Lagrangian: ", 100 * tl_error,
          "%)");
  CHECK(largest < kBlockScale);  // measured 0.60 of it, the top's 1.19x settlement
  CHECK(settle > 1.0);           // softer than Hooke's law ...
  CHECK(settle < 1.3);           // ... by the measured 19% and a margin
  CHECK(tl_error > 0);           // the smoothing's stiffness loss: the Euler-Bernoulli period is the floor
  CHECK(error > tl_error);       // softer: longer than the total Lagrangian form's, computed above
  CHECK(error < 0.2);            // the measured 16.9% and a margin (a regression guard: tests/README.md)
  // With the seed's walls (eq. 28 pressure, walls at rest in the sums) instead of contact springs
  // the block holds too, softer still at the wall: measured 2.11x, largest displacement 1.54 rho g
  // H^2 / E' (3.5e-5 m).
  const auto seed_walls = run((dir / "block.toml").string(), updated + " --set method.solid_walls=\"seed\"",
                              "elastic_updated_walls");
  auto walls_csv = test::read_csv(std::filesystem::path(seed_walls) / "probes.csv");
  const double walls_settle =
      -walls_csv["top_y"].back() / (1000 * 9.81 * 0.05 * 0.05 / (2 * 1e6 / (1 - 0.09)));
  const double walls_largest = largest_block_displacement(seed_walls);  // its own frame's kind
  MESSAGE("seed walls: block settles ", walls_settle, " x the analytic, largest displacement ",
          walls_largest / kBlockScale, " x rho g H^2 / E'");
  CHECK(walls_largest < 2 * kBlockScale);  // measured 1.54 times it
  CHECK(walls_settle > 1.0);
  CHECK(walls_settle < 2.5);  // the measured 2.11x and a margin
}

TEST_CASE("elastic: a 3D block stays at rest under no load and settles on a wall by its own weight") {
  // 6 x 6 x 6 particles (E = 1 MPa, nu = 0.3, rho = 1000, H = 0.06 m): with free sides its top
  // settles by rho g H^2 / (2E) = 1.766e-5 m (measured 1.756e-5 at t = 0.5 s). Without gravity
  // and walls nothing may move: at the body's corners det(M) is about 0.03, and the rest
  // correction once fell back to B = I there, so the block flew apart (1.7 cm in 0.025 s).
  const std::string text = R"([scene]
dimension = 3
[domain]
min = [-0.05, -0.05, -0.05]
max = [0.15, 0.15, 0.15]
[particles]
spacing = 0.01
[time]
end = 0.5
[output]
interval = 0.25
probe_interval = 0.01
[[wall]]
min = [0.0, 0.0, 0.0]
max = [0.1, 0.1, 0.1]
[[elastic]]
min = [0.02, 0.02, 0.0]
max = [0.08, 0.08, 0.06]
density = 1000.0
youngs_modulus = 1.0e6
poisson_ratio = 0.3
[[probe]]
name = "top_z"
type = "solid_displacement"
position = [0.05, 0.05, 0.06]
axis = 2
)";
  auto dir = test::unique_scratch("elastic_block_3d");
  test::write_text(dir / "block.toml", text);
  const auto out = run((dir / "block.toml").string(), "", "elastic_block_3d_run");
  auto csv = test::read_csv(std::filesystem::path(out) / "probes.csv");
  const double expected = 1000 * 9.81 * 0.06 * 0.06 / (2 * 1e6);
  MESSAGE("3D top settles by ", -csv["top_z"].back(), " m (rho g H^2 / 2E = ", expected, " m)");
  CHECK_MESSAGE(test::within_relative(-csv["top_z"].back(), expected, 0.05),
                "3D top settles by " << -csv["top_z"].back() << " m against " << expected << " m");
  const auto free = run((dir / "block.toml").string(),
                        "--set time.end=0.05 --set physics.gravity=[0.0,0.0,0.0]", "elastic_block_3d_free");
  auto u = test::read_dataset(test::last_frame(free), "displacement").values;
  auto kind = test::read_dataset(test::last_frame(free), "kind").values;
  double largest = 0;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 3) largest = std::max(largest, std::hypot(u[3 * i], u[3 * i + 1], u[3 * i + 2]));
  MESSAGE("without load: largest displacement ", largest, " m");
  CHECK(largest < 1e-12);
}

TEST_CASE("elastic: water hitting an elastic block exchanges momentum and keeps the total") {
  // The fluid feels the solid's particles as moving walls, the solid the reaction pair by pair,
  // so the total momentum (fluid m v plus solid rho0 d^2 v) is kept to round-off while the solid
  // takes up a good part of it.
  // Once with seed 002's single step and once with the solid in substeps of the fluid's step
  // (c_s = 35 m/s against c0 = 20: two substeps): the fluid's push enters the last kick either
  // way, so the exchange balances the same.
  auto dir = test::unique_scratch("elastic_momentum");
  test::write_text(dir / "hit.toml", kWaterIntoBlock);
  double share[2] = {0, 0};
  // Third: seed 002's updated form, whose forces differ but whose exchange with the water is the same.
  for (int substeps : {1, 4, 0}) {
    const std::string sets = substeps ? "--set method.solid_substeps=" + std::to_string(substeps)
                                      : "--set method.solid_formulation=\"updated\"";
    const auto out = run((dir / "hit.toml").string(), sets, "elastic_momentum_run");
    auto momentum = [&](int frame, double* solid) {
      auto f = test::frame_path(out, frame);
      auto m = test::read_dataset(f, "mass").values, v = test::read_dataset(f, "velocity").values,
           kind = test::read_dataset(f, "kind").values;
      double total = 0;
      *solid = 0;
      for (std::size_t i = 0; i < kind.size(); ++i) {
        if (kind[i] == 0) total += m[i] * v[3 * i];
        if (kind[i] == 3) *solid += 1100 * 0.005 * 0.005 * v[3 * i];
      }
      return total + *solid;
    };
    double solid0 = 0, solid = 0;
    const double p0 = momentum(0, &solid0), p = momentum(2, &solid);
    const std::string label = substeps ? "solid_substeps = " + std::to_string(substeps) : "updated form";
    MESSAGE(label, ": momentum ", p0, " -> ", p, " kg m/s per m; the solid's ", solid0, " -> ", solid);
    CHECK(solid0 == 0.0);
    CHECK(solid > 0.2 * p0);
    CHECK(std::abs(p - p0) < 1e-10 * p0);
    if (substeps) share[substeps == 1 ? 0 : 1] = solid / p0;
  }
  // The solid's share (0.380) moves by 1.3e-4 with the substeps (measured): the steps differ, the
  // physics not; a push entered per substep instead of once would double it.
  CHECK(std::abs(share[1] - share[0]) < 0.005);
}

TEST_CASE("elastic: a run stopped at a checkpoint and resumed ends bit-identical to an unstopped one") {
  // What the solid keeps between steps besides its columns (whether the forces in the column
  // are those at the positions, reused by the next step's first substep) goes into the
  // checkpoint: a resumed run takes the same steps. Water into a block, solid substeps and the
  // artificial viscosity on, so that a fresh evaluation would differ.
  auto dir = test::unique_scratch("elastic_resume");
  test::write_text(dir / "hit.toml", kWaterIntoBlock);
  const auto scene = (dir / "hit.toml").string(), full = (dir / "full").string(),
             part = (dir / "part").string();
  const std::string sets =
      " --quiet --checkpoint-interval 0.01 --set method.solid_substeps=4 --set output.interval=0.01";
  auto r = test::run_command(bin() + " run " + scene + sets + " --end-time 0.04 --out " + full);
  REQUIRE_MESSAGE(r.code == 0, r.output);
  r = test::run_command(bin() + " run " + scene + sets + " --end-time 0.02 --out " + part);
  REQUIRE_MESSAGE(r.code == 0, r.output);
  r = test::run_command(bin() + " resume " + part + " --quiet --end-time 0.04");
  REQUIRE_MESSAGE(r.code == 0, r.output);
  for (int k = 1; k <= 4; ++k) {
    for (const char* column : {"position", "velocity", "stress"}) {
      const auto a = test::read_dataset(test::frame_path(full, k), column).values;
      const auto b = test::read_dataset(test::frame_path(part, k), column).values;
      CHECK_MESSAGE(a == b, "frame " << k << ": " << column << " differs from the unstopped run");
    }
  }
}

TEST_CASE(
    "elastic: a solid particle that escapes stops the run with exit code 3 naming the step, system and "
    "particle") {
  // The health check covers elastic particles as it covers fluid ones: a block thrown at 50 m/s
  // out of a small domain (an unstable solid ends the same way: non-finite or out of the box).
  const std::string text = R"([scene]
dimension = 2
[domain]
min = [-0.05, -0.05]
max = [0.2, 0.1]
[particles]
spacing = 0.005
[physics]
gravity = [0.0, 0.0]
[method]
name = "wcsph"
[time]
end = 0.1
[[elastic]]
min = [0.0, 0.0]
max = [0.05, 0.05]
density = 1000.0
youngs_modulus = 1.0e6
poisson_ratio = 0.3
velocity = [50.0, 0.0]
)";
  auto dir = test::unique_scratch("elastic_escape");
  test::write_text(dir / "escape.toml", text);
  auto r = test::run_command(bin() + " run " + (dir / "escape.toml").string() + " --quiet --out " +
                             (dir / "out").string());
  CHECK(r.code == 3);
  CHECK_MESSAGE(r.output.find("numerical failure: step ") != std::string::npos, r.output);
  CHECK_MESSAGE(r.output.find("left the domain") != std::string::npos, r.output);
  CHECK_MESSAGE(r.output.find("after system 'elastic_") != std::string::npos, r.output);
}

TEST_CASE(
    "elastic: seed 002's drifting block hits the elastic plate, goes over it and the run holds to t = 0.5 "
    "s") {
  // scenes/drifting_body_2d.toml at d = 4 mm (the seed's 2 mm in docs/multiphysics.md), the
  // solid in up to 8 substeps of the water's step. Measured: the block reaches the plate at
  // t = 0.2 s, the tip swings 23 mm downstream (t = 0.23 s) and the upstream foot of the plate
  // takes 498 kPa of tension (the seed: tension on the upstream face, compression downstream); by
  // t = 0.3 s the block is over the plate, at 0.5 s carried up the run-up at the right wall,
  // whose spray (3 particles) leaves the box over the wall and is removed.
  const auto out = run(test::scene_path("drifting_body_2d.toml"), "--threads 2", "drifting_body");
  auto summary = test::read_text(std::filesystem::path(out) / "summary.json");
  CHECK(test::json_number(summary, "simulated_time") == doctest::Approx(0.5));
  // Spray over the walls only: under 1% of the 2,840 water particles.
  CHECK(test::json_number(summary, "removed_particles") < 28);
  auto csv = test::read_csv(std::filesystem::path(out) / "probes.csv");
  const auto &t = csv["time"], &tip = csv["plate_tip_x"], &sigma = csv["plate_foot_sigma22"];
  double swing = 0, tension = 0, before = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < 0.15)
      before = std::max(before, std::abs(tip[k]));
    else
      swing = std::max(swing, tip[k]), tension = std::max(tension, sigma[k]);
  }
  MESSAGE("plate tip: ", before, " m before t = 0.15 s, then up to ", swing, " m; foot sigma22 up to ",
          tension, " Pa");
  CHECK(before < 1e-3);  // the water alone barely moves it
  CHECK(swing > 0.005);  // the block's impact bends it downstream
  CHECK(tension > 1e5);  // and puts its upstream face in tension
  auto x = test::read_dataset(test::last_frame(out), "position").values;
  auto kind = test::read_dataset(test::last_frame(out), "kind").values;
  auto body = test::read_dataset(test::last_frame(out), "elastic_body").values;
  double block_left = 1e9;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 3 && body[i] == 1) block_left = std::min(block_left, x[3 * i]);
  CHECK(block_left > 0.41);  // over the plate (its downstream face at x = 0.41)
}
