// Surface tension (src/systems/surface_tension/, issue 54): a square of liquid relaxes to a circle
// whose pressure is the Laplace pressure sigma / R of the equal-area circle, with no velocity left;
// the cube to a sphere (coarse); a drop's mode-2 oscillation against Lamb; the system's bad input.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "scene_error.hpp"
#include "shipped_scene_run.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

constexpr double kSigma = 0.007, kSide = 0.001;

std::string exact(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

double laplace_pressure_2d() {
  return kSigma / (kSide / std::sqrt(std::numbers::pi));
}

}  // namespace

// scenes/square_drop_2d.toml at 18 particles across (R/d = 10) and mu = 0.01 Pa s (Ohnesorge
// mu / sqrt(rho sigma R) = 0.17), to 2 R^2 / nu = 0.064 s. Measured 2026-11-30: the centre's
// pressure over the last 20% 1.33% above sigma / R (R/d = 20: +0.53%); the drop at rest to 1e-10
// m/s. Asserted: within 3% (the bound at R/d = 20), and the largest speed below 1e-3
// sigma / mu (the spurious-current bound). At water's viscosity the drop is not stable at
// these resolutions (docs/surface_tension.md, "Open").
TEST_CASE("surface tension: a square drop relaxes to a circle at the Laplace pressure") {
  const double mu = 0.01, radius = kSide / std::sqrt(std::numbers::pi),
               end = 2 * radius * radius / (mu / 1000);
  const auto out = test::run_shipped_scene(
      "square_drop", "square_drop_2d.toml", "",
      {"particles.spacing=" + exact(kSide / 18), "material.viscosity=" + exact(mu), "time.end=" + exact(end),
       "output.interval=" + exact(end / 4), "output.probe_interval=" + exact(end / 100)});
  auto csv = test::read_csv(out / "probes.csv");
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < csv["time"].size(); ++k)
    if (csv["time"][k] >= 0.8 * end) sum += csv["p_centre"][k], ++count;
  REQUIRE(count > 5);
  const double pressure = sum / count, exact = laplace_pressure_2d();
  MESSAGE("pressure over the last 20%: ", pressure, " Pa against sigma / R = ", exact, " Pa");
  CHECK(std::abs(pressure / exact - 1) < 0.03);
  const auto velocity = test::read_dataset(test::last_frame(out), "velocity");
  double fastest = 0;
  for (std::size_t k = 0; k + 2 < velocity.values.size(); k += 3)
    fastest = std::max(fastest, std::hypot(velocity.values[k], velocity.values[k + 1]));
  MESSAGE("largest speed at the end: ", fastest, " m/s");
  CHECK(fastest < 1e-3 * kSigma / mu);
}

// scenes/cube_drop_3d.toml at 10 across (1,000 particles; R/d = 6.2), mu = 0.01, to 2 R^2 / nu:
// the 3D fit and normal. Measured 2026-11-30: the centre's pressure over the last 20% 4.7% above
// 2 sigma / R (20 across: +4.8%, most of it the volume the 3D projection loses; docs/
// surface_tension.md). Asserted: 8%, a coarse guard of the 3D fit and normal; the 5% is for
// 40 across.
TEST_CASE("surface tension: the paper's cube relaxes to a sphere near its Laplace pressure (coarse)") {
  const double radius = kSide * std::cbrt(3 / (4 * std::numbers::pi));
  const auto out = test::run_shipped_scene("cube_drop", "cube_drop_3d.toml", "", {"particles.spacing=1e-4"});
  auto csv = test::read_csv(out / "probes.csv");
  const double end = csv["time"].back();
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < csv["time"].size(); ++k)
    if (csv["time"][k] >= 0.8 * end) sum += csv["p_centre"][k], ++count;
  REQUIRE(count > 5);
  const double pressure = sum / count, exact = 2 * kSigma / radius;
  MESSAGE("pressure over the last 20%: ", pressure, " Pa against 2 sigma / R = ", exact, " Pa");
  CHECK(std::abs(pressure / exact - 1) < 0.08);
}

namespace {

// The square drop at 18 across relaxed at mu = 0.01 (as above): its last frame.
std::filesystem::path relaxed_drop(const std::string& name) {
  const double mu = 0.01, radius = kSide / std::sqrt(std::numbers::pi),
               end = 2 * radius * radius / (mu / 1000);
  const auto out =
      test::run_shipped_scene(name, "square_drop_2d.toml", "",
                              {"particles.spacing=" + exact(kSide / 18), "material.viscosity=" + exact(mu),
                               "time.end=" + exact(end), "output.interval=" + exact(end / 2)});
  return test::last_frame(out);
}

// (Ixx - Iyy) / (Ixx + Iyy) of the particles about their centre: 2 eps for r = R (1 + eps cos 2 theta).
double deformation(const std::filesystem::path& frame) {
  const auto x = test::read_dataset(frame, "position").values;
  const std::size_t n = x.size() / 3;
  double cx = 0, cy = 0;
  for (std::size_t k = 0; k < n; ++k) cx += x[3 * k] / n, cy += x[3 * k + 1] / n;
  double ixx = 0, iyy = 0;
  for (std::size_t k = 0; k < n; ++k)
    ixx += (x[3 * k] - cx) * (x[3 * k] - cx), iyy += (x[3 * k + 1] - cy) * (x[3 * k + 1] - cy);
  return (ixx - iyy) / (ixx + iyy);
}

}  // namespace

// Mode 2 of a drop at rest (the relaxed square above, R/d = 10) given the potential flow
// v = A (x, -y) that swings its surface by 5% of R, at water's viscosity (Ohnesorge 0.016), 3.5
// periods. Measured 2026-11-30: period 1.1% above Lamb's 2 pi sqrt(rho R^3 / (6 sigma)), the
// amplitude's decay 5.1% above 4 nu / R^2 (R/d = 20: +0.8%, -6.7%). Asserted: the 5% and
// 30%, from the peaks of the deformation (period: their spacing; decay: their ratio).
TEST_CASE("surface tension: a drop's mode-2 oscillation has Lamb's period and decays at 4 nu / R^2") {
  const auto start = relaxed_drop("oscillating_drop_start");
  const double radius = kSide / std::sqrt(std::numbers::pi), rho = 1000, mu = 1e-3;
  const double omega = std::sqrt(6 * kSigma / (rho * radius * radius * radius)), lift = 0.05 * omega;
  const auto x = test::read_dataset(start, "position").values,
             p = test::read_dataset(start, "pressure").values;
  const std::size_t n = x.size() / 3;
  double cx = 0, cy = 0;
  for (std::size_t k = 0; k < n; ++k) cx += x[3 * k] / n, cy += x[3 * k + 1] / n;
  auto dir = test::unique_scratch("oscillating_drop");
  std::string csv = "x,y,u,v,p\n";
  for (std::size_t k = 0; k < n; ++k)
    csv += exact(x[3 * k] - cx) + "," + exact(x[3 * k + 1] - cy) + "," + exact(lift * (x[3 * k] - cx)) + "," +
           exact(-lift * (x[3 * k + 1] - cy)) + "," + exact(p[k]) + "\n";
  test::write_text(dir / "drop.csv", csv);
  std::string scene = test::read_text(test::scene_path("square_drop_2d.toml"));
  const auto block = scene.find("[[fluid]]");
  REQUIRE(block != std::string::npos);
  scene.replace(block, scene.find("[[systems]]") - block, "[[import]]\nfile = \"drop.csv\"\n\n");
  test::write_text(dir / "scene.toml", scene);
  RunOptions opt;
  opt.scene = (dir / "scene.toml").string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  opt.sets = {"particles.spacing=" + exact(kSide / 18), "material.viscosity=" + exact(mu), "time.end=0.045",
              "output.interval=0.0005"};
  REQUIRE(run_scene(opt) == kExitDone);
  std::vector<double> t, shape;
  for (int k = 0; std::filesystem::exists(test::frame_path(dir / "out", k)); ++k)
    t.push_back(0.0005 * k), shape.push_back(deformation(test::frame_path(dir / "out", k)));
  REQUIRE(t.size() == 91);
  std::vector<double> peak_t, peak;  // local maxima, refined by a parabola through three samples
  for (std::size_t k = 1; k + 1 < shape.size(); ++k)
    if (shape[k] > shape[k - 1] && shape[k] >= shape[k + 1]) {
      const double a = shape[k - 1], b = shape[k], c = shape[k + 1], s = 0.5 * (a - c) / (a - 2 * b + c);
      peak_t.push_back(t[k] + s * 0.0005), peak.push_back(b - 0.25 * (a - c) * s);
    }
  REQUIRE(peak.size() >= 3);
  const double period = (peak_t[2] - peak_t[0]) / 2, lamb = 2 * std::numbers::pi / omega;
  const double decay = std::log(peak[0] / peak[2]) / (peak_t[2] - peak_t[0]),
               viscous = 4 * mu / rho / (radius * radius);
  MESSAGE("period ", period, " s against Lamb's ", lamb, "; decay ", decay,
          " 1/s against 4 nu / R^2 = ", viscous);
  CHECK(std::abs(period / lamb - 1) < 0.05);
  CHECK(std::abs(decay / viscous - 1) < 0.3);
}

TEST_CASE("surface tension: bad keys and a method without free-surface rows are exit 2 at the key") {
  const std::string base = test::read_text(test::scene_path("square_drop_2d.toml"));
  CHECK(test::scene_error(base, {"systems.0.sigma=-0.1"}).find("'sigma'") != std::string::npos);
  CHECK(test::scene_error(base, {"systems.0.contact_angle=180"}).find("must be > 0 and < 180") !=
        std::string::npos);
  CHECK(test::scene_error(base, {"systems.0.curvature=\"exact\""}).find("'curvature'") != std::string::npos);
  const auto wcsph = test::scene_error(base, {"method.name=\"wcsph\""});
  CHECK(wcsph.find(
            "system 'surface_tension' needs free_surface_pressure, which method 'wcsph' does not provide") !=
        std::string::npos);
  const auto implicit = test::scene_error(base, {"method.formulation=\"implicit_density\""});
  CHECK(implicit.find("needs free_surface_pressure, which method 'isph' does not provide") !=
        std::string::npos);
  CHECK(test::scene_error(base) == "");
}
