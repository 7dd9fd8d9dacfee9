#pragma once
#include "scene/registered_keys.hpp"

namespace ryushi {

// The shallow-water method's sections and its scene hooks (swe_spec.cpp).
MethodSpec swe_spec();
// [swe], [bed], [[bed_hump]], [[bed_ramp]] and [splitting] into scene.swe (swe_sections.cpp).
void read_swe_sections(Scene& scene, const toml::table& root, Validator& val);

}  // namespace ryushi
