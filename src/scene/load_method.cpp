#include "scene/load_method.hpp"

#include <set>
#include <string>
#include <vector>

#include "scene/registered_keys.hpp"
#include "scene/scene.hpp"
#include "scene/schema.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::vector<std::string> key_names(const MethodSpec& spec) {
  std::vector<std::string> names;
  for (auto& k : spec.keys) names.push_back(k.key);
  return names;
}

// A key that `method` does not declare: name its owners, or suggest the closest of its own.
[[noreturn]] void foreign_key(const Validator& val, const toml::key& key, const std::string& path,
                              const std::string& label, const std::string& method, const MethodSpec& spec) {
  const std::string k(key.str());
  if (auto it = spec.retired.find(k); it != spec.retired.end())
    val.fail_at(&key.source(), path,
                label + " " + k + " was removed from method " + method + ": " + it->second);
  const auto owners = methods_owning_key(k);
  const auto own = key_names(spec);
  const std::string own_list = own.empty() ? "none besides name" : joined(own);
  if (!owners.empty())
    val.fail_at(&key.source(), path,
                label + " " + k + " is for method " + joined(owners) + ", not for " + method +
                    (label == "[method]" ? " (the scene's method, which would ignore it)" : "") + "; " +
                    method + "'s keys: " + own_list + " (settings for another method go in [method." +
                    owners.front() + "])");
  std::string hint = closest_name(k, own);
  val.fail_at(&key.source(), path,
              "unknown key '" + k + "' in " + label + (hint.empty() ? "" : "; did you mean '" + hint + "'?") +
                  " (" + method + "'s keys: " + own_list + ")");
}

// Checks each key of `table` against `spec`'s keys (types, ranges, choices) in place.
void check_keys(Validator& val, toml::table& table, const std::string& label, const std::string& path_prefix,
                const std::string& method, const MethodSpec& spec) {
  for (auto& [key, node] : table) {
    const KeySpec* k = find_key(spec.keys, std::string(key.str()));
    if (!k) foreign_key(val, key, path_prefix + std::string(key.str()), label, method, spec);
    val.check_value(node, *k, label, path_prefix + std::string(key.str()));
  }
}

}  // namespace

void load_method_section(toml::table& root, Validator& val, Scene& scene) {
  if (!root.contains("method")) root.insert("method", toml::table{});
  toml::node* section = root.get("method");
  if (!section->is_table()) val.fail(section, "method", "[method] must be a table");
  toml::table& table = *section->as_table();
  const auto names = method_spec_names();

  std::string method = "wcsph";
  if (toml::node* name = table.get("name")) {
    if (!name->is_string()) val.fail(name, "method.name", "'name' in [method] must be string");
    method = *name->value<std::string>();
    if (!find_method_spec(method)) {
      std::string hint = closest_name(method, names);
      val.fail(name, "method.name",
               "'name' in [method] is '" + method + "'; allowed: " + joined(names) +
                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
  }
  const MethodSpec& spec = *find_method_spec(method);

  // Keys written directly in [method] belong to the scene's method; [method.<name>] tables hold
  // another method's settings and are checked against that method's keys.
  for (auto& [key, node] : table) {
    const std::string k(key.str());
    if (k == "name") continue;
    if (node.is_table() && find_method_spec(k)) {
      check_keys(val, *node.as_table(), "[method." + k + "]", "method." + k + ".", k, *find_method_spec(k));
      continue;
    }
    if (node.is_table() && !find_key(spec.keys, k))
      val.fail_at(
          &key.source(), "method." + k,
          "[method." + k + "]: no method is registered as '" + k + "' (registered: " + joined(names) + ")");
    if (!find_key(spec.keys, k)) foreign_key(val, key, "method." + k, "[method]", method, spec);
    val.check_value(node, *find_key(spec.keys, k), "[method]", "method." + k);
  }

  std::set<std::string> given;
  toml::table values;
  for (auto& [key, node] : table)
    if (std::string(key.str()) != "name" && !node.is_table()) {
      values.insert(key, node);
      given.insert(std::string(key.str()));
    }
  if (auto* own = table.get_as<toml::table>(method))
    for (auto& [key, node] : *own) {
      const std::string k(key.str());
      if (given.count(k))
        val.fail_at(&key.source(), "method." + method + "." + k,
                    "'" + k + "' is set both in [method] and in [method." + method + "]; keep one");
      values.insert(key, node);
      given.insert(k);
    }
  for (auto& k : spec.keys)
    if (k.required && !values.contains(k.key))
      val.fail(section, "method." + k.key,
               "[method] of method " + method + " is missing required key '" + k.key + "'");
  for (auto& k : spec.keys)
    if (!values.contains(k.key) && !k.default_value.empty() && k.default_value.front() != '(') {
      auto parsed = toml::parse("v = " + k.default_value);
      values.insert(k.key, *parsed["v"].node());
    }
  scene.method = method;
  scene.method_params = MethodParams(std::move(values), std::move(given));
}

void check_owned_by_other_methods(const toml::table& root, const Validator& val, const Scene& scene,
                                  const std::set<std::string>& written,
                                  const std::set<std::string>& written_keys) {
  for (auto& owner : method_spec_names()) {
    if (owner == scene.method) continue;
    for (auto& owned : find_method_spec(owner)->owns) {
      const auto dot = owned.find('.'), equals = owned.find('=');
      if (dot == std::string::npos) {  // a whole section
        if (!written.count(owned)) continue;
        if (find_section(owned)->array_of_tables)
          val.fail_entry(root, owned, 0, "min", "[[" + owned + "]] #0 is for method " + owner);
        val.fail(root[owned].node(), owned, "[" + owned + "] is for [method] name = \"" + owner + "\"");
      }
      const std::string section = owned.substr(0, dot);
      const std::string key =
          owned.substr(dot + 1, equals == std::string::npos ? std::string::npos : equals - dot - 1);
      if (!written_keys.count(section + "." + key)) continue;
      const auto* entries = root[section].as_array();
      if (!entries) {  // a key of a plain section
        val.fail(root[section][key].node(), section + "." + key,
                 "[" + section + "] " + key + " is for method " + owner);
      }
      // A key, or one of its values, in an entry of [[section]]: the first entry that has it.
      for (std::size_t i = 0; i < entries->size(); ++i) {
        const toml::node* node = root[section][i][key].node();
        if (!node) continue;
        const std::string label = "[[" + section + "]] #" + std::to_string(i);
        if (equals == std::string::npos)
          val.fail_entry(root, section, i, key, label + " " + key + " is for method " + owner);
        const std::string value = owned.substr(equals + 1);
        if (node->value<std::string>() == value)
          val.fail_entry(root, section, i, key,
                         label + " of " + key + " " + value + " is for method " + owner);
      }
    }
  }
}

}  // namespace ryushi
