#pragma once
// The scene loader's validation state: the file, the parsed tree and where each overridden key
// came from; it checks tables against the schema and reports a problem once, as
// "file:line:column: message" (or the `--set` that gave the key). Shared by the loader's files.
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "functions/expression.hpp"
#include "scene/scene.hpp"
#include "scene/schema.hpp"

namespace ryushi {

// Validation state: the file, the parsed tree and where each overridden key came from.
class Validator {
 public:
  Validator(std::string path, toml::table& root) : path_(std::move(path)), root_(root) {}

  std::map<std::string, std::string> overridden;  // "section.key" -> "--set section.key=value"

  [[noreturn]] void fail(const toml::node* node, const std::string& where_path,
                         const std::string& msg) const {
    fail_at(node ? &node->source() : nullptr, where_path, msg);
  }
  [[noreturn]] void fail_at(const toml::source_region* src, const std::string& where_path,
                            const std::string& msg) const {
    throw SceneError(location_at(src, where_path) + ": " + msg);
  }
  // At key `key` of entry i of [[section]] (at the entry when the scene left the key out).
  [[noreturn]] void fail_entry(const toml::table& root, const std::string& section, std::size_t i,
                               const std::string& key, const std::string& msg) const {
    const toml::node* node = root[section][i][key].node();
    fail(node ? node : root[section][i].node(), section + "." + std::to_string(i) + "." + key, msg);
  }
  // "file:line:column" of a key, or the `--set` that gave it.
  std::string location(const toml::node* node, const std::string& where_path) const {
    return location_at(node ? &node->source() : nullptr, where_path);
  }
  std::string location_at(const toml::source_region* src, const std::string& where_path) const {
    auto o = overridden.find(where_path);
    if (o != overridden.end()) return o->second;
    std::ostringstream out;
    out << path_;
    if (src && src->begin) out << ":" << src->begin.line << ":" << src->begin.column;
    return out.str();
  }

  int dimension = 2;

  void check_table(toml::table& table, const std::string& label, const std::string& path_prefix,
                   const std::vector<KeySpec>& keys, const toml::node* table_node) {
    std::vector<std::string> names;
    for (auto& k : keys) names.push_back(k.key);
    for (auto& [k, node] : table) {
      std::string key(k.str());
      const KeySpec* spec = find_key(keys, key);
      if (!spec) {
        std::string hint = closest_name(key, names);
        fail_at(
            &k.source(), path_prefix + key,
            "unknown key '" + key + "' in " + label + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
      }
      check_value(node, *spec, label, path_prefix + key);
    }
    for (auto& k : keys) {
      if (table.contains(k.key)) continue;
      if (k.required)
        fail(table_node, path_prefix + k.key, label + " is missing required key '" + k.key + "'");
      if (!k.default_value.empty() && k.default_value.front() != '(') {
        auto parsed = toml::parse("v = " + k.default_value);
        table.insert(k.key, *parsed["v"].node());
      }
    }
  }

  void check_value(toml::node& node, const KeySpec& spec, const std::string& label, const std::string& path) {
    auto bad_type = [&] {
      fail(&node, path, "'" + spec.key + "' in " + label + " must be " + type_name(spec.type));
    };
    auto check_range = [&](double v) {
      if (!std::isfinite(v)) fail(&node, path, "'" + spec.key + "' in " + label + " must be finite");
      bool low = spec.min && (spec.min_exclusive ? v <= *spec.min : v < *spec.min);
      bool high = spec.max && (spec.max_exclusive ? v >= *spec.max : v > *spec.max);
      if (low || high) {
        std::ostringstream m;
        m << "'" << spec.key << "' in " << label << " is " << v << "; it must be";
        if (spec.min) m << (spec.min_exclusive ? " > " : " >= ") << *spec.min;
        if (spec.min && spec.max) m << " and";
        if (spec.max) m << (spec.max_exclusive ? " < " : " <= ") << *spec.max;
        fail(&node, path, m.str());
      }
    };
    auto per_axis_array = [&] {  // an array with one entry per axis
      auto* arr = node.as_array();
      if (!arr) bad_type();
      if (static_cast<int>(arr->size()) != dimension)
        fail(&node, path,
             "'" + spec.key + "' in " + label + " has " + std::to_string(arr->size()) +
                 " values; the scene is " + std::to_string(dimension) + "D");
      return arr;
    };
    switch (spec.type) {
      case KeyType::Integer:
        if (!node.is_integer()) bad_type();
        check_range(static_cast<double>(*node.value<long long>()));
        break;
      case KeyType::Float:
        if (!node.is_number()) bad_type();
        check_range(*node.value<double>());
        break;
      case KeyType::Bool:
        if (!node.is_boolean()) bad_type();
        break;
      case KeyType::String: {
        if (!node.is_string()) bad_type();
        std::string v = *node.value<std::string>();
        if (!spec.choices.empty() &&
            std::find(spec.choices.begin(), spec.choices.end(), v) == spec.choices.end()) {
          std::string list;
          for (auto& c : spec.choices) list += (list.empty() ? "" : ", ") + c;
          std::string hint = closest_name(v, spec.choices);
          fail(&node, path,
               "'" + spec.key + "' in " + label + " is '" + v + "'; allowed: " + list +
                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
        }
        break;
      }
      case KeyType::Vector:
      case KeyType::BoolVector: {
        auto* arr = per_axis_array();
        for (auto& e : *arr) {
          if (spec.type == KeyType::Vector) {
            if (!e.is_number()) bad_type();
            if (!std::isfinite(*e.value<double>()))
              fail(&e, path, "'" + spec.key + "' in " + label + " must be finite");
          } else if (!e.is_boolean()) {
            bad_type();
          }
        }
        break;
      }
      case KeyType::StringList: {
        auto* arr = node.as_array();
        if (!arr) bad_type();
        for (auto& e : *arr)
          if (!e.is_string()) bad_type();
        break;
      }
      case KeyType::FieldVector: {
        auto* arr = per_axis_array();
        for (std::size_t a = 0; a < arr->size(); ++a)
          check_field(arr->get(a), spec, label + ", axis " + std::to_string(a), path, bad_type);
        break;
      }
      case KeyType::FieldValue:
        check_field(&node, spec, label, path, bad_type);
        break;
    }
  }

  // A number (finite) or an expression that muparser compiles.
  template <class BadType>
  void check_field(toml::node* node, const KeySpec& spec, const std::string& label, const std::string& path,
                   BadType&& bad_type) {
    if (node->is_number()) {
      if (!std::isfinite(*node->value<double>()))
        fail(node, path, "'" + spec.key + "' in " + label + " must be finite");
      return;
    }
    if (!node->is_string()) bad_type();
    const std::string text = *node->value<std::string>();
    try {
      Expression{text};
    } catch (const ExpressionError& e) {
      fail(node, path, "'" + spec.key + "' in " + label + ": expression \"" + text + "\": " + e.what());
    }
  }

 private:
  std::string path_;
  toml::table& root_;
};

}  // namespace ryushi
