#pragma once
// The [method] section: the method's name, and its keys checked against the keys that method
// registered (scene/registered_keys.hpp). A key of another method is an error at the key naming
// the method that owns it; a scene that carries settings for several methods (a tank run under
// each) puts them in [method.<name>] tables, read only when that method is the scene's.
#include <toml++/toml.h>

namespace ryushi {

struct Scene;
class Validator;

// Sets scene.method and scene.method_params (every key of the method, defaults inserted).
void load_method_section(toml::table& root, Validator& val, Scene& scene);

}  // namespace ryushi
