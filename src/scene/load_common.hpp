#pragma once
// What the scene loader's files share (loader.cpp, load_bodies.cpp, load_measurements.cpp,
// load_swe.cpp): numbers and formulas read from validated nodes, and the entries of [[section]]
// tables with their places for errors.
#include <toml++/toml.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.hpp"

namespace ryushi {

inline std::vector<double> vec_of(const toml::node& n) {
  std::vector<double> v;
  for (auto& e : *n.as_array()) v.push_back(*e.value<double>());
  return v;
}

// A number or formula entry (KeyType::FieldValue) as the text of a formula: numbers exactly
// (17 digits), so that a number and its formula give the same value.
inline std::string field_text(const toml::node& n) {
  if (n.is_string()) return *n.value<std::string>();
  std::ostringstream number;
  number.precision(17);
  number << *n.value<double>();
  return number.str();
}

// The bounding box of a disc or ball of `radius` about `centre`; on axis `along` (a 3D
// cylinder's; -1: none) the box spans [lo, hi] instead.
inline std::pair<std::vector<double>, std::vector<double>> round_box(const std::vector<double>& centre,
                                                                     double radius, int along,
                                                                     const std::vector<double>& lo,
                                                                     const std::vector<double>& hi) {
  std::vector<double> min = centre, max = centre;
  for (std::size_t a = 0; a < centre.size(); ++a) {
    min[a] = static_cast<int>(a) == along ? lo[a] : centre[a] - radius;
    max[a] = static_cast<int>(a) == along ? hi[a] : centre[a] + radius;
  }
  return {min, max};
}

// Applies one `section.key=value` or `section.N.key=value` override to the tree.

// "section.i.key": where an error in entry i of [[section]] points when the key came from --set.
inline std::string path_of(const char* sec, std::size_t i, const char* key) {
  return std::string(sec) + "." + std::to_string(i) + "." + key;
}

// The parsed scene (defaults inserted) as the loader reads it.
struct SceneEntries {
  toml::table& root;
  const Scene& sc;
  toml::node& get(const char* sec, const char* key) const { return *root[sec][key].node(); }
  const toml::node* where(const char* sec, std::size_t i, const char* key) const {
    return root[sec][i][key].node();
  }
  // Whether the box [lo, hi] lies in the domain.
  bool inside(const std::vector<double>& lo, const std::vector<double>& hi) const {
    for (int a = 0; a < sc.dimension; ++a)
      if (lo[a] < sc.domain_min[a] - 1e-12 || hi[a] > sc.domain_max[a] + 1e-12) return false;
    return true;
  }
};

}  // namespace ryushi
