#pragma once
// The [material] rheology and heat keys and the thermal keys of [[fluid]], [[wall]] and [[solid]]
// (docs/multiphysics.md): read into the scene and checked together, after the blocks, walls and
// bodies are read.
#include <toml++/toml.h>

#include "scene/scene.hpp"
#include "scene/validator.hpp"

namespace ryushi {

void load_heat_and_rheology(toml::table& root, const Validator& val, Scene& sc);

}  // namespace ryushi
