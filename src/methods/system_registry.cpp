#include "methods/system_registry.hpp"

#include <map>
#include <stdexcept>

#include "scene/registered_keys.hpp"

namespace ryushi {

namespace {
// Function-local so registration from any translation unit's static initialiser is safe.
std::map<std::string, SystemRegistryEntry>& registry() {
  static std::map<std::string, SystemRegistryEntry> r;
  return r;
}
}  // namespace

bool register_system(const std::string& name, SystemRegistryEntry entry) {
  // The loader checks [[systems]] keys against the scene layer's copy of them.
  if (!register_system_keys(name, entry.keys)) return false;  // a name taken
  registry().emplace(name, std::move(entry));
  return true;
}

void unregister_system(const std::string& name) {
  registry().erase(name);
  unregister_system_keys(name);
}

std::vector<std::string> system_registry_names() {
  std::vector<std::string> names;
  for (auto& [n, _] : registry()) names.push_back(n);
  return names;
}

bool system_registered(const std::string& name) { return registry().count(name) != 0; }

const SystemRegistryEntry& system_registry_entry(const std::string& name) {
  auto it = registry().find(name);
  if (it == registry().end()) throw std::invalid_argument("no system registered as '" + name + "'");
  return it->second;
}

}  // namespace ryushi
