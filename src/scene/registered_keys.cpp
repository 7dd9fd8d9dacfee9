#include "scene/registered_keys.hpp"

#include <map>
#include <memory>
#include <stdexcept>

#include "scene/scene.hpp"

namespace ryushi {

namespace {
// Function-local so registration from any translation unit's static initialiser is safe.
std::map<std::string, MethodSpec>& specs() {
  static std::map<std::string, MethodSpec> r;
  return r;
}
std::map<std::string, SystemKeys>& systems() {
  static std::map<std::string, SystemKeys> r;
  return r;
}
unsigned long& generation() {
  static unsigned long g = 0;
  return g;
}
// The plugin being loaded (begin_plugin_registrations), or none.
std::unique_ptr<PluginRegistrations>& loading() {
  static std::unique_ptr<PluginRegistrations> p;
  return p;
}
std::vector<std::string>& built_in_clashes() {
  static std::vector<std::string> c;
  return c;
}
// A name taken: recorded, for the plugin loader while a plugin loads, else for main() to report
// before any command (thrown from a static initialiser, it aborted every command, exit 134).
bool clash(const std::string& what) {
  (loading() ? loading()->clashes : built_in_clashes()).push_back(what);
  return false;
}
}  // namespace

const std::vector<std::string>& built_in_registration_clashes() {
  return built_in_clashes();
}

void begin_plugin_registrations() {
  loading() = std::make_unique<PluginRegistrations>();
}

PluginRegistrations end_plugin_registrations() {
  PluginRegistrations done = loading() ? std::move(*loading()) : PluginRegistrations{};
  loading().reset();
  return done;
}

unsigned long registered_keys_generation() {
  return generation();
}

namespace {
// The one way into either registry: a name taken is a clash (thrown, or recorded while a plugin
// loads); a name added while a plugin loads is listed for its roll-back.
template <class Entry>
bool add(std::map<std::string, Entry>& registry, const std::string& kind, const std::string& name,
         Entry entry, std::vector<std::string> PluginRegistrations::*added) {
  if (!registry.emplace(name, std::move(entry)).second) return clash(kind + " '" + name + "'");
  if (loading()) ((*loading()).*added).push_back(name);
  ++generation();
  return true;
}
template <class Entry>
void remove(std::map<std::string, Entry>& registry, const std::string& name) {
  registry.erase(name);
  ++generation();
}
template <class Entry>
std::vector<std::string> names_of(const std::map<std::string, Entry>& registry) {
  std::vector<std::string> names;
  for (auto& [n, _] : registry) names.push_back(n);
  return names;
}
template <class Entry>
const Entry* find_in(const std::map<std::string, Entry>& registry, const std::string& name) {
  auto it = registry.find(name);
  return it == registry.end() ? nullptr : &it->second;
}
}  // namespace

bool register_method_spec(const std::string& name, MethodSpec spec) {
  return add(specs(), "method", name, std::move(spec), &PluginRegistrations::methods);
}
void unregister_method_spec(const std::string& name) {
  remove(specs(), name);
}
std::vector<std::string> method_spec_names() {
  return names_of(specs());
}
const MethodSpec* find_method_spec(const std::string& name) {
  return find_in(specs(), name);
}

bool register_system_keys(const std::string& name, SystemKeys keys) {
  return add(systems(), "system", name, std::move(keys), &PluginRegistrations::systems);
}
void unregister_system_keys(const std::string& name) {
  remove(systems(), name);
}
std::vector<std::string> system_key_names() {
  return names_of(systems());
}
const SystemKeys* find_system_keys(const std::string& name) {
  return find_in(systems(), name);
}

std::vector<std::string> methods_owning_key(const std::string& key) {
  std::vector<std::string> owners;
  for (auto& [name, spec] : specs())
    if (find_key(spec.keys, key)) owners.push_back(name);
  return owners;
}

const toml::node& MethodParams::at(const std::string& key) const {
  const toml::node* node = values_.get(key);
  // The loader inserted every key the method declares; asking for another is a coding error.
  if (!node) throw std::logic_error("[method] has no key '" + key + "'");
  return *node;
}
double MethodParams::number(const std::string& key) const {
  return *at(key).value<double>();
}
long long MethodParams::integer(const std::string& key) const {
  return *at(key).value<long long>();
}
bool MethodParams::flag(const std::string& key) const {
  return *at(key).value<bool>();
}
std::string MethodParams::text(const std::string& key) const {
  return *at(key).value<std::string>();
}

}  // namespace ryushi
