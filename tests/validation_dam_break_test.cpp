// Acceptance 2 and 3 of the foundation issue: the 2D dam break (Martin & Moyce 1952, n^2 = 2)
// and the 3D dam break.
//
// Surge front: Martin & Moyce's data (a = 2.25 in column, their Fig. 3, digitised in
// tools/reference/martin_moyce_1952_n2_2.csv) lag converged simulations by a constant time
// offset: their time origin is the release of the gate, which takes a finite time to clear
// the column. Here the front of ryushi leads the unshifted data by 9-17% at every T <= 2.5
// and at every resolution tried (a/d = 20, 25, 50), and one constant shift of the time origin,
// Delta T ~= 0.2 (t ~= 0.023 s), brings every point within about 1%. The test therefore fits
// that one shift over [0, 0.3] and asserts (a) the shift is at most 0.25, and (b) with it,
// every data point up to T = 2.5 is matched within 5%. The unshifted errors are printed.
#include <doctest/doctest.h>

#include <cmath>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

struct Point {
  double T, Z;
};

std::vector<Point> martin_moyce() {
  std::vector<Point> pts;
  std::ifstream in(test::source_dir() / "tools" / "reference" / "martin_moyce_1952_n2_2.csv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'T') continue;
    auto comma = line.find(',');
    pts.push_back({std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1))});
  }
  return pts;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  for (std::size_t k = 1; k < x.size(); ++k)
    if (x[k] >= at) return y[k - 1] + (y[k] - y[k - 1]) * (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y.back();
}

}  // namespace

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
  CHECK(test::json_number(summary, "fluid_mass_relative_change") == 0.0);  // exactly

  auto probes = test::read_csv(out / "probes.csv");
  std::vector<double> T, Z;
  for (std::size_t k = 0; k < probes["time"].size(); ++k) {
    T.push_back(probes["time"][k] / t_scale);
    Z.push_back(probes["surge_front"][k] / a);
  }
  CHECK(Z.front() == doctest::Approx(1.0));
  // The front reaches the far wall (Z = 4) and stays there or beyond the impact.
  CHECK(Z.back() >= 3.9);

  auto data = martin_moyce();
  REQUIRE(data.size() >= 4);
  auto max_error = [&](double shift) {
    double worst = 0;
    for (auto& p : data)
      if (p.T <= 2.5 + 0.1) worst = std::max(worst, std::abs(interpolate(T, Z, p.T - shift) - p.Z) / p.Z);
    return worst;
  };
  double best_shift = 0, best = max_error(0);
  for (double s = 0.01; s <= 0.3001; s += 0.01)
    if (max_error(s) < best) best = max_error(s), best_shift = s;
  std::string unshifted;
  for (auto& p : data)
    if (p.T <= 2.6) unshifted += std::to_string(100 * (interpolate(T, Z, p.T) / p.Z - 1)) + "% ";
  MESSAGE("unshifted front errors: ", unshifted, "| time-origin shift ", best_shift, " -> max error ", 100 * best, "%");
  CHECK(best_shift <= 0.25);
  CHECK(best <= 0.05);
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
  CHECK(test::json_number(summary, "fluid_mass_relative_change") == 0.0);
  // The front has crossed the tank (4a = 1 m) by the end: the 3D flow is a dam break, not a
  // column standing still.
  auto probes = test::read_csv(out / "probes.csv");
  CHECK(probes["surge_front"].back() > 0.9);
}
