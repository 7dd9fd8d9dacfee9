// Acceptance 2 and 3 of the foundation issue: the 2D dam break (Martin & Moyce 1952, n^2 = 2)
// and the 3D dam break.
//
// Surge front: the criterion of tests/front_criterion.hpp (one fitted time-origin shift in
// [0, 0.30], 3% after it for T <= 2.5, a/d = 20 and 40 within 3% of each other); the unshifted
// errors are printed beside it.
#include <doctest/doctest.h>

#include <cmath>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "front_criterion.hpp"
#include "test_util.hpp"

using namespace ryushi;


TEST_CASE("validation: 2D dam break surge front follows Martin and Moyce, runs past the impact, conserves mass") {
  auto out = test::scratch("dam_break_2d");
  const double a = 0.25, g = 9.81, T_end = 6.2;
  const double t_scale = std::sqrt(a / (2 * g));  // t = T * sqrt(a / 2g)
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = T_end * t_scale;
  opt.sets = {"particles.spacing=0.0125", "output.interval=0.05", "output.probe_interval=0.002"};  // a / d = 20
  REQUIRE(run_scene(opt) == kExitDone);

  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "completed");
  CHECK(test::json_number(summary, "simulated_time") / t_scale >= 6.0);
  // Mass is exact by construction; the volume sum m/rho and the density can drift. WCSPH's sound
  // speed (10 times the largest speed) keeps density variations near 1% (Mach^2): measured +0.2%
  // volume and 0.48% peak deviation through the impact at a/d = 20.
  CHECK(std::abs(test::json_number(summary, "fluid_volume_relative_change")) < 0.01);
  CHECK(test::json_number(summary, "max_density_deviation") < 0.02);

  auto coarse = test::front_of(test::read_csv(out / "probes.csv"), a, t_scale);
  CHECK(coarse.Z.front() == doctest::Approx(1.0));
  // The front reaches the far wall (Z = 4) and stays there or beyond the impact.
  CHECK(coarse.Z.back() >= 3.9);

  // a/d = 40 to T = 2.6 for the convergence check (the window ends at 2.5).
  auto fine_out = test::scratch("dam_break_2d_fine");
  opt.out_dir = fine_out.string();
  opt.end_time = 2.6 * t_scale;
  opt.sets = {"particles.spacing=0.00625", "output.interval=0.05", "output.probe_interval=0.002"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto fine = test::front_of(test::read_csv(fine_out / "probes.csv"), a, t_scale);

  test::check_time_origin_criterion(coarse, fine);
  double difference = test::front_difference(coarse, fine);
  MESSAGE("a/d = 20 against 40 over T <= 2.5: ", 100 * difference, "%");
  CHECK(difference <= 0.03);
}

TEST_CASE("validation: 3D dam break scene completes at coarse resolution") {
  auto out = test::scratch("dam_break_3d");
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_3d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  REQUIRE(run_scene(opt) == kExitDone);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "completed");
  CHECK(test::json_number(summary, "simulated_time") == doctest::Approx(test::json_number(summary, "end_time")));
  CHECK(std::abs(test::json_number(summary, "fluid_volume_relative_change")) < 0.01);  // as in 2D
  // The front has crossed the tank (4a = 1 m) by the end: the 3D flow is a dam break, not a
  // column standing still.
  auto probes = test::read_csv(out / "probes.csv");
  CHECK(probes["surge_front"].back() > 0.9);
}
