// Acceptance 1 of the foundation issue: a tank of water at rest (seed 002 section 5.1).
// After settling, the probe pressures at depths 0.1 ... 0.45 m, and the wall sensors' (issue 57:
// a tank at rest, every sensor within 1% of rho g depth), must be within 1% of rho g depth
// (the paper reports 3.7% at its deepest probe) and the fluid must be at rest:
// max speed < 1e-3 sqrt(g H).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;

TEST_CASE("validation: hydrostatic tank settles to rho g depth within 1 percent") {
  auto out = test::scratch("hydrostatic");
  RunOptions opt;
  opt.scene = test::scene_path("hydrostatic_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.sets = {"particles.spacing=0.025"};  // coarse: H / d = 20 (the scene file uses 40)
  REQUIRE(run_scene(opt) == kExitDone);

  const double rho = 1000, g = 9.81, H = 0.5, surface = 0.5;
  auto probes = test::read_csv(out / "probes.csv");
  auto& time = probes["time"];
  REQUIRE(time.back() == doctest::Approx(2.0));
  const std::vector<std::pair<std::string, double>> depths{{"p_depth_0.10", 0.10},
                                                           {"p_depth_0.20", 0.20},
                                                           {"p_depth_0.30", 0.30},
                                                           {"p_depth_0.40", 0.40},
                                                           {"p_depth_0.45", 0.45},
                                                           // the wall sensors (probes.hpp)
                                                           {"sensor_left_0.40", 0.40},
                                                           {"sensor_right_0.25", 0.25},
                                                           {"sensor_floor_0.50", 0.50}};
  // Every sample in the last quarter of the run, not just the final one: settled means staying put.
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] < 1.5) continue;
    for (auto& [name, depth] : depths) {
      double exact = rho * g * depth;
      double err = std::abs(probes[name][k] - exact) / exact;
      CHECK_MESSAGE(err < 0.01,
                    name << " at t = " << time[k] << ": " << probes[name][k] << " Pa vs " << exact);
    }
  }
  // The free surface stays where it started (within a tenth of a particle spacing).
  CHECK(std::abs(probes["surface"].back() - surface) < 0.1 * 0.025);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_number(summary, "max_speed") < 1e-3 * std::sqrt(g * H));
  // Mass is a constant column (exact by construction); what can drift is the volume sum m/rho
  // and the density. At rest nothing should compress further than the hydrostatic start:
  // measured -1.2e-5 volume change and 0.49% peak density deviation (rho g H / (rho c0^2) with
  // c0 = 10 sqrt(2 g H) gives 0.5%); bounds 1e-3 and 1% (WCSPH's c0 keeps density within 1%).
  CHECK(std::abs(test::json_number(summary, "fluid_volume_relative_change")) < 1e-3);
  CHECK(test::json_number(summary, "max_density_deviation") < 0.01);
  MESSAGE(
      "final probe errors: ",
      [&] {
        std::string s;
        for (auto& [name, depth] : depths)
          s += name + " " + std::to_string(100 * (probes[name].back() / (rho * g * depth) - 1)) + "% ";
        return s;
      }(),
      " max speed ", test::json_number(summary, "max_speed"));
}

// The same tank with the Riemann dissipation (issue 57; Zhang, Hu & Adams 2017): no artificial
// viscosity, whose A = B = 1 above damps the start-up's acoustic waves within a few periods. The
// limiter damps a pair as the square of its approach speed, so the waves of the hydrostatic start
// ring longer: at H / d = 20 the probes' rms departure falls from 3.0-4.3% over t = 0.1-0.5 s to
// 0.75-0.89% over 1.5-2 s, while their mean over 1.5-2 s stays within 0.55% of rho g depth
// (measured 2026-11-29; the same +0.4-0.5% at depth as the artificial viscosity's). Asserted:
// the mean within 1%, the late rms below 1.5% and below 0.4 times the early one (it decays).
TEST_CASE(
    "validation: the tank at rest with the Riemann dissipation: mean pressure rho g depth, the start-up "
    "waves decay") {
  auto out = test::scratch("hydrostatic_riemann");
  const std::string scene =
      test::with_riemann_dissipation(test::read_text(test::scene_path("hydrostatic_2d.toml")));
  test::write_text(out / "tank.toml", scene);
  RunOptions opt;
  opt.scene = (out / "tank.toml").string();
  opt.out_dir = (out / "run").string();
  opt.quiet = true;
  opt.sets = {"particles.spacing=0.025"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto probes = test::read_csv(out / "run" / "probes.csv");
  const auto& time = probes["time"];
  for (auto [name, depth] : {std::pair{"p_depth_0.10", 0.10},
                             {"p_depth_0.45", 0.45},
                             {"sensor_left_0.40", 0.40},
                             {"sensor_right_0.25", 0.25},
                             {"sensor_floor_0.50", 0.50}}) {
    const std::string probe = name;  // CAPTURE of a const char* prints the pointer
    CAPTURE(probe);
    double mean = 0, late = 0, early = 0;
    int n_late = 0, n_early = 0;
    for (std::size_t k = 0; k < time.size(); ++k) {
      const double e = probes[name][k] / (1000 * 9.81 * depth) - 1;
      if (time[k] >= 1.5) mean += e, late += e * e, ++n_late;
      if (time[k] >= 0.1 && time[k] <= 0.5) early += e * e, ++n_early;
    }
    REQUIRE(n_late > 10);
    REQUIRE(n_early > 10);
    mean /= n_late, late = std::sqrt(late / n_late), early = std::sqrt(early / n_early);
    MESSAGE("mean ", mean, ", rms over 1.5-2 s ", late, ", over 0.1-0.5 s ", early);
    CHECK(std::abs(mean) < 0.01);
    CHECK(late < 0.015);
    CHECK(late < 0.4 * early);
  }
  CHECK(test::json_number(test::read_text(out / "run" / "summary.json"), "max_density_deviation") < 0.01);
}

// Tait's equation of state (seed 002 eq. 3), p = B ((rho / rho0)^7 - 1), B = rho0 c0^2 / 7,
// particle by particle on the tank's first frame, where the hydrostatic start sets each density
// from rho0 g depth through its inverse. A change of the exponent (7 -> 6, the mutation check of
// issue 50) passed every other test: at the bottom of this tank p / B is 0.07, and the density
// of exponent 6 read through exponent 7 gives a pressure 17% off.
TEST_CASE("validation: the tank's first frame follows Tait's equation of state, exponent 7") {
  auto out = test::scratch("tait");
  RunOptions opt;
  opt.scene = test::scene_path("hydrostatic_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.sets = {"particles.spacing=0.025", "time.max_steps=1"};
  REQUIRE(run_scene(opt) == kExitDone);
  const double rho0 = 1000, c0 = test::json_number(test::read_text(out / "summary.json"), "sound_speed");
  const double B = rho0 * c0 * c0 / 7;
  const auto frame = out / "frames" / "frame_00000.h5";
  auto kind = test::read_dataset(frame, "kind").values, rho = test::read_dataset(frame, "density").values,
       p = test::read_dataset(frame, "pressure").values;
  double worst = 0, deepest = 0;
  for (std::size_t i = 0; i < kind.size(); ++i) {
    if (kind[i] != 0) continue;
    worst = std::max(worst, std::abs(p[i] - B * (std::pow(rho[i] / rho0, 7) - 1)));
    deepest = std::max(deepest, p[i]);
  }
  CHECK_MESSAGE(worst < 1e-9 * B,
                "largest departure from Tait's equation " << worst << " Pa (B = " << B << " Pa)");
  // Not vacuous: the bottom particles are compressed, p near rho0 g H = 4.9 kPa (the first row
  // half a spacing above the floor).
  CHECK(deepest > 0.9 * rho0 * 9.81 * 0.5);
}
