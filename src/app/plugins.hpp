#pragma once
// Plugin libraries (docs/extending.md): shared libraries built against an installed ryushi
// whose methods and systems register as built-in ones do. They load before a scene's keys are
// checked, so their keys are validated like ryushi's own.
#include <string>
#include <vector>

namespace ryushi {

// Loads `--plugin` libraries (paths as given) and the scene's [plugins] libraries (relative to
// the scene file; "" : no scene), each once per process. Throws SceneError, one line naming the
// library and why: no such file, not a shared library, not a ryushi plugin (no RYUSHI_PLUGIN()
// mark), built against another ryushi version, not loadable (the dynamic loader's message), or a
// method or system name already registered (then none of the library's names stay registered).
void load_plugins(const std::vector<std::string>& libraries, const std::string& scene_path = "");

}  // namespace ryushi
