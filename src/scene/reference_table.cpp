#include "scene/reference_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "scene/scene.hpp"

namespace ryushi {

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

}  // namespace ryushi
