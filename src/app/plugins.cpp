#include "app/plugins.hpp"

#include <dlfcn.h>
#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "methods/method.hpp"
#include "methods/plugin.hpp"
#include "methods/system_registry.hpp"
#include "scene/scene.hpp"

namespace ryushi {

namespace fs = std::filesystem;

namespace {

// The mark RYUSHI_PLUGIN() leaves in the library's bytes: the version it was built against,
// or "" when there is none.
std::string plugin_version(const std::string& bytes) {
  const std::string mark = RYUSHI_PLUGIN_MARK;
  const auto at = bytes.find(mark);
  if (at == std::string::npos) return "";
  const auto end = bytes.find(';', at + mark.size());
  return end == std::string::npos ? "" : bytes.substr(at + mark.size(), end - at - mark.size());
}

void load_one(const std::string& library, const std::string& origin) {
  static std::set<std::string> loaded;  // canonical paths, so a library named twice loads once
  const std::string where = origin + ": plugin " + library;
  std::error_code ec;
  if (!fs::is_regular_file(library, ec)) throw SceneError(where + ": no such file");
  const std::string canonical = fs::canonical(library, ec).string();
  if (loaded.count(canonical)) return;
  std::ifstream in(library, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.compare(0, 4,
                    "\x7f"
                    "ELF") != 0)
    throw SceneError(where + ": not a shared library");
  const std::string version = plugin_version(bytes);
  if (version.empty())
    throw SceneError(where + ": not a ryushi plugin (no RYUSHI_PLUGIN() mark; docs/extending.md)");
  if (version != RYUSHI_VERSION)
    throw SceneError(where + ": built against ryushi " + version + ", this is ryushi " RYUSHI_VERSION +
                     "; rebuild it against this installation");
  begin_plugin_registrations();
  void* handle = dlopen(canonical.c_str(), RTLD_NOW | RTLD_LOCAL);
  const char* error = handle ? nullptr : dlerror();
  const PluginRegistrations registered = end_plugin_registrations();
  if (!handle) throw SceneError(where + ": cannot be loaded: " + (error ? error : "unknown error"));
  if (!registered.clashes.empty()) {
    for (auto& name : registered.methods) unregister_method(name);
    for (auto& name : registered.systems) unregister_system(name);
    std::string names;
    for (auto& clash : registered.clashes) names += (names.empty() ? "" : ", ") + clash;
    throw SceneError(where + ": registers " + names +
                     ", a name already registered (by ryushi or an earlier plugin)");
  }
  loaded.insert(canonical);  // the handle stays open: its methods and systems are in use
}

}  // namespace

void load_plugins(const std::vector<std::string>& libraries, const std::string& scene_path) {
  for (auto& library : libraries) load_one(library, "--plugin");
  if (scene_path.empty()) return;
  toml::table root;
  try {
    root = toml::parse_file(scene_path);
  } catch (const std::exception&) {
    return;  // the scene loader reports what is wrong with the file
  }
  const auto* list = root["plugins"]["libraries"].as_array();
  if (!list) return;  // absent, or of the wrong type: the loader says so
  for (auto& entry : *list) {
    const auto* text = entry.as_string();
    if (!text) continue;
    fs::path library(text->get());
    if (library.is_relative()) library = fs::path(scene_path).parent_path() / library;
    std::ostringstream origin;
    origin << scene_path << ":" << entry.source().begin.line << ":" << entry.source().begin.column;
    load_one(library.string(), origin.str());
  }
}

}  // namespace ryushi
