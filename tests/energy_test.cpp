// Energy in a sloshing tank (issue 15): scenes/sloshing_2d.toml, the first standing mode of water
// H = 0.5 m deep in a tank L = 1 m wide, started from rest with the surface H + a cos(pi x / L),
// a = 0.1 m, as eight columns on a 0.025 m lattice. The stair holds A = 23.0 J/m of potential
// energy above the flat surface. Physics says:
//   - the mechanical energy E = kinetic + potential (probes) never grows. Allowed: 5% of A. The
//     time integration's own error on an oscillation of frequency omega is about omega dt / 2
//     (0.4% at WCSPH's dt, 4% at the projection methods' 1.5 ms), and WCSPH's hydrostatic start
//     stores rho g^2 H^3 L / (6 c^2) = 2.0 J (9% of A) as compression that may come back;
//     measured: WCSPH at most +0.26 J (1.1% of A), in the first 0.1 s.
//   - the water cannot lose more than A (it would have to sink below the flat surface, i.e. lose
//     volume): E >= E(0) - 1.05 A. WCSPH's compression lowers the potential by twice the stored
//     2.0 J (a spring's share), within the 5%; measured -10.7 J after two periods.
//   - the mode keeps the linear period 2 pi / sqrt(g k tanh(k H)), k = pi / L: 1.182 s; the
//     height at the left wall is highest again within 5% of it (a / H = 0.2 shifts the period by
//     about 1% at second order; the stair adds higher modes). Measured (WCSPH): 1.20 s.
//   - the wave survives: after two periods the left-right height difference is at least half the
//     initial 0.2 m. The physical damping (wall boundary layers, nu = 1e-6) takes less than 1%
//     over two periods, so what goes is numerical; WCSPH measured 67% left.
// MPS passes since its Poisson source takes the density from a smooth kernel (source_density =
// "smooth", 2026-11-26): E never above E(0) (-12.8 .. 0 J/m), the left wall highest again at
// 1.190 s, 0.101 m of the wave left after two periods: the last at its bound (source_support 0.8,
// 0.85, 0.95: 0.080, 0.096, 0.090 m; H/d = 40: 0.106 m; docs/mps.md). With the BMG paper's
// number-density source MPS gains 4.1 J (18% of A) in the first quarter period and keeps 0.089 m:
// the MPS weight reads disorder as compression, so holding n* = n0 lets the water spread (0.9% in
// mean Voronoi cell by t = 0.3 s) and its centre of mass rise. (Until 2026-11-26 the scene fixed
// smoothing_ratio = 1.5, which gave MPS r_e = 1.5 l0: it gained 16 J, 69% of A.) The ISPH paper
// set-up gains 320 J and stops at t = 1.26 s (a particle thrown out of the domain). The known
// failures are marked should_fail: they pass while the defect is there and turn red, to be
// flipped, once it is fixed.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "isph_one_set_up.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

void check_sloshing_energy(const std::string& method, std::vector<std::string> sets = {}) {
  // Each set of overrides its own directory: ctest runs the cases side by side.
  std::string joined;
  for (const auto& s : sets) joined += s + ";";
  std::string name = "sloshing_" + method;
  if (!sets.empty()) {
    name += '_';
    name += std::to_string(std::hash<std::string>{}(joined) % 1000000);
  }
  auto out = test::scratch(name);
  RunOptions opt;
  opt.scene = test::scene_path("sloshing_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  sets.push_back("method.name=" + method);
  opt.sets = sets;
  const int code = run_scene(opt);
  CHECK(code == kExitDone);
  auto probes = test::read_csv(out / "probes.csv");
  const auto& t = probes["time"];
  const auto &kinetic = probes["kinetic_energy"], &potential = probes["potential_energy"];
  const auto &left = probes["height_left"], &right = probes["height_right"];
  REQUIRE(t.size() > 2);
  const double A = 0.5 * 1000 * 9.81 * 0.125 *
                   (0.6 * 0.6 + 0.575 * 0.575 + 0.55 * 0.55 + 0.525 * 0.525 + 0.475 * 0.475 + 0.45 * 0.45 +
                    0.425 * 0.425 + 0.4 * 0.4 - 8 * 0.25);
  const double E0 = kinetic[0] + potential[0];
  double highest = -1e300, lowest = 1e300;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double E = kinetic[k] + potential[k] - E0;
    highest = std::max(highest, E), lowest = std::min(lowest, E);
  }
  MESSAGE(method, ": E - E(0) between ", lowest, " and ", highest, " J/m (A = ", A, " J/m) to t = ", t.back(),
          " s");
  CHECK(highest <= 0.05 * A);
  CHECK(lowest >= -1.05 * A);

  const double omega = std::sqrt(9.81 * M_PI * std::tanh(M_PI * 0.5)), period = 2 * M_PI / omega;
  // The left height's highest sample between half a period and one and a half.
  std::size_t top = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] > 0.5 * period && t[k] < 1.5 * period && (top == 0 || left[k] > left[top])) top = k;
  REQUIRE(top > 0);
  MESSAGE(method, ": left wall highest again at t = ", t[top], " s (linear period ", period, " s)");
  CHECK(std::abs(t[top] / period - 1) < 0.05);
  REQUIRE(t.back() >= 2 * period - 1e-9);
  // The wave at t = 2 periods: the largest left-right difference within a tenth of a period of it.
  double difference = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (std::abs(t[k] - 2 * period) < 0.1 * period) difference = std::max(difference, left[k] - right[k]);
  MESSAGE(method, ": left-right height difference after two periods ", difference, " m (0.2 m at the start)");
  CHECK(difference >= 0.5 * 0.2);
}

// The violent-flow set-up of docs/isph.md (Shepard wall rows, standard Laplacians, the
// compression term, Fickian shifting) with the gradient and surface keys of each case added.
std::vector<std::string> isph_violent_flow(std::vector<std::string> sets) {
  sets.insert(sets.end(),
              {"method.wall_rows=\"shepard\"", "method.ppe_laplacian=\"standard\"",
               "method.viscous_laplacian=\"standard\"", "solver.tolerance=1e-6",
               "method.compression_relaxation=0.5", "shifting.model=\"fickian\"", "time.cfl=0.2"});
  return sets;
}

}  // namespace

// Seed 001's leapfrog (one force evaluation per step) is WCSPH's default; the midpoint (two) under
// the same physics.
TEST_CASE("energy: a WCSPH sloshing tank never gains energy and keeps the linear period") {
  check_sloshing_energy("wcsph");
}

TEST_CASE(
    "energy: a WCSPH sloshing tank with the midpoint integrator never gains energy and keeps the linear "
    "period") {
  check_sloshing_energy("wcsph", {"method.integrator=midpoint"});
}

TEST_CASE("energy: an MPS sloshing tank never gains energy and keeps the linear period") {
  check_sloshing_energy("mps");
}

TEST_CASE(
    "energy: an MPS sloshing tank with the number-density source never gains energy (known to fail: it gains "
    "18% "
    "of it)" *
    doctest::should_fail()) {
  check_sloshing_energy("mps", {"method.source_density=\"number_density\""});
}

// ISPH with the violent-flow set-up and the symmetric gradient (scenes/dam_break_isph_2d.toml's
// until 2026-11-27, with its h = 1.2 d) passes:
// E - E(0) between -15.6 and +0.46 J/m (the loss is mostly the column settling), period 1.231 s
// (4.1% long), 0.141 m left after two periods. (At h = 1.5 d, the scene's until 2026-11-26:
// -22.8 .. +0.23 J/m, 1.220 s, 0.161 m; with compression_relaxation 0.05 it lost 77 J.)
TEST_CASE(
    "energy: an ISPH sloshing tank with the violent-flow set-up never gains energy and keeps the period") {
  check_sloshing_energy("isph", isph_violent_flow({"method.pressure_gradient=\"symmetric\"",
                                                   "method.free_surface_pressure=\"particle\""}));
}

// The dam-break scene's hybrid gradient (symmetric where the free surface cuts the support,
// corrected elsewhere) does not conserve here: the corrected gradient is not the adjoint of the
// pressure equation's divergence, so the projection can add kinetic energy. Measured 2026-11-27:
// E - E(0) up to +13.7 J/m (A = 23.0) by t = 2.4 s; the hybrid that took the symmetric form
// wherever det M_i < 0.8 (disordered interior particles and the corners too) +64.4 J/m; the
// corrected gradient alone +35.3 J/m. docs/isph.md, "The hybrid gradient".
TEST_CASE(
    "energy: an ISPH sloshing tank with the dam-break scene's hybrid gradient never gains energy (known to "
    "fail: it gains 0.6 A)" *
    doctest::should_fail()) {
  check_sloshing_energy("isph", isph_violent_flow({"method.pressure_gradient=\"hybrid\""}));
}

// The one-set-up candidate (isph_one_set_up.hpp): the corrected gradient's projection with the
// full support's compression term holding the volume and pair collisions. Measured 2026-11-28:
// E - E(0) between -1.0 and +1.0 J/m (2 threads), the left wall highest again at 1.024 periods,
// 0.16 m of the wave left. Without the compression term it passes two periods (+0.44 J/m) but the
// 200-period tank swells (docs/isph.md).
TEST_CASE(
    "energy: an ISPH sloshing tank with the one-set-up candidate never gains energy and keeps the period") {
  check_sloshing_energy("isph", test::isph_one_set_up());
}

TEST_CASE(
    "energy: an ISPH sloshing tank never gains energy (known to fail: the paper set-up gains and stops)" *
    doctest::should_fail()) {
  check_sloshing_energy("isph");
}
