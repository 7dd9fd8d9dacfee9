#pragma once
// The scene-file schema: every section and key with its type, unit, default, range and doc.
// One table drives validation, defaults and docs/scenes.md (`ryushi keys --markdown`), so the
// documentation cannot drift from what the loader accepts.
#include <optional>
#include <string>
#include <vector>

namespace ryushi {

// FieldVector / FieldValue: numbers or expressions of x, y, z (functions/expression.hpp).
enum class KeyType { Integer, Float, Bool, String, Vector, BoolVector, StringList, FieldVector, FieldValue };

struct KeySpec {
  std::string key;
  KeyType type;
  std::string unit;
  // TOML literal inserted when the key is absent ("" = no default). A text in parentheses is
  // descriptive only: the loader computes that default.
  std::string default_value;
  std::string doc;
  bool required = false;
  std::optional<double> min{};
  std::optional<double> max{};
  bool min_exclusive = false;
  bool max_exclusive = false;
  std::vector<std::string> choices{};
};

struct SectionSpec {
  std::string name;
  bool array_of_tables;
  bool required;
  std::string doc;
  std::vector<KeySpec> keys;
};

// Shorthands for key tables (the schema's, and those that methods and systems register).
namespace keyspec {
inline KeySpec positive(std::string key, std::string unit, std::string def, std::string doc,
                        bool required = false) {
  KeySpec k{std::move(key), KeyType::Float, std::move(unit), std::move(def), std::move(doc), required};
  k.min = 0.0;
  k.min_exclusive = true;
  return k;
}
inline KeySpec non_negative(std::string key, std::string unit, std::string def, std::string doc) {
  KeySpec k{std::move(key), KeyType::Float, std::move(unit), std::move(def), std::move(doc)};
  k.min = 0.0;
  return k;
}
inline KeySpec ranged(KeySpec k, std::optional<double> lo, std::optional<double> hi) {
  k.min = lo;
  k.max = hi;
  return k;
}
inline KeySpec choice(std::string key, std::string def, std::string doc, std::vector<std::string> choices,
                      bool required = false) {
  KeySpec k{std::move(key), KeyType::String, "", std::move(def), std::move(doc), required};
  k.choices = std::move(choices);
  return k;
}
}  // namespace keyspec

const std::vector<SectionSpec>& scene_schema();
// The [[probe]] section (scene/schema_probe.cpp), part of scene_schema().
SectionSpec probe_section();
const SectionSpec* find_section(const std::string& name);
const KeySpec* find_key(const std::vector<KeySpec>& keys, const std::string& key);
std::string type_name(KeyType t);
// Closest candidate by edit distance, or "" if none is reasonably close.
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates);
// Markdown reference of every section and key (docs/scenes.md), including registered systems.
std::string schema_markdown();
// The same keys one per line with the first sentence of each, for a terminal (`ryushi keys`).
std::string schema_text();

}  // namespace ryushi
