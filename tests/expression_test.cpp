// Initial fields from expressions (functions/expression.hpp): the formulas' values, the errors a bad
// formula gives, the values landing on the particles of every method, and a flow that only
// expressions can set up, the Taylor-Green vortices, decaying at the analytic rate.
#include "functions/expression.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include "h5_read.hpp"
#include "scene/scene.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

constexpr double kPi = std::numbers::pi;

std::string load_error(const std::string& text, const std::vector<std::string>& sets = {}) {
  return test::scene_error(text, sets);
}

// A unit box with walls around a fluid block whose [[fluid]] table ends with `fluid_keys`.
std::string scene_with(const std::string& fluid_keys, const std::string& method = "wcsph") {
  return "[scene]\ndimension = 2\n[domain]\nmin = [-0.2, -0.2]\nmax = [1.2, 1.2]\n[particles]\nspacing = "
         "0.05\n"
         "[method]\nname = \"" +
         method +
         "\"\n[time]\nend = 0.1\n"
         "[[wall]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n"
         "[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, 0.5]\n" +
         fluid_keys;
}

}  // namespace

TEST_CASE("expression: formulas of x, y, z and t evaluate as written") {
  CHECK(Expression("sin(2*pi*x)*cos(2*pi*y)")(0.25, 0.0, 0.0) == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(Expression("x^2 + y*z - t")(3.0, 2.0, 5.0, 1.0) == 18.0);
  CHECK(Expression("x < 0.5 ? 1 : -1")(0.7, 0, 0) == -1.0);
  CHECK(Expression("e")(0, 0, 0) == std::numbers::e);
  CHECK(Expression("-1000/4*(cos(4*pi*x) + cos(4*pi*y))")(0.0, 0.0, 0.0) == -500.0);
  // Copies share one compiled parser: both see their own arguments.
  Expression a("2*x"), b = a;
  CHECK(a(1, 0, 0) == 2.0);
  CHECK(b(4, 0, 0) == 8.0);
  CHECK_THROWS_AS(Expression("sin(2*pi*x"), ExpressionError);
  CHECK_THROWS_AS(Expression("w + 1"), ExpressionError);
  CHECK_THROWS_AS(Expression(""), ExpressionError);
}

TEST_CASE("expression: a bad formula is bad input at its key, with the parser's message") {
  CHECK(load_error(scene_with("velocity = [\"sin(2*pi*x\", 0.0]\n")) ==
        "bad.toml:18:13: 'velocity' in [[fluid]] #0, axis 0: expression \"sin(2*pi*x\": Missing parenthesis");
  CHECK(load_error(scene_with("velocity = [0.0, \"x + w\"]\n")) ==
        "bad.toml:18:18: 'velocity' in [[fluid]] #0, axis 1: expression \"x + w\": Unexpected token \"w\" "
        "found at "
        "position 4.");
  CHECK(load_error(scene_with("pressure = \"1000*\"\n")) ==
        "bad.toml:18:12: 'pressure' in [[fluid]] #0: expression \"1000*\": Unexpected end of expression at "
        "position 6");
  CHECK(load_error(scene_with("velocity = [\"x\"]\n")) ==
        "bad.toml:18:12: 'velocity' in [[fluid]] #0 has 1 values; the scene is 2D");
  CHECK(load_error(scene_with("velocity = [true, 0.0]\n")) ==
        "bad.toml:18:12: 'velocity' in [[fluid]] #0 must be array of numbers or expressions (one per axis)");
  CHECK(load_error(scene_with(""), {"fluid.0.pressure=\"2*\""}) ==
        "--set fluid.0.pressure=\"2*\": 'pressure' in [[fluid]] #0: expression \"2*\": Unexpected end of "
        "expression "
        "at position 3");
  CHECK(load_error(scene_with("velocity = [\"y\", \"-x\"]\npressure = \"100*y\"\n")) == "");
}

TEST_CASE("expression: a formula that is not finite at some particle stops the run before it starts") {
  std::string bin = RYUSHI_BINARY;
  auto dir = test::unique_scratch("expression_nan");
  test::write_text(dir / "nan.toml", scene_with("velocity = [\"sqrt(0.5 - x)\", 0.0]\n"));
  auto r =
      test::run_command(bin + " run " + (dir / "nan.toml").string() + " --out " + (dir / "out").string());
  CHECK(r.code == 2);
  // "nan" or "-nan": the sign printf gives a NaN depends on the C library (glibc writes -nan).
  const std::string place = "nan.toml:18:12: [[fluid]] #0 velocity (axis 0) \"sqrt(0.5 - x)\" is ";
  const auto at = r.output.find(place);
  REQUIRE_MESSAGE(at != std::string::npos, r.output);
  const auto rest = r.output.substr(at + place.size());
  CHECK_MESSAGE((rest.starts_with("nan at (0.525, 0.025)") || rest.starts_with("-nan at (0.525, 0.025)")),
                r.output);
  CHECK_MESSAGE(!std::filesystem::exists(dir / "out"), "nothing written on bad input");
}

TEST_CASE(
    "expression: every method starts its particles with the formulas' values, and check --write-initial "
    "shows them") {
  std::string bin = RYUSHI_BINARY;
  for (std::string method : {"wcsph", "mps", "isph"}) {
    CAPTURE(method);
    auto dir = test::unique_scratch("expression_fields_" + method);
    test::write_text(
        dir / "s.toml",
        scene_with("velocity = [\"sin(pi*x)\", \"x*y - 0.25\"]\npressure = \"100 + 50*x\"\n", method));
    auto r = test::run_command(bin + " check " + (dir / "s.toml").string() + " --write-initial " +
                               (dir / "initial").string());
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CHECK(r.output.find("initial particles: " + (dir / "initial" / "particles.xdmf").string()) !=
          std::string::npos);
    CHECK(test::read_text(dir / "initial" / "particles.xdmf").find("frames/frame_00000.h5") !=
          std::string::npos);
    const auto frame = dir / "initial" / "frames" / "frame_00000.h5";
    auto x = test::read_dataset(frame, "position").values, v = test::read_dataset(frame, "velocity").values,
         p = test::read_dataset(frame, "pressure").values, kind = test::read_dataset(frame, "kind").values;
    std::size_t fluid = 0, walls = 0;
    double velocity_error = 0, pressure_error = 0;
    for (std::size_t i = 0; i < kind.size(); ++i) {
      if (kind[i] != 0) {
        ++walls;
        continue;
      }
      ++fluid;
      const double px = x[3 * i], py = x[3 * i + 1];
      velocity_error = std::max({velocity_error, std::abs(v[3 * i] - std::sin(kPi * px)),
                                 std::abs(v[3 * i + 1] - (px * py - 0.25))});
      pressure_error = std::max(pressure_error, std::abs(p[i] - (100 + 50 * px)) / (100 + 50 * px));
    }
    CHECK(fluid == 200);  // the 1 x 0.5 block at d = 0.05
    CHECK(walls > 0);
    CHECK(velocity_error < 1e-14);
    // MPS and ISPH take the pressure as given; WCSPH goes through its equation of state and back
    // (rho = rho0 (1 + p / B)^(1/7), p = B ((rho / rho0)^7 - 1)): round-off of that pair.
    CHECK(pressure_error < (method == "wcsph" ? 1e-9 : 1e-15));
    if (method == "isph") {  // the single wall layer with its normals, for the Neumann rows
      auto n = test::read_dataset(frame, "wall_normal").values;
      for (std::size_t i = 0; i < kind.size(); ++i)
        if (kind[i] != 0) CHECK(std::hypot(n[3 * i], n[3 * i + 1]) == doctest::Approx(1.0));
    }
  }
}

namespace {

// Largest |E(t) / E(0) / exp(-16 pi^2 nu t) - 1| over the kinetic-energy samples with t <= until:
// the Taylor-Green vortices' energy against the exact viscous decay (nu = 0.01 m^2/s). `run`
// receives the output directory.
double taylor_green_energy_error(const std::string& extra_sets, double until, double& at_end,
                                 std::filesystem::path* run = nullptr) {
  std::string bin = RYUSHI_BINARY;
  auto dir = test::unique_scratch("taylor_green");
  auto r = test::run_command(bin + " run " + test::scene_path("taylor_green_2d.toml") + " --quiet --out " +
                             dir.string() + extra_sets);
  REQUIRE_MESSAGE(r.code == 0, r.output);
  auto csv = test::read_csv(dir / "probes.csv");
  const auto& t = csv["time"];
  const auto& e = csv["kinetic_energy"];
  double worst = 0;
  for (std::size_t k = 0; k < t.size() && t[k] <= until + 1e-9; ++k) {
    at_end = e[k] / e[0] / std::exp(-16 * kPi * kPi * 0.01 * t[k]) - 1;
    worst = std::max(worst, std::abs(at_end));
  }
  REQUIRE(t.back() >= until - 1e-9);
  if (run) *run = dir;
  return worst;
}

// L2 distance of the particles' velocities from the exact field at their positions, relative to
// the exact field's L2, in frame `frame` (at time t) of a Taylor-Green run.
double taylor_green_velocity_error(const std::filesystem::path& run, int frame, double t) {
  auto x = test::read_dataset(test::frame_path(run, frame), "position").values;
  auto v = test::read_dataset(test::frame_path(run, frame), "velocity").values;
  const double decay = std::exp(-8 * kPi * kPi * 0.01 * t);
  double diff = 0, norm = 0;
  for (std::size_t i = 0; 3 * i < x.size(); ++i) {
    const double px = 2 * kPi * x[3 * i], py = 2 * kPi * x[3 * i + 1];
    const double u = -std::cos(px) * std::sin(py) * decay, w = std::sin(px) * std::cos(py) * decay;
    diff += std::pow(v[3 * i] - u, 2) + std::pow(v[3 * i + 1] - w, 2);
    norm += u * u + w * w;
  }
  return std::sqrt(diff / norm);
}

}  // namespace

TEST_CASE("expression: Taylor-Green vortices set up by formulas decay at the viscous rate") {
  // WCSPH without shifting, before its particles gather in lines (from t = 0.15 s): the energy
  // falls 14.6% by t = 0.1 s, so 1% pins the decay rate (the viscosity) to about 7%; measured
  // 0.45%. A wrong viscous term (or the artificial viscosity the scene turns off, +7.5% on nu)
  // shows up beyond that.
  double end = 0;
  CHECK(taylor_green_energy_error(" --set method.name=wcsph --set shifting.model=none --set time.end=0.1",
                                  0.1, end) < 0.01);
  // ISPH with Fickian shifting, the scene as it is, to t = 1 s (the energy falls 79%): the energy
  // goes as exp(-16 pi^2 nu t), so at t = 1 s an error of x on nu moves it by about 1.58 x, and 3%
  // on the energy pins the rate to 1.9%, a quarter of the artificial viscosity's +7.5% on nu (an
  // 11% energy error here). Measured 2.44% (0.4% up to t = 0.3 s, then above the exact decay).
  // Both energy bounds below keep 0.6-0.8 points over the error measured when they were set
  // (2.36% here, 3.20% confined): these errors move by 0.1-0.2 points with the code around them
  // (now 2.44%, 2.99%), and a tighter bound would fail on that (issue 50, audit row 29). The
  // velocity field against the exact one at t = 0.2, 0.5, 1 s, measured 0.15%, 0.66%, 1.38%: 2%.
  // With A = 2 it was 10.7%, 7.8%, 3.5%: the lattice strained at the stagnation points made the pressure grow
  // stripes from t = 0.064 s, and the weaker shifting never repaired it (docs/isph.md, "Open").
  std::filesystem::path run;
  // Over the first 0.2 s (the energy falls 27%) the bound the suite has always had, 1%: measured 0.65%.
  CHECK(taylor_green_energy_error(" --set time.end=0.2", 0.2, end) < 0.01);
  CHECK(taylor_green_energy_error("", 1.0, end, &run) < 0.03);
  for (double t : {0.2, 0.5, 1.0}) {
    const double error = taylor_green_velocity_error(run, static_cast<int>(std::lround(t / 0.02)), t);
    MESSAGE("ISPH, t = ", t, " s: velocity L2 error ", 100 * error, "%");
    CHECK(error < 0.02);
  }
  // Declared confined (no free-surface detection; the periodic box has no Dirichlet row, so the
  // gauge sets the level): measured 2.99% on the energy (3.20% when its bound was set), velocity
  // 0.87%, 0.93%, 1.66%. 4% on the energy pins the rate to 2.5%, still a third of the artificial
  // viscosity's 7.5%; 3% would leave no margin (above).
  CHECK(taylor_green_energy_error(" --set method.confined=true", 1.0, end, &run) < 0.04);
  for (double t : {0.2, 0.5, 1.0}) {
    const double error = taylor_green_velocity_error(run, static_cast<int>(std::lround(t / 0.02)), t);
    MESSAGE("ISPH confined, t = ", t, " s: velocity L2 error ", 100 * error, "%");
    CHECK(error < 0.02);
  }
}

// Pair collisions (the ISPH one-set-up candidate's 0.8 d) on the same vortices: the smooth strain
// at the stagnation points brings pairs closer than 0.8 d, and taking their approach as a collision
// drained 4.8% of the energy by t = 0.2 s (measured; the scene without collisions 0.65%). With
// collision_approach = "beyond_resolved_flow" the approach the fitted velocity gradient explains
// is left alone: measured 0.59%, so the suite's 1% over 0.2 s holds, and "full" must fail it.
TEST_CASE("expression: Taylor-Green vortices keep their energy with collisions beyond the resolved flow") {
  const std::string collisions = " --set time.end=0.2 --set method.collision_distance=0.8";
  double end = 0;
  CHECK(taylor_green_energy_error(collisions + " --set method.collision_approach=beyond_resolved_flow", 0.2,
                                  end) < 0.01);
  CHECK(taylor_green_energy_error(collisions, 0.2, end) > 0.02);
}
