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
// "smooth", 2026-11-26), asserted at H/d = 40 (audit row 9): E never above E(0) (-9.6 .. 0 J/m),
// the left wall highest again at 1.190 s, 0.123 m of the wave left after two periods (0.115 m
// with the solver's tolerance 3e-9 instead of 1e-8: the figure moves by 7% with round-off). At
// H/d = 20 it keeps 0.101 m, and 0.096 m with that tolerance: on both sides of the bound, so the
// coarse run cannot decide the case (2026-11-29; docs/mps.md). With the BMG paper's
// number-density source MPS gains 4.1 J (18% of A) in the first quarter period and keeps 0.089 m:
// the MPS weight reads disorder as compression, so holding n* = n0 lets the water spread (0.9% in
// mean Voronoi cell by t = 0.3 s) and its centre of mass rise. (Until 2026-11-26 the scene fixed
// smoothing_ratio = 1.5, which gave MPS r_e = 1.5 l0: it gained 16 J, 69% of A.) The ISPH paper
// set-up gains and stops: its health check 'energy' stops it at t = 0.954 s with E 59.7 J/m
// above its start (until the health checks, 320 J and a particle thrown out at 1.26 s). The known
// failures assert their defect's signature (test audit round three, issue 50, row 3; until then
// should_fail, which any failed assertion passed, a renamed key or a missing probe too): the run
// completes and E rises above E(0) by more than a stated amount, or it stops cleanly (exit 3)
// after a stated time; a run that keeps the energy fails with a message that the defect may be
// fixed, and the case is then to become check_sloshing_energy.
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

// What one sloshing run shows: its exit, the energy's range, the period and the wave left. The
// checks are the callers': check_sloshing_energy() for the cases that pass, the signature of the
// known defect for the others.
struct Sloshing {
  int code = -1;
  std::string summary;
  double A = 0, highest = 0, lowest = 0, period = 0;
  double top = -1;         // t of the left height's highest sample within (0.5, 1.5) periods; -1: none
  double difference = -1;  // the wave after two periods (m); -1: the run stopped before it
};

Sloshing run_sloshing(const std::string& method, std::vector<std::string> sets = {}) {
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
  Sloshing s;
  s.code = run_scene(opt);
  s.summary = test::read_text(out / "summary.json");
  auto probes = test::read_csv(out / "probes.csv");
  const auto& t = probes["time"];
  const auto &kinetic = probes["kinetic_energy"], &potential = probes["potential_energy"];
  const auto &left = probes["height_left"], &right = probes["height_right"];
  REQUIRE(t.size() > 2);
  s.A = 0.5 * 1000 * 9.81 * 0.125 *
        (0.6 * 0.6 + 0.575 * 0.575 + 0.55 * 0.55 + 0.525 * 0.525 + 0.475 * 0.475 + 0.45 * 0.45 +
         0.425 * 0.425 + 0.4 * 0.4 - 8 * 0.25);
  const double E0 = kinetic[0] + potential[0];
  s.highest = -1e300, s.lowest = 1e300;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double E = kinetic[k] + potential[k] - E0;
    s.highest = std::max(s.highest, E), s.lowest = std::min(s.lowest, E);
  }
  MESSAGE(method, ": exit ", s.code, ", E - E(0) between ", s.lowest, " and ", s.highest, " J/m (A = ", s.A,
          " J/m) to t = ", t.back(), " s");
  const double omega = std::sqrt(9.81 * M_PI * std::tanh(M_PI * 0.5));
  s.period = 2 * M_PI / omega;
  // The left height's highest sample between half a period and one and a half.
  std::size_t top = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] > 0.5 * s.period && t[k] < 1.5 * s.period && (top == 0 || left[k] > left[top])) top = k;
  if (top > 0) {
    s.top = t[top];
    MESSAGE(method, ": left wall highest again at t = ", s.top, " s (linear period ", s.period, " s)");
  }
  if (t.back() >= 2 * s.period - 1e-9) {
    // The wave at t = 2 periods: the largest left-right difference within a tenth of a period of it.
    s.difference = 0;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (std::abs(t[k] - 2 * s.period) < 0.1 * s.period)
        s.difference = std::max(s.difference, left[k] - right[k]);
    MESSAGE(method, ": left-right height difference after two periods ", s.difference,
            " m (0.2 m at the start)");
  }
  return s;
}

// The physics of the comment at the top.
void check_sloshing(const Sloshing& s) {
  CHECK(s.code == kExitDone);
  CHECK(s.highest <= 0.05 * s.A);
  CHECK(s.lowest >= -1.05 * s.A);
  REQUIRE(s.top > 0);
  CHECK(std::abs(s.top / s.period - 1) < 0.05);
  REQUIRE(s.difference >= 0);  // the run reached two periods
  CHECK(s.difference >= 0.5 * 0.2);
}

void check_sloshing_energy(const std::string& method, std::vector<std::string> sets = {}) {
  check_sloshing(run_sloshing(method, std::move(sets)));
}

// A known defect's signature (test audit round three, issue 50, row 3; the pattern of
// tests/stability/disorder_test.cpp): the run completes to two periods and E rises above E(0) by
// more than `gain`. A run that stays within the 5% of A is checked as the passing cases are and
// fails with a message: the defect may be fixed, and the case is to become check_sloshing_energy.
void check_known_gain(const Sloshing& s, double gain, const char* fixed) {
  const std::string message = s.code == kExitDone ? "" : test::json_raw(s.summary, "message");
  REQUIRE_MESSAGE(s.code == kExitDone, message);
  REQUIRE(s.difference >= 0);  // completed: two periods
  if (s.highest <= 0.05 * s.A) {
    check_sloshing(s);
    FAIL_CHECK(fixed);
    return;
  }
  CHECK_MESSAGE(s.highest > gain, "E rises " << s.highest
                                             << " J/m above E(0), over the 5% of A but less than the " << gain
                                             << " J/m this case knows: the defect has changed");
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
  check_sloshing_energy("mps", {"particles.spacing=0.0125"});  // H/d = 40: above
}

TEST_CASE(
    "energy: an MPS sloshing tank with the number-density source never gains energy (known to fail: it gains "
    "18% "
    "of it)") {
  // Measured 2026-11-29: completes, E - E(0) between -6.83 and +4.07 J/m (0.177 A), the left wall
  // highest again at 1.200 s, 0.089 m of the wave left. Asserted: a gain above 0.1 A (2.3 J/m),
  // twice the 5% that the passing cases hold to, and 57% of the measured gain.
  const auto s = run_sloshing("mps", {"method.source_density=\"number_density\""});
  check_known_gain(s, 0.1 * s.A,
                   "the MPS number-density source now keeps E within 5% of A over two periods: "
                   "the known gain may be fixed; make this case check_sloshing_energy");
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
// E - E(0) up to +13.7 J/m (A = 23.0) by t = 2.4 s (+12.2 on 2026-11-29); the hybrid that took the symmetric
// form wherever det M_i < 0.8 (disordered interior particles and the corners too) +64.4 J/m; the corrected
// gradient alone +35.3 J/m. docs/isph.md, "The hybrid gradient".
TEST_CASE(
    "energy: an ISPH sloshing tank with the dam-break scene's hybrid gradient never gains energy (known to "
    "fail: it gains 0.6 A)") {
  // Measured 2026-11-29: completes, E - E(0) between -0.81 and +12.2 J/m (0.53 A), period 1.221
  // s, 0.177 m left. Asserted: a gain above 0.25 A (5.7 J/m), five times the passing cases' 5%
  // and half the measured gain.
  const auto s = run_sloshing("isph", isph_violent_flow({"method.pressure_gradient=\"hybrid\""}));
  check_known_gain(s, 0.25 * s.A,
                   "the hybrid gradient now keeps E within 5% of A over two periods: the known "
                   "gain may be fixed; make this case check_sloshing_energy");
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

// formulation = "implicit_density": SPH's symmetric pressure force and the density change that is
// its adjoint, so the pressure does no work in the fluid. Undamped (the default since the settle;
// the tilted start is not at rest and is not settled). Measured 2026-11-29 (2 threads): E - E(0)
// between -6.1 and +0.93 J/m, the left wall highest again at 1.008 periods, 0.147 m of the wave left
// (with the particle-scale damping at 0.2 -8.2 .. +0.89, 1.015, 0.146 m; XSPH's smoothing at 0.05
// instead left 0.130 m).
TEST_CASE("energy: an ISPH sloshing tank with the implicit density formulation never gains energy") {
  check_sloshing_energy("isph", {"method.formulation=\"implicit_density\""});
}

TEST_CASE(
    "energy: an ISPH sloshing tank never gains energy (known to fail: the paper set-up gains and stops)") {
  const auto s = run_sloshing("isph");
  if (s.code == kExitDone) {
    check_sloshing(s);
    FAIL_CHECK(
        "the ISPH paper set-up now completes two periods: if it kept its energy (the checks above), the "
        "known failure is fixed; make this case check_sloshing_energy");
    return;
  }
  // Stops cleanly: exit 3, the message naming the step and the system, after the gain. Measured
  // 2026-11-29 (2 threads): the health check 'energy' stops it at step 640, t = 0.954 s, E 59.7
  // J/m above its start (5% of its energy scale, 1.19e3 J/m); the probes' largest E - E(0) before
  // it +57.1 J/m (2.5 A). Asserted: a stop after t = 0.75 s (a stop earlier than that is another
  // failure) with E above E(0) by more than A first.
  CHECK(s.code == kExitNumericalFailure);
  CHECK(test::json_raw(s.summary, "status") == "failed");
  const auto message = test::json_raw(s.summary, "message");
  INFO(message);
  CHECK(message.rfind("step ", 0) == 0);
  CHECK(message.find("system '") != std::string::npos);
  const double stopped = test::json_number(s.summary, "simulated_time");
  MESSAGE("isph paper set-up: stopped at t = ", stopped, " s: ", message);
  CHECK_MESSAGE(stopped > 0.75, "stops at t = " << stopped << " s, before the known failure: a new defect");
  CHECK_MESSAGE(s.highest > s.A, "E rose " << s.highest << " J/m before the stop, less than the known gain");
}
