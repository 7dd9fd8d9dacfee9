#pragma once
#include "scene/registered_keys.hpp"

namespace ryushi {

// MPS's [method] keys and its scene hooks (mps_spec.cpp).
MethodSpec mps_spec();

}  // namespace ryushi
