#pragma once
#include "scene/registered_keys.hpp"

namespace ryushi {

// The shallow-water method's sections and its scene hooks (swe_spec.cpp).
MethodSpec swe_spec();

}  // namespace ryushi
