#pragma once
// The dam-break criterion decided in the ISPH issue, for every method: the surge front Z = x/a
// against Martin & Moyce (1952, n^2 = 2; tools/reference/martin_moyce_1952_n2_2.csv) after ONE
// fitted time-origin shift dT in [0, 0.30] (the experiment's gate needs time to open; published
// SPH, MPS, BEM and level-set fronts lead it the same way), within 3% at the four data points
// T <= 2.547; the unshifted lead at most 20% (the same 0.30 at the data's front speed); and
// convergence: the fronts at a/d = 20 and 40 agree within 3% over T <= 2.5.
// Why 0.30 is a bound and not a fit to these runs (tests/README.md, audit row 7): the fitted
// shift converges with resolution below it, measured to a/d = 100 (ISPH 0.260 / 0.286 / 0.289 /
// 0.293 at a/d = 20 / 40 / 80 / 100, docs/validation.md): 0.30 is the experiment's delay
// (16 ms at a = 2.25 in) with the finest run's distance to it as the margin. A shift is
// the gate's, so it may not grow without bound; a run that needs more leads the data by
// more than the release can explain.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "test_util.hpp"

namespace ryushi::test {

struct FrontPoint {
  double T, Z;
};

// A table of tools/reference/ (default: the n^2 = 2 column's front). A missing file or one with
// no rows fails the test: an empty table would make every criterion below pass.
inline std::vector<FrontPoint> martin_moyce(const std::string& file = "martin_moyce_1952_n2_2.csv") {
  std::vector<FrontPoint> pts;
  std::ifstream in(source_dir() / "tools" / "reference" / file);
  REQUIRE_MESSAGE(in.good(), "cannot open tools/reference/" << file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'T') continue;
    auto comma = line.find(',');
    pts.push_back({std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1))});
  }
  REQUIRE_MESSAGE(!pts.empty(), "tools/reference/" << file << " has no data rows");
  return pts;
}

// y(at) on the polyline (x, y), x increasing.
inline double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  for (std::size_t k = 1; k < x.size(); ++k)
    if (x[k] >= at) return y[k - 1] + (y[k] - y[k - 1]) * (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y.back();
}

// The front of a run as (T, Z) from its probes.csv column surge_front.
struct Front {
  std::vector<double> T, Z;
};
inline Front front_of(const Csv& probes, double a, double t_scale) {
  Front f;
  for (std::size_t k = 0; k < probes["time"].size(); ++k) {
    f.T.push_back(probes["time"][k] / t_scale);
    f.Z.push_back(probes["surge_front"][k] / a);
  }
  return f;
}

struct FrontFit {
  double shift = 0, error = 0;  // the fitted dT and the largest relative error after it
  double unshifted_lead = 0;    // the largest relative error without a shift
  std::string unshifted;        // the errors without a shift, for the message
};

// The fit needs at least `min_points` reference points with T <= T_max (four for the default
// table: 0.832, 1.219, 1.997, 2.547; the runs end at T = 2.6 or later): with none, the error
// would be 0 and every criterion pass.
inline FrontFit fit_time_origin(const Front& f, double T_max = 2.6,
                                const std::vector<FrontPoint>& data = martin_moyce(),
                                std::size_t min_points = 4) {
  const auto used =
      std::count_if(data.begin(), data.end(), [&](const FrontPoint& p) { return p.T <= T_max; });
  REQUIRE_MESSAGE(std::size_t(used) >= min_points, used << " reference points with T <= " << T_max);
  auto max_error = [&](double shift) {
    double worst = 0;
    for (auto& p : data)
      if (p.T <= T_max) worst = std::max(worst, std::abs(interpolate(f.T, f.Z, p.T - shift) / p.Z - 1));
    return worst;
  };
  FrontFit fit{0, max_error(0), max_error(0), ""};
  for (int k = 1; k <= 300; ++k)  // dT in [0, 0.30] in steps of 0.001
    if (double e = max_error(0.001 * k); e < fit.error) fit = {0.001 * k, e, fit.unshifted_lead, ""};
  for (auto& p : data)
    if (p.T <= T_max) fit.unshifted += std::to_string(100 * (interpolate(f.T, f.Z, p.T) / p.Z - 1)) + "% ";
  return fit;
}

// The 3% after one fitted shift and the unshifted lead of at most 20%, at a/d = 20 (coarse) and
// 40 (fine), with the unshifted errors and the fit printed beside it.
inline void check_time_origin_criterion(const Front& coarse, const Front& fine) {
  for (auto* f : {&coarse, &fine}) {
    auto fit = fit_time_origin(*f);
    MESSAGE((f == &coarse ? "a/d = 20" : "a/d = 40"), ": unshifted front errors ", fit.unshifted,
            "| time-origin shift ", fit.shift, " -> max error ", 100 * fit.error, "%");
    CHECK(fit.error <= 0.03);
    CHECK(fit.unshifted_lead <= 0.20);
  }
}

// Largest relative difference of two fronts over T in [0, T_max] (sampled every 0.05).
inline double front_difference(const Front& coarse, const Front& fine, double T_max = 2.5) {
  double worst = 0;
  for (double T = 0.0; T <= T_max + 1e-9; T += 0.05)
    worst = std::max(worst, std::abs(interpolate(coarse.T, coarse.Z, T) / interpolate(fine.T, fine.Z, T) - 1));
  return worst;
}

}  // namespace ryushi::test
