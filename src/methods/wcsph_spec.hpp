#pragma once
#include "scene/registered_keys.hpp"

namespace ryushi {

// WCSPH's [method] keys, the sections it owns and its scene hooks (wcsph_spec.cpp).
MethodSpec wcsph_spec();

}  // namespace ryushi
