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
