// The dam break of Lobovsky et al. (2014), H = 300 mm, onto a wall with pressure sensors
// (scenes/dam_break_lobovsky_2d.toml, issue 57; docs/validation.md, "Impact pressure"), coarse:
// H / d = 20, every method in its scene table, and WCSPH with the Riemann dissipation. What holds
// is asserted; the first impact's peak, which only WCSPH with the Riemann dissipation gets near the
// experiment's band, is a known failure for the others.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

// tools/reference/lobovsky_2014_h300_peaks.csv: the first peak's 2.5% and 97.5% by sensor
// height (mm), in mbar.
std::map<int, std::pair<double, double>> experiment_peak_bands() {
  std::ifstream in(test::source_dir() / "tools" / "reference" / "lobovsky_2014_h300_peaks.csv");
  REQUIRE(in.good());
  std::map<int, std::pair<double, double>> bands;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    double z, median, lo, hi;
    row >> z >> median >> lo >> hi;
    bands[static_cast<int>(z)] = {lo, hi};
  }
  return bands;
}

}  // namespace

// Measured at H / d = 20 (2026-11-29): the first peak at the 15 mm sensor 9.5 (WCSPH), 16.1
// (ISPH), 4.6 (MPS) rho g H against the experiment's 1.82-2.16; at H / d = 40 17.5, 3.4, 3.6 and
// at 80 (docs/validation.md). WCSPH's is the acoustic compression of the one-particle tongue
// against the wall (rho c0 U) after the artificial viscosity has slowed and thickened it, ISPH's
// and MPS's the projection stopping a particle within a step. WCSPH with the Riemann dissipation
// (its limiter damps the impact, not the tongue's shear): 2.51 at 15 mm and 1.53 at 30 mm (bands
// 1.82-2.16 and 1.36-1.69), asserted within 25% of the band at this resolution: the experiment's
// own runs spread by +-9% about their median, and one run's first peak moves by round-off.
TEST_CASE(
    "impact: Lobovsky's dam break, sensors dry until the water arrives, ordered by height in the run-up "
    "(the first peak: WCSPH's Riemann dissipation near the experiment's band, the others known to "
    "overshoot)") {
  const auto bands = experiment_peak_bands();
  REQUIRE(bands.size() == 4);
  const double H = 0.3, g = 9.81, rho_g_H = 997 * g * H, T = std::sqrt(H / g), d = 0.015;
  for (std::string label : {"wcsph", "wcsph_riemann", "isph", "mps"}) {
    CAPTURE(label);
    const bool riemann = label == "wcsph_riemann";
    const std::string method = riemann ? "wcsph" : label;
    auto dir = test::unique_scratch("lobovsky_" + label);
    RunOptions opt;
    opt.scene = test::scene_path("dam_break_lobovsky_2d.toml");
    opt.out_dir = dir.string();
    opt.quiet = true;
    opt.sets = {"particles.spacing=" + std::to_string(d), "method.name=\"" + method + "\"",
                "output.probe_interval=2.5e-4", "time.end=0.97"};  // t* = 5.5, before the run-up returns
    if (method == "isph") opt.sets.push_back("shifting.model=\"fickian\"");
    if (riemann) opt.sets.push_back("method.wcsph.dissipation=\"riemann\"");
    REQUIRE(run_scene(opt) == kExitDone);
    auto probes = test::read_csv(dir / "probes.csv");
    const auto& t = probes["time"];
    const auto& front = probes["surge_front"];
    std::map<std::string, double> median_run_up;
    for (auto [name, z] : {std::pair{"sensor_1", 3}, {"sensor_2", 15}, {"sensor_3", 30}, {"sensor_4", 80}}) {
      CAPTURE(name);
      const auto& p = probes[name];
      // No pressure before the water: every sample zero while the front is more than two
      // spacings and a sensor support (2 d) from the wall.
      std::size_t arrival = t.size();
      for (std::size_t k = 0; k < t.size(); ++k) {
        if (front[k] < 1.61 - 4 * d) CHECK(p[k] == 0.0);
        if (arrival == t.size() && p[k] > 0.2 * rho_g_H) arrival = k;
      }
      REQUIRE(arrival < t.size());
      std::vector<double> run_up;
      double peak = 0;
      for (std::size_t k = arrival; k < t.size(); ++k) {
        if (t[k] <= t[arrival] + 0.5 * T) peak = std::max(peak, p[k] / rho_g_H);
        if (t[k] >= 3.0 * T && t[k] <= 5.5 * T) run_up.push_back(p[k]);
      }
      std::nth_element(run_up.begin(), run_up.begin() + run_up.size() / 2, run_up.end());
      median_run_up[name] = run_up[run_up.size() / 2];
      const double top = bands.at(z).second / (rho_g_H / 100),  // mbar -> rho g H
          bottom = bands.at(z).first / (rho_g_H / 100);
      MESSAGE(label, " ", std::string(name), ": arrival t* ", t[arrival] / T, ", first peak ", peak,
              " rho g H (experiment up to ", top, "), run-up median ", median_run_up[name] / rho_g_H);
      // The known failure (issue 57): the first peak at the 15 mm sensor more than 1.5 times the
      // experiment's 97.5%. When this fails, the field is right: make it the band.
      if (riemann && (z == 15 || z == 30)) {
        CHECK(peak > 0.75 * bottom);
        CHECK(peak < 1.25 * top);
      } else if (z == 15) {
        CHECK(peak > 1.5 * top);
      }
    }
    // The run-up is a layer of water standing on the wall's foot: its pressure falls with height.
    CHECK(median_run_up["sensor_1"] > median_run_up["sensor_3"]);
    CHECK(median_run_up["sensor_3"] > median_run_up["sensor_4"]);
    CHECK(median_run_up["sensor_4"] > 0);
  }
}
