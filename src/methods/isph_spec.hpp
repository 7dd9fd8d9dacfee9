#pragma once
#include "scene/registered_keys.hpp"

namespace ryushi {

// ISPH's [method] keys and its scene hooks (isph_spec.cpp).
MethodSpec isph_spec();

}  // namespace ryushi
