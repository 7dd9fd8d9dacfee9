// Surface tension (src/systems/surface_tension/, issue 54): a square of liquid relaxes to a circle
// whose pressure is the Laplace pressure sigma / R of the equal-area circle, with no velocity left;
// and the system's bad input.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

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
// pressure over the last 20% 1.40% above sigma / R (R/d = 20: +0.52%); the drop at rest to 1e-9
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
