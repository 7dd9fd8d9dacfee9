// `--set section.key=value` (and section.table.key, section.N.key) applied to the parsed tree
// before validation; where each overridden key came from is kept for the error messages.
#include <sstream>

#include "scene/load_parts.hpp"
#include "scene/schema.hpp"
#include "scene/validator.hpp"

namespace ryushi {

void apply_override(toml::table& root, const std::string& text, Validator& val) {
  auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw SceneError("--set " + text + ": expected section.key=value");
  std::string path = text.substr(0, eq), value = text.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  std::string where = "--set " + text;
  const SectionSpec* section = parts.empty() ? nullptr : find_section(parts[0]);
  if (!section) {
    std::vector<std::string> names;
    for (auto& s : scene_schema()) names.push_back(s.name);
    std::string hint = parts.empty() ? "" : closest_name(parts[0], names);
    throw SceneError(where + ": unknown section '" + (parts.empty() ? "" : parts[0]) + "'" +
                     (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
  }
  toml::table* target = nullptr;
  std::string key, key_path;
  if (section->array_of_tables) {
    if (parts.size() != 3) throw SceneError(where + ": use " + parts[0] + ".N.key for [[" + parts[0] + "]]");
    auto* arr = root[parts[0]].as_array();
    std::size_t idx = 0;
    try {
      idx = std::stoul(parts[1]);
    } catch (...) {
      throw SceneError(where + ": '" + parts[1] + "' is not an index");
    }
    if (!arr || idx >= arr->size() || !(*arr)[idx].is_table())
      throw SceneError(where + ": the scene has no [[" + parts[0] + "]] entry " + parts[1]);
    target = (*arr)[idx].as_table();
    key = parts[2];
    key_path = parts[0] + "." + parts[1] + "." + key;
  } else {
    // section.key, or section.table.key for a table inside it ([method.isph] keys).
    if (parts.size() != 2 && parts.size() != 3) throw SceneError(where + ": use section.key");
    if (!root.contains(parts[0])) root.insert(parts[0], toml::table{});
    target = root[parts[0]].as_table();
    if (!target) throw SceneError(where + ": [" + parts[0] + "] is not a table in the scene");
    if (parts.size() == 3) {
      if (!target->contains(parts[1])) target->insert(parts[1], toml::table{});
      target = target->get_as<toml::table>(parts[1]);
      if (!target)
        throw SceneError(where + ": " + parts[0] + "." + parts[1] + " is not a table in the scene");
    }
    key = parts.back();
    key_path = path;
  }
  toml::table holder;
  try {
    holder = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    holder = toml::table{};
    holder.insert("v", value);  // a bare word is a string
  }
  target->insert_or_assign(key, *holder["v"].node());
  val.overridden[key_path] = where;
}

}  // namespace ryushi
