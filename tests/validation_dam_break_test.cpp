// Acceptance 2 and 3 of the foundation issue: the 2D dam break (Martin & Moyce 1952, n^2 = 2)
// and the 3D dam break.
//
// Surge front: the criterion of tests/front_criterion.hpp (one fitted time-origin shift in
// [0, 0.30], 3% after it for T <= 2.5, a/d = 20 and 40 within 3% of each other); the unshifted
// errors are printed beside it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "front_criterion.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;

TEST_CASE(
    "validation: 2D dam break surge front follows Martin and Moyce, runs past the impact, keeps its volume") {
  auto out = test::scratch("dam_break_2d");
  // To T = 3.8: the front reaches the far wall (Z = 4) at T = 3.15; the asserted window ends at 2.5.
  const double a = 0.25, g = 9.81, T_end = 3.8;
  const double t_scale = std::sqrt(a / (2 * g));  // t = T * sqrt(a / 2g)
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = T_end * t_scale;
  // The integrator named though it is the default: these runs are also the leapfrog's dam-break
  // criterion (tests/leapfrog_test.cpp runs only what they do not).
  opt.sets = {"particles.spacing=0.0125", "output.interval=0.05", "output.probe_interval=0.002",
              "method.integrator=leapfrog"};  // a / d = 20
  REQUIRE(run_scene(opt) == kExitDone);

  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "completed");
  CHECK(test::json_number(summary, "simulated_time") / t_scale >= 3.8 - 1e-6);
  // Mass is exact by construction; the volume sum m/rho and the density can drift. WCSPH's sound
  // speed (10 times the largest speed) keeps density variations near 1% (Mach^2): measured +0.2%
  // volume and 0.48% peak deviation through the impact at a/d = 20.
  CHECK(std::abs(test::json_number(summary, "fluid_volume_relative_change")) < 0.01);
  CHECK(test::json_number(summary, "max_density_deviation") < 0.02);
  // And over every step (audit row 43): the impact's water hammer compresses the particles at the
  // wall by about U / c0, a tenth with c0 = 10 U (Mach 0.1): bound 0.1; the volume within the 1%.
  const double hammer = test::json_number(summary, "run_max_density_deviation");
  const double volume = test::json_number(summary, "run_max_fluid_volume_change");
  MESSAGE("over the run: largest density deviation ", hammer,
          " at t = ", test::json_number(summary, "run_max_density_deviation_time"),
          " s, largest volume change ", volume);
  CHECK(hammer < 0.1);
  CHECK(std::abs(volume) < 0.01);

  auto coarse = test::front_of(test::read_csv(out / "probes.csv"), a, t_scale);
  CHECK(coarse.Z.front() == doctest::Approx(1.0));
  // The front reaches the far wall (Z = 4) and stays there or beyond the impact.
  CHECK(coarse.Z.back() >= 3.9);

  // a/d = 40 to T = 2.6 for the convergence check (the window ends at 2.5).
  auto fine_out = test::scratch("dam_break_2d_fine");
  opt.out_dir = fine_out.string();
  opt.end_time = 2.6 * t_scale;
  opt.sets = {"particles.spacing=0.00625", "output.interval=0.05", "output.probe_interval=0.002",
              "method.integrator=leapfrog"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto fine = test::front_of(test::read_csv(fine_out / "probes.csv"), a, t_scale);

  test::check_time_origin_criterion(coarse, fine);
  double difference = test::front_difference(coarse, fine);
  MESSAGE("a/d = 20 against 40 over T <= 2.5: ", 100 * difference, "%");
  CHECK(difference <= 0.03);
}

// WCSPH with ISPH's Fickian shifting ([shifting] model = "fickian"; issue 8): the same dam break at
// a/d = 20 to T = 2.6 keeps the front criterion (measured: shift 0.220, 1.75% after it; 0.202 and
// 1.24% without shifting) and keeps the particles apart: the closest pair at T = 2.6 is 0.70 d
// apart with shifting and 0.07 d without (particles pair up in WCSPH's tensile regions); the
// interior pressure noise, mean |p_i - mean of its neighbours|, falls from 189 to 106 Pa.
// Asserted: the criterion and no pair closer than half a spacing.
TEST_CASE("validation: WCSPH dam break with Fickian shifting keeps the front and the particles apart") {
  auto out = test::scratch("dam_break_2d_shifting");
  const double a = 0.25, g = 9.81, d = 0.0125;
  const double t_scale = std::sqrt(a / (2 * g));
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = 2.6 * t_scale;
  opt.sets = {"particles.spacing=0.0125", "output.interval=0.25", "output.probe_interval=0.002",
              "shifting.model=\"fickian\""};
  REQUIRE(run_scene(opt) == kExitDone);
  auto front = test::front_of(test::read_csv(out / "probes.csv"), a, t_scale);
  auto fit = test::fit_time_origin(front);
  MESSAGE("with shifting, a/d = 20: unshifted front errors ", fit.unshifted, "| time-origin shift ",
          fit.shift, " -> max error ", 100 * fit.error, "%");
  CHECK(fit.error <= 0.03);
  CHECK(fit.unshifted_lead <= 0.20);
  auto frame = test::last_frame(out);
  auto kind = test::read_dataset(frame, "kind").values, x = test::read_dataset(frame, "position").values;
  double closest = 1e9;
  for (std::size_t i = 0; i < kind.size(); ++i)
    for (std::size_t j = i + 1; j < kind.size(); ++j)
      if (kind[i] == 0 && kind[j] == 0)
        closest = std::min(closest, std::hypot(x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1]));
  MESSAGE("closest fluid pair at the last frame: ", closest / d, " d");
  CHECK(closest >= 0.5 * d);
}

// WCSPH with the Riemann dissipation (issue 57; docs/wcsph.md): the same dam break at a/d = 20 to
// T = 2.6 keeps the front criterion. Asserted as above.
TEST_CASE("validation: WCSPH dam break with the Riemann dissipation keeps the front criterion") {
  auto out = test::scratch("dam_break_2d_riemann");
  const double a = 0.25, g = 9.81;
  const double t_scale = std::sqrt(a / (2 * g));
  test::write_text(out / "dam_break.toml",
                   test::with_riemann_dissipation(test::read_text(test::scene_path("dam_break_2d.toml"))));
  RunOptions opt;
  opt.scene = (out / "dam_break.toml").string();
  opt.out_dir = (out / "run").string();
  opt.quiet = true;
  opt.end_time = 2.6 * t_scale;
  opt.sets = {"particles.spacing=0.0125", "output.interval=0.25", "output.probe_interval=0.002"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto front = test::front_of(test::read_csv(out / "run" / "probes.csv"), a, t_scale);
  auto fit = test::fit_time_origin(front);
  MESSAGE("riemann, a/d = 20: unshifted front errors ", fit.unshifted, "| time-origin shift ", fit.shift,
          " -> max error ", 100 * fit.error, "%");
  CHECK(fit.error <= 0.03);
  CHECK(fit.unshifted_lead <= 0.20);
}

// The 3D tank is one column wide (0.25 m) between two walls: the flow is the 2D one except in the
// walls' boundary layers, so at the same spacing (a/d = 10) the 3D front must follow the 2D front
// (measured 1.8% apart over T <= 2.6) and meet the same criterion (measured: shift 0.154, 1.19%
// after it, 10.7% before). To T = 3.5, past the impact on the far wall at T = 3.15, where a
// leaking wall would let particles through: every fluid particle must still be inside the tank.
TEST_CASE("validation: 3D dam break front meets the criterion, follows the 2D front and stays in its tank") {
  const double a = 0.25, g = 9.81, d = 0.025, T_end = 3.5;
  const double t_scale = std::sqrt(a / (2 * g));
  auto out = test::scratch("dam_break_3d");
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_3d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = T_end * t_scale;
  opt.sets = {"output.interval=" + std::to_string(T_end * t_scale), "output.probe_interval=0.002"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "completed");
  // Volume as in 2D (measured +0.08%). The density just after the impact on the far wall: the
  // sound speed c0 = 10 u_max puts a stagnation pressure rho u^2 at (u/c0)^2 = 1% and the water
  // hammer rho c0 u of a full stop at u/c0 = 10%; measured 2.38% at T = 3.5 (a/d = 10, at the wall).
  CHECK(std::abs(test::json_number(summary, "fluid_volume_relative_change")) < 0.01);
  CHECK(test::json_number(summary, "max_density_deviation") < 0.03);

  auto front3 = test::front_of(test::read_csv(out / "probes.csv"), a, t_scale);
  auto fit = test::fit_time_origin(front3);
  MESSAGE("3D, a/d = 10: unshifted front errors ", fit.unshifted, "| time-origin shift ", fit.shift,
          " -> max error ", 100 * fit.error, "%");
  CHECK(fit.error <= 0.03);
  CHECK(fit.unshifted_lead <= 0.20);

  auto out2 = test::scratch("dam_break_3d_as_2d");
  RunOptions two = opt;
  two.scene = test::scene_path("dam_break_2d.toml");
  two.out_dir = out2.string();
  two.sets.push_back("particles.spacing=" + std::to_string(d));
  REQUIRE(run_scene(two) == kExitDone);
  auto front2 = test::front_of(test::read_csv(out2 / "probes.csv"), a, t_scale);
  const double difference = test::front_difference(front3, front2);
  MESSAGE("3D against 2D at a/d = 10 over T <= 2.5: ", 100 * difference, "%");
  CHECK(difference <= 0.03);

  // No wall leak: no fluid particle centre in the last frame lies past the first wall layer (d/2
  // behind the wall faces of the tank [0, 1] x [0, 0.25] x [0, ..)). In the impact particles are
  // pressed against the faces: measured up to 0.25 d past the side faces, 0.02 d past the far wall.
  auto inside = test::fluid_containment(test::last_frame(out), {0, 0, 0}, {1.0, 0.25, 0}, d / 2);
  CHECK(inside.fluid == 2000);
  CHECK(inside.outside == 0);
  CHECK(front3.Z.back() >= 3.9);  // the front reached the far wall
}

// The square column (Martin & Moyce 1952, n^2 = 1; tools/reference/martin_moyce_1952_square_height.csv,
// digitised from Xie 2021, +-0.05 in T): the time the water at the back wall takes to fall to
// each of their marks H = h/a = 8/9 .. 5/9, against theirs, for the three methods at a/d = 20
// (each its own dam-break scene with the square column in a 15a tank). These marks are passed
// before T = t sqrt(g/a) = 2.2, while the column drains as a body: every method within 0.15 of
// the experiment there (three times the digitisation's uncertainty, and the gate's opening, up to
// 0.21 in these units by the n^2 = 2 criterion, is not fitted). Measured here, at a/d = 20, the
// largest differences: WCSPH 0.017, MPS 0.081 (early at the first mark), ISPH 0.112 (early at the
// last), so the worst, ISPH, is 0.038 inside the bound (issue 50, audit row 28: this comment
// quoted a/d = 40 figures, WCSPH 0.03, MPS 0.12, ISPH 0.12). Later marks (H = 4/9 .. 1/9) and the
// front (the data start at Z = 6, a sheet a tenth of a thick) are reported, not asserted:
// docs/validation.md, "The square column".
TEST_CASE(
    "validation: the square column drains at the back wall as Martin and Moyce measured, every method") {
  const double a = 0.25, g = 9.81;
  const double t_scale = std::sqrt(a / g);  // T = t sqrt(g/a) for n^2 = 1
  std::vector<test::FrontPoint> marks;      // (T, H) of the experiment
  for (auto& p : test::martin_moyce("martin_moyce_1952_square_height.csv"))
    if (p.T > 0 && p.Z >= 5.0 / 9 - 1e-3) marks.push_back(p);
  REQUIRE(marks.size() == 4);
  for (std::string scene : {"dam_break_2d.toml", "dam_break_mps_2d.toml", "dam_break_isph_2d.toml"}) {
    auto out = test::scratch("square_column_" + scene.substr(0, scene.size() - 5));
    RunOptions opt;
    opt.scene = test::scene_path(scene);
    opt.out_dir = out.string();
    opt.quiet = true;
    opt.end_time = 2.6 * t_scale;
    opt.sets = {"particles.spacing=0.0125", "fluid.0.max=[0.25, 0.25]", "wall.0.max=[3.75, 1.0]",
                "domain.max=[3.85, 3.0]",   "output.interval=0.1",      "output.probe_interval=0.002"};
    REQUIRE(run_scene(opt) == kExitDone);
    auto probes = test::read_csv(out / "probes.csv");
    const auto& t = probes["time"];
    const auto& h = probes["height_left_wall"];
    std::string report;
    double worst = 0;
    for (auto& m : marks) {
      // The first time the height falls to the mark (linear between samples).
      double crossed = NAN;
      for (std::size_t k = 1; k < t.size() && std::isnan(crossed); ++k)
        if (h[k] / a <= m.Z)
          crossed = (t[k - 1] + (t[k] - t[k - 1]) * (h[k - 1] / a - m.Z) / ((h[k - 1] - h[k]) / a)) / t_scale;
      REQUIRE_MESSAGE(!std::isnan(crossed),
                      scene << ": the water at the back wall never fell to H = " << m.Z);
      report += "H = " + std::to_string(m.Z) + " at T = " + std::to_string(crossed) + " (" +
                std::to_string(m.T) + "); ";
      worst = std::max(worst, std::abs(crossed - m.T));
    }
    MESSAGE(scene, ": ", report, "largest difference ", worst);
    CHECK(worst <= 0.15);
  }
}
