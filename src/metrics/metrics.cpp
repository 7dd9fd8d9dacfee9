#include "metrics/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace ryushi {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// y(at) on the polyline (x, y), x increasing, clamped at the ends.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty()) return kNaN;
  if (at <= x.front()) return y.front();
  for (std::size_t k = 1; k < x.size(); ++k)
    if (x[k] >= at) return y[k - 1] + (y[k] - y[k - 1]) * (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y.back();
}

// The probe's column (time, value) from the rows; empty when the probe is unknown.
std::pair<std::vector<double>, std::vector<double>> probe_series(const Scene& s, const ProbeRows& rows,
                                                                 const std::string& name) {
  std::size_t column = 0;
  for (std::size_t k = 0; k < s.probes.size(); ++k)
    if (s.probes[k].name == name) column = k + 1;
  std::pair<std::vector<double>, std::vector<double>> out;
  if (!column) return out;
  for (auto& r : rows)
    if (r.size() > column) out.first.push_back(r[0]), out.second.push_back(r[column]);
  return out;
}

}  // namespace

std::vector<std::pair<double, double>> read_reference_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot open the reference table");
  std::vector<std::pair<double, double>> table;
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream ls(line);
    double a, b;
    if (!(ls >> a >> b)) {
      if (!header && table.empty()) {  // the header line
        header = true;
        continue;
      }
      throw SceneError(path + ":" + std::to_string(number) + ": expected two numbers, got '" + line + "'");
    }
    if (!std::isfinite(a) || !std::isfinite(b)) throw SceneError(path + ":" + std::to_string(number) + ": non-finite value");
    if (!table.empty() && a <= table.back().first)
      throw SceneError(path + ":" + std::to_string(number) + ": the first column must increase");
    table.push_back({a, b});
  }
  if (table.size() < 2) throw SceneError(path + ": fewer than two data lines");
  return table;
}

template <int D>
std::vector<std::pair<std::string, double>> evaluate_metrics(const Scene& s, const World<D>& world,
                                                             const ProbeRows& probes, double rho0, double g) {
  std::vector<std::pair<std::string, double>> out;
  for (auto& m : s.metrics) {
    if (m.type == "dam_break_front") {
      auto [t, x] = probe_series(s, probes, m.probe);
      const double a = m.width, t_scale = std::sqrt(a / (2 * g));
      std::vector<double> T, Z;
      for (std::size_t k = 0; k < t.size(); ++k) T.push_back(t[k] / t_scale), Z.push_back(x[k] / a);
      const double reached = T.empty() ? 0.0 : T.back();
      // The largest relative error over the reference points with T <= t_max that the run
      // reached (after the shift): a run stopped early is judged on what it computed.
      auto max_error = [&](double shift) {
        double worst = kNaN;
        for (auto& [Tr, Zr] : m.table)
          if (Tr <= m.t_max && Tr - shift <= reached && Tr - shift >= 0) {
            double e = std::abs(interpolate(T, Z, Tr - shift) / Zr - 1);
            worst = std::isnan(worst) ? e : std::max(worst, e);
          }
        return worst;
      };
      double best = max_error(0), shift = 0;
      const double unshifted = best;
      for (int k = 1; k <= int(std::lround(m.max_shift / 0.001)); ++k) {
        double e = max_error(0.001 * k);
        if (!std::isnan(e) && (std::isnan(best) || e < best)) best = e, shift = 0.001 * k;
      }
      out.push_back({m.name, best});
      out.push_back({m.name + "_shift", shift});
      out.push_back({m.name + "_unshifted", unshifted});
    } else if (m.type == "hydrostatic_pressure") {
      auto& x = world.column(components::position);
      auto& p = world.column(components::pressure);
      auto& kind = world.column(components::kind);
      double num = 0, den = 0;
      for (std::size_t i = 0; i < world.size(); ++i) {
        if (kind[i] != kFluid || x[i][D - 1] > m.surface) continue;
        const double ref = rho0 * g * (m.surface - x[i][D - 1]);
        num += (p[i] - ref) * (p[i] - ref);
        den += ref * ref;
      }
      out.push_back({m.name, den > 0 ? std::sqrt(num / den) : kNaN});
    } else {  // probe_csv
      auto [t, v] = probe_series(s, probes, m.probe);
      std::vector<double> rt, rv;
      for (auto& [a, b] : m.table) rt.push_back(a), rv.push_back(b);
      double num = 0, den = 0;
      for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k] < rt.front() || t[k] > rt.back()) continue;
        const double ref = interpolate(rt, rv, t[k]);
        num += (v[k] - ref) * (v[k] - ref);
        den += ref * ref;
      }
      out.push_back({m.name, den > 0 ? std::sqrt(num / den) : kNaN});
    }
  }
  return out;
}

template std::vector<std::pair<std::string, double>> evaluate_metrics<2>(const Scene&, const World<2>&,
                                                                         const ProbeRows&, double, double);
template std::vector<std::pair<std::string, double>> evaluate_metrics<3>(const Scene&, const World<3>&,
                                                                         const ProbeRows&, double, double);

}  // namespace ryushi
