#pragma once
// The [method] section: the method's name, and its keys checked against the keys that method
// registered (scene/registered_keys.hpp). A key of another method is an error at the key naming
// the method that owns it; a scene that carries settings for several methods (a tank run under
// each) puts them in [method.<name>] tables, read only when that method is the scene's.
#include <toml++/toml.h>

#include <set>
#include <string>

namespace ryushi {

struct Scene;
class Validator;

// Sets scene.method and scene.method_params (every key of the method, defaults inserted).
void load_method_section(toml::table& root, Validator& val, Scene& scene);

// What another method owns (MethodSpec::owns) and the scene wrote is an error at its place: a
// section, a key of a section or of any entry of [[section]], or a value of such a key
// ("probe.type=front_depth"). `written`: the sections the file and --set wrote (before any
// default was inserted); `written_keys`: their "section.key"s.
void check_owned_by_other_methods(const toml::table& root, const Validator& val, const Scene& scene,
                                  const std::set<std::string>& written,
                                  const std::set<std::string>& written_keys);

}  // namespace ryushi
