// ISPH's dam break (scenes/dam_break_isph_2d.toml, Martin & Moyce n^2 = 2): the criterion of
// tests/front_criterion.hpp (one fitted time-origin shift in [0, 0.30], 3% after it for
// T <= 2.5, a/d = 20 and 40 within 3% of each other), a run through the far-wall impact and the
// returning wave to t = 2 s, and the same front with the multigrid and with Jacobi.
#include <doctest/doctest.h>

#include <cmath>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "front_criterion.hpp"
#include "h5_read.hpp"
#include "isph_one_set_up.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {
constexpr double a = 0.25, g = 9.81;
const double t_scale = std::sqrt(a / (2 * g));  // t = T sqrt(a / 2g)

RunOptions dam_break(const std::filesystem::path& out, double end_time, std::vector<std::string> sets) {
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_isph_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = end_time;
  sets.push_back("output.interval=0.05");
  sets.push_back("output.probe_interval=0.002");
  opt.sets = sets;
  return opt;
}
}  // namespace

// Measured (the hybrid gradient, symmetric only where the free surface cuts the support, p = 0
// extrapolated, 2026-11-27): a/d = 20 shift 0.260, 2.52% after it (unshifted up to 19.4%); a/d =
// 40 shift 0.286, 1.74% (18.3%). Through t = 2 s at a/d = 20 one particle leaves over the 2.5 m
// walls (the scene removes any that do, outflow = "remove"); the largest speed at the end is
// 5.2 m/s (3.8 with the hybrid's earlier det-only rule). (The symmetric gradient with p = 0 at the
// surface particles, the scene until then: shifts 0.220 and 0.254, 1.74% and 1.25%; the hybrid
// with p = 0 at the particles: a/d = 20 against 40 3.34%, over the criterion.)
TEST_CASE("isph: dam break front meets the criterion at a/d = 20 and 40 and runs through the impact to t = 2 s") {
  auto out = test::scratch("isph_dam_break_20");
  REQUIRE(run_scene(dam_break(out, 2.0, {"particles.spacing=0.0125"})) == kExitDone);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "completed");
  CHECK(test::json_number(summary, "simulated_time") >= 2.0);
  // Spray over the walls is allowed to leave, a little of it: 1% of the fluid.
  const double fluid = test::json_number(summary, "fluid_particles");
  const double removed = test::json_number(summary, "removed_particles");
  MESSAGE("a/d = 20: ", removed, " of ", fluid + removed, " fluid particles left over the walls");
  CHECK(removed <= 0.01 * (fluid + removed));
  // No blow-up: at t = 2 s the water sloshes in a pool 0.12 m deep, slower than the free fall
  // from the column's top, sqrt(2 g 2a) = 3.1 m/s, with room for a splash (twice that).
  const double max_speed = test::json_number(summary, "max_speed");
  MESSAGE("largest speed at t = 2 s: ", max_speed, " m/s");
  CHECK(max_speed < 2 * std::sqrt(2 * g * 2 * a));

  auto coarse = test::front_of(test::read_csv(out / "probes.csv"), a, t_scale);
  CHECK(coarse.Z.front() == doctest::Approx(1.0));
  CHECK(coarse.Z.back() >= 3.9);  // the front reached the far wall

  auto fine_out = test::scratch("isph_dam_break_40");
  REQUIRE(run_scene(dam_break(fine_out, 2.6 * t_scale, {"particles.spacing=0.00625"})) == kExitDone);
  auto fine = test::front_of(test::read_csv(fine_out / "probes.csv"), a, t_scale);
  test::check_time_origin_criterion(coarse, fine);
  // Measured: 2.42% over T <= 2.5 (the 3%); a/d = 40 against 80: 1.25%.
  double difference = test::front_difference(coarse, fine);
  MESSAGE("a/d = 20 against 40 over T <= 2.5: ", 100 * difference, "%");
  CHECK(difference <= 0.03);
}

// The one-set-up candidate (isph_one_set_up.hpp) on the same dam break: the criterion at a/d = 20
// and 40, through the impact and the plunging wave to t = 2.2 s with no particle over the walls.
// Measured 2026-11-28: a/d = 20 2.21% after a shift of 0.256, a/d = 40 1.52% after 0.280, 2.06%
// apart, none removed. Without its pair collisions the corrected gradient failed in the
// fragmented flow after the plunging wave in some runs (exit 3 at t = 1.42 s, the step below
// dt_min) and not in others (frames at other times change the steps): not asserted.
namespace {
// The criterion at a/d = 20 and 40 under `sets`, and a/d = 20 through the impact and the plunging
// wave to t = 2.2 s with no particle over the walls.
void check_dam_break_through_impact(const std::string& label, const std::vector<std::string>& sets) {
  auto with = [&](std::string spacing) {
    auto all = sets;
    all.push_back(std::move(spacing));
    return all;
  };
  auto out = test::scratch(label + "_20");
  REQUIRE(run_scene(dam_break(out, 2.2, with("particles.spacing=0.0125"))) == kExitDone);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_number(summary, "removed_particles") == 0);
  CHECK(test::json_number(summary, "max_speed") < 2 * std::sqrt(2 * g * 2 * a));
  auto coarse = test::front_of(test::read_csv(out / "probes.csv"), a, t_scale);
  CHECK(coarse.Z.back() >= 3.9);
  auto fine_out = test::scratch(label + "_40");
  REQUIRE(run_scene(dam_break(fine_out, 2.6 * t_scale, with("particles.spacing=0.00625"))) == kExitDone);
  auto fine = test::front_of(test::read_csv(fine_out / "probes.csv"), a, t_scale);
  test::check_time_origin_criterion(coarse, fine);
  const double difference = test::front_difference(coarse, fine);
  MESSAGE(label, ", a/d = 20 against 40 over T <= 2.5: ", 100 * difference, "%");
  CHECK(difference <= 0.03);
}
}  // namespace

TEST_CASE("isph: the one-set-up candidate meets the dam-break criterion and runs through the impact") {
  check_dam_break_through_impact("isph_one_set_up", test::isph_one_set_up());
}

// formulation = "implicit_density" at a CFL of 0.4 (DFSPH's; the scene's other keys do not apply to
// it). Measured 2026-11-29 (2 threads), undamped (the default; the column is not at rest, so the
// settle gives up after 20 steps and the run starts from the lattice): a/d = 20 to t = 2.2 s, 2.40%
// after a shift of 0.235, a/d = 40 1.68% after 0.264, 2.49% apart (with the particle-scale damping at
// 0.2: 1.77% after 0.215, 1.76% after 0.261, 2.61% apart).
// Before spray took no pressure of its own (kSprayDensity) two drops near the edge of each other's
// support were given 1e7-1e10 Pa and the run failed at t = 1.64 s (exit 3, a particle at 386 m/s).
TEST_CASE(
    "isph: the implicit density formulation meets the dam-break criterion at CFL 0.4 and runs through the "
    "impact") {
  check_dam_break_through_impact("isph_implicit_density",
                                 {"method.formulation=\"implicit_density\"", "time.cfl=0.4"});
}

// The preconditioner changes how the pressure equation is solved, not its solution: both solve
// to a relative residual of 1e-8, so the fronts agree far inside the 1%.
TEST_CASE("isph: the dam break's front is the same with the multigrid and with Jacobi") {
  auto multigrid_out = test::scratch("isph_dam_break_bmg");
  auto jacobi_out = test::scratch("isph_dam_break_jacobi");
  REQUIRE(run_scene(dam_break(multigrid_out, 2.6 * t_scale, {"particles.spacing=0.0125"})) == kExitDone);
  REQUIRE(run_scene(dam_break(jacobi_out, 2.6 * t_scale,
                              {"particles.spacing=0.0125", "solver.preconditioner=\"jacobi\""})) == kExitDone);
  auto multigrid = test::front_of(test::read_csv(multigrid_out / "probes.csv"), a, t_scale);
  auto jacobi = test::front_of(test::read_csv(jacobi_out / "probes.csv"), a, t_scale);
  double difference = test::front_difference(jacobi, multigrid);
  MESSAGE("front, Jacobi against multigrid over T <= 2.5: ", 100 * difference, "%");
  CHECK(difference <= 0.01);
  auto iterations = [](const std::filesystem::path& out) {
    return test::json_number(test::read_text(out / "summary.json"), "mean_iterations");
  };
  MESSAGE("mean BiCGSTAB iterations: multigrid ", iterations(multigrid_out), ", Jacobi ", iterations(jacobi_out));
  CHECK(iterations(multigrid_out) < iterations(jacobi_out));
  // The summary names the method the solves used: ISPH's matrix is not symmetric, so BiCGSTAB,
  // whatever [solver] krylov says (it said "cg", the default, while BiCGSTAB ran).
  CHECK(test::json_raw(test::read_text(multigrid_out / "summary.json"), "krylov") == "bicgstab");
}

// The I-SPH(2) column collapse (seed 000, I-SPH(2) section 5: a 40 cm square column in a 300 cm
// tank) with scenes/dam_break_isph2_2d.toml's set-up, coarse (d = 2 cm, a/d = 20) to t = 1.0 s:
// the front reaches the far wall (0.78 s at the paper's d = 0.5 cm),
// advances without stalling or blowing back until then, and no particle passes the far wall
// (the front stays within half a spacing of it). The paper's own operators stop at t = 0.41 s
// here (docs/isph.md).
TEST_CASE("isph: the I-SPH(2) column collapse runs through the far-wall impact") {
  auto out = test::scratch("isph2_column");
  const double d = 0.02, tank = 3.0;
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_isph2_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = 1.0;
  opt.sets = {"particles.spacing=0.02", "output.interval=1.0"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto front = test::read_csv(out / "probes.csv")["surge_front"];
  REQUIRE(front.size() > 100);
  CHECK(front.front() == doctest::Approx(0.4));
  std::size_t k = 1;
  for (; k < front.size() && front[k] < tank - d; ++k) CHECK(front[k] >= front[k - 1] - 1e-9);
  CHECK(k < front.size());  // reached the wall
  for (double x : front) CHECK(x <= tank + 0.5 * d);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_number(summary, "removed_particles") == 0);
}

// The 3D dam break (scenes/dam_break_isph_3d.toml, a/d = 10, the violent-flow set-up) to T = 3.4,
// past the impact on the far wall (reached at T = 3.1): it completes, its front meets the
// criterion (measured: shift 0.179, 2.31% after it, 13.1% before; 13 s alone), and
// no fluid particle centre lies past the single wall layer (d/2 behind the faces).
TEST_CASE("isph: 3D dam break runs through the impact, meets the front criterion and stays in its tank") {
  auto out = test::scratch("isph_dam_break_3d");
  const double d = 0.025;
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_isph_3d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = 3.4 * t_scale;
  opt.sets = {"output.interval=" + std::to_string(3.4 * t_scale)};
  REQUIRE(run_scene(opt) == kExitDone);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_number(summary, "removed_particles") == 0);
  auto front = test::front_of(test::read_csv(out / "probes.csv"), a, t_scale);
  auto fit = test::fit_time_origin(front);
  MESSAGE("ISPH 3D, a/d = 10: unshifted front errors ", fit.unshifted, "| time-origin shift ", fit.shift,
          " -> max error ", 100 * fit.error, "%");
  CHECK(fit.error <= 0.03);
  CHECK(fit.unshifted_lead <= 0.20);
  CHECK(front.Z.back() >= 3.9);
  auto inside = test::fluid_containment(test::last_frame(out), {0, 0, 0}, {1.0, 0.25, 0}, d / 2);
  CHECK(inside.fluid == 2000);
  CHECK(inside.outside == 0);
}
