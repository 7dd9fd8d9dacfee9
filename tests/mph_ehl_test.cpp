// The soft-EHL line contact under MPH-I (systems/mph/elastic_line_contact.hpp, issue 55
// acceptance 4, docs/mph.md): scenes/ehl_soft_mph_2d.toml, the soft-EHL paper's case scaled so that
// its elasticity parameter g_E = 5.56 stays (E / 100, mu x 100), run to a steady film and compared
// with the Reynolds-equation solution of the same contact (tools/ehl_reynolds.py, same elastic
// deformation, Reynolds outlet, p = 0 at the inlet meniscus): tools/reference/
// ehl_soft_scaled_reynolds.csv holds that solution's central and minimum film for inlets from
// -1.5 b to -4 b, interpolated at the meniscus the run ends with.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

struct Film {
  std::vector<double> x, p, h;  // per surface column, ascending x
  double inlet = 0;             // the meniscus: the upstream end of the filled film through the centre
};

// Columns from the surface particles (film_* are per column, the same on each layer); a column
// is filled where a fluid particle lies within 2 spacings of the face (tools/ehl_compare.py's rule).
Film read_film(const std::filesystem::path& frame, double spacing) {
  const auto slot = test::read_dataset(frame, "contact_slot").values;
  const auto fx = test::read_dataset(frame, "film_position").values;
  const auto fp = test::read_dataset(frame, "film_pressure").values;
  const auto fh = test::read_dataset(frame, "film_thickness").values;
  const auto kind = test::read_dataset(frame, "kind").values;
  const auto position = test::read_dataset(frame, "position");
  const auto& pos = position.values;
  const std::size_t stride = position.dims.size() > 1 ? position.dims[1] : 1;  // 3: frames store x, y, z
  std::map<double, std::pair<double, double>> columns;
  for (std::size_t i = 0; i < slot.size(); ++i)
    if (slot[i] > 0) columns.emplace(fx[i], std::pair{fp[i], fh[i]});
  Film f;
  for (auto& [x, ph] : columns) f.x.push_back(x), f.p.push_back(ph.first), f.h.push_back(ph.second);
  std::vector<double> top(f.x.size(), -1e300);
  for (std::size_t i = 0; i < kind.size(); ++i) {
    if (kind[i] != 0) continue;
    const long c = std::lround((pos[stride * i] - f.x.front()) / spacing);
    if (c >= 0 && c < static_cast<long>(top.size())) top[c] = std::max(top[c], pos[stride * i + 1]);
  }
  auto filled = [&](std::size_t c) { return f.h[c] - top[c] < 2 * spacing; };  // the plate's face is y = 0
  std::size_t c =
      std::min_element(f.x.begin(), f.x.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) -
      f.x.begin();
  REQUIRE(filled(c));
  for (std::size_t k = c, breaks = 0; k-- > 0 && breaks <= 3;)  // upstream, across breaks of up to 3 columns
    if (filled(k))
      c = k, breaks = 0;
    else
      ++breaks;
  f.inlet = f.x[c] - 0.5 * spacing;
  return f;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  REQUIRE(at >= x.front());
  REQUIRE(at <= x.back());
  const std::size_t k = std::upper_bound(x.begin(), x.end(), at) - x.begin();
  if (k >= x.size()) return y.back();
  const double t = (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + t * (y[k] - y[k - 1]);
}

}  // namespace

TEST_CASE("mph: a soft-EHL line contact settles on the Reynolds solution of the same contact (scaled g_E)") {
  auto dir = test::scratch("mph_ehl");
  RunOptions opt;
  opt.scene = test::scene_path("ehl_soft_mph_2d.toml");
  opt.out_dir = (dir / "out").string();
  opt.overwrite = true;
  opt.quiet = true;
  REQUIRE(run_scene(opt) == kExitDone);
  const double l = 4e-4, R = 0.1, E = 1.95e5, W = 1000, mu = 8.31, U = 0.4;
  const double b = std::sqrt(4 * W * R / (std::numbers::pi * E));
  // The settled film: the frames from t = 0.5 s on (every 0.05 s to 0.8 s), averaged, since the
  // particles' pressure still moves the load by about 1% from frame to frame.
  double load = 0, inlet = 0, h_central = 0, h_min = 0;
  int frames = 0;
  for (int k = 10; k <= 16; ++k, ++frames) {
    const Film f = read_film(test::frame_path(dir / "out", k), l);
    double carried = 0, lowest = 1e300;
    for (double p : f.p) carried += p * l;
    for (std::size_t c = 0; c < f.x.size(); ++c)
      if (f.x[c] > f.inlet && f.x[c] < 2 * b) lowest = std::min(lowest, f.h[c]);
    load += carried, inlet += f.inlet, h_central += interpolate(f.x, f.h, 0.0), h_min += lowest;
  }
  load /= frames, inlet /= frames, h_central /= frames, h_min /= frames;
  // The load balance (eq. 2) on the surface's pressure: int p dx = W.
  CHECK(std::abs(load / W - 1) < 0.005);
  // The films against the reference at the same inlet (p = 0 at the meniscus; the run's own
  // pressure there, about 200 Pa, moves the reference's films by 1%); the pool must not have
  // drained below what the table covers.
  const auto ref =
      test::read_csv(test::source_dir() / "tools" / "reference" / "ehl_soft_scaled_reynolds.csv");
  auto ascending = [&](const std::string& name) {
    auto& c = ref.columns.at(name);
    return std::vector<double>(c.rbegin(), c.rend());
  };
  const auto in = ascending("inlet_b"), central = ascending("central_film_m"),
             minimum = ascending("minimum_film_m");
  const double inlet_b = inlet / b;
  CHECK(inlet_b < -2.0);
  const double ref_central = interpolate(in, central, inlet_b), ref_min = interpolate(in, minimum, inlet_b);
  MESSAGE("inlet ", inlet_b, " b; load ", load, " N/m; central film ", h_central * 1e6, " um (reference ",
          ref_central * 1e6, "), minimum ", h_min * 1e6, " um (reference ", ref_min * 1e6, ")");
  CHECK(std::abs(h_min / ref_min - 1) < 0.05);
  CHECK(std::abs(h_central / ref_central - 1) < 0.05);
  // Herrebrugh's isoviscous-elastic regime (Johnson, Contact Mechanics, 13.5): h_min = 3.01
  // g_E^0.8 eta u_e R / W with u_e = U / 2, g_E = (W^2 / (eta u_e E R))^(1/2) = 5.56: 1.972 mm.
  const double u_e = U / 2, g_E = std::sqrt(W * W / (mu * u_e * E * R));
  const double herrebrugh = 3.01 * std::pow(g_E, 0.8) * mu * u_e * R / W;
  CHECK(std::abs(h_min / herrebrugh - 1) < 0.20);
}
