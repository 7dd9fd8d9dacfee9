#pragma once
// [[elastic]] bodies and the [method] solid_* keys (docs/multiphysics.md), read into the scene and
// checked, after the fluid, walls and solids are read.
#include <toml++/toml.h>

#include "scene/scene.hpp"
#include "scene/validator.hpp"

namespace ryushi {

void load_elastic(toml::table& root, const Validator& val, Scene& sc);

}  // namespace ryushi
