// ISPH's implicit density formulation in 3D: the box tank at rest (scenes/hydrostatic_isph_3d.toml,
// H/d = 10), with the formulation's 3D kernel, Wendland C2 at h = d. With the cubic spline at
// h = 1.2 d (the 2D kernel) the same tank moved at 7e-2 sqrt(g H) by t = 1-2 s: SPH's symmetric
// pressure force under a pressure destabilises the displacements that keep every kernel sum, and an
// incompressible solve answers only the kernel sums (docs/isph.md, "Which kernel holds a lattice
// under pressure"; tools/kernel_stability.py gives the growth rate, 31/s there, 0 at h = d).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "h5_read.hpp"
#include "shipped_scene_run.hpp"
#include "test_util.hpp"

using namespace ryushi;

// Measured 2026-11-29 (2 threads, 5.5 s), with the particle-scale damping at 0.2: the probe at 0.1 m
// depth within 0.26% of rho g depth over t = 0.5-2 s; at t = 2 s the largest speed 1.18e-4
// sqrt(g H) below the top four rows (the bottom layer's; issue 49 asks 1e-4: not met) and 4.4e-4 in
// them (1e-3: met). Without the damping 8.0e-4 and 1.4e-3, the probe within 0.42%. The bound below
// the top rows is 2.5x the measured, so that the instability (7e-2) or a slow growth fails; in them
// the issue's.
TEST_CASE("isph: a 3D tank stays at rest under the implicit density formulation") {
  const double H = 0.2, d = 0.02, rho_g = 1000 * 9.81;
  const auto out = test::run_shipped_scene("isph_implicit_density_3d_rest", "hydrostatic_isph_3d.toml", "",
                                           {"method.formulation=\"implicit_density\"", "time.end=2.0",
                                            "output.interval=0.5", "output.probe_interval=0.05"});
  auto probes = test::read_csv(out / "probes.csv");
  std::size_t samples = 0;
  double worst = 0;
  for (std::size_t k = 0; k < probes["time"].size(); ++k) {
    if (probes["time"][k] < 0.5) continue;
    const double deviation = std::abs(probes["p_depth_0.1"][k] / (rho_g * 0.1) - 1);  // NaN fails here
    CHECK_MESSAGE(deviation < 0.005,
                  "t = " << probes["time"][k] << ": " << probes["p_depth_0.1"][k] << " Pa");
    worst = std::max(worst, deviation), ++samples;
  }
  MESSAGE("3D implicit density: largest deviation from rho g depth over t = 0.5-2 s: ", worst);
  REQUIRE(samples >= 10);

  auto last = out / "frames" / "frame_00004.h5";
  auto x = test::read_dataset(last, "position").values, v = test::read_dataset(last, "velocity").values;
  auto kind = test::read_dataset(last, "kind").values;
  const double scale = std::sqrt(9.81 * H);
  double interior = 0, surface = 0;
  for (std::size_t i = 0; i < kind.size(); ++i) {
    if (kind[i] != 0) continue;
    double& band = x[3 * i + 2] < H - 4 * d ? interior : surface;
    band = std::max(band, std::hypot(v[3 * i], v[3 * i + 1], v[3 * i + 2]) / scale);
  }
  MESSAGE("3D implicit density at t = 2 s: max speed / sqrt(gH) below the top four rows ", interior,
          ", in them ", surface);
  CHECK(interior < 3.0e-4);
  CHECK(surface < 1.0e-3);
}
