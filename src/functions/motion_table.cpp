#include "functions/motion_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "functions/csv_row.hpp"

namespace ryushi {

std::vector<MotionSample> read_motion_table(const std::string& path, int dimension) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::getline(in, line);  // the header
  std::vector<MotionSample> table;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (csv_blank(line)) continue;
    const std::string where = path + ":" + std::to_string(number) + ": ";
    std::vector<double> values;
    try {
      values = csv_numbers(line);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(where + e.what());
    }
    if (static_cast<int>(values.size()) != dimension + 1)
      throw std::runtime_error(where + std::to_string(values.size()) + " values; expected t and " +
                               std::to_string(dimension) + " displacements");
    if (!table.empty() && !(values[0] > table.back().t))
      throw std::runtime_error(where + "the times must increase");
    MotionSample s{values[0], {0, 0, 0}};
    for (int a = 0; a < dimension; ++a) s.displacement[a] = values[1 + a];
    table.push_back(s);
  }
  if (table.empty()) throw std::runtime_error(path + ": no row after the header");
  return table;
}

std::pair<std::array<double, 3>, std::array<double, 3>> sample_motion(const std::vector<MotionSample>& table,
                                                                      double t) {
  std::array<double, 3> x = table.front().displacement, v{0, 0, 0};
  if (t <= table.front().t) return {x, v};
  if (t >= table.back().t) return {table.back().displacement, v};
  auto next = std::upper_bound(table.begin(), table.end(), t,
                               [](double time, const MotionSample& s) { return time < s.t; });
  auto prev = next - 1;
  const double span = next->t - prev->t, w = (t - prev->t) / span;
  for (int a = 0; a < 3; ++a) {
    x[a] = prev->displacement[a] + w * (next->displacement[a] - prev->displacement[a]);
    v[a] = (next->displacement[a] - prev->displacement[a]) / span;
  }
  return {x, v};
}

std::array<double, 3> motion_acceleration(const std::vector<MotionSample>& table, double t) {
  std::array<double, 3> a{0, 0, 0};
  if (table.size() < 2) return a;
  // The interval that holds t (the first or last one beyond the table's ends).
  auto next = std::upper_bound(table.begin(), table.end(), t,
                               [](double time, const MotionSample& s) { return time < s.t; });
  next = std::clamp(next, table.begin() + 1, table.end() - 1);
  const double span = next->t - (next - 1)->t;
  const auto before = sample_motion(table, t - 0.5 * span).second,
             after = sample_motion(table, t + 0.5 * span).second;
  for (int k = 0; k < 3; ++k) a[k] = (after[k] - before[k]) / span;
  return a;
}

}  // namespace ryushi
