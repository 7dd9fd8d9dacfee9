#pragma once
// Small file helpers of the driver: a whole file as text (the scene a checkpoint keeps) and
// probes.csv from the probe rows.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace ryushi {

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string probes_csv(const std::vector<ProbeSpec>& probes,
                              const std::vector<std::vector<double>>& rows) {
  std::ostringstream out;
  out.precision(10);
  out << "time";
  for (auto& p : probes) out << "," << p.name;
  out << "\n";
  for (auto& r : rows) {
    for (std::size_t k = 0; k < r.size(); ++k) out << (k ? "," : "") << r[k];
    out << "\n";
  }
  return out.str();
}

}  // namespace ryushi
