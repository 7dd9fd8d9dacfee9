#pragma once
// [method] keys that several methods declare, each in its own list (a key is its method's: the
// same words in two methods' lists are two keys that happen to share a name and meaning).
#include "scene/schema.hpp"

namespace ryushi {

inline KeySpec hydrostatic_init_key() {
  using K = KeyType;
  return {
      "hydrostatic_init", K::Bool, "", "true",
      "Start fluid with hydrostatic pressure and the matching density (mass = density * d^dim), so a resting "
      "column starts in equilibrium. mps: the hydrostatic pressure is the first solve's initial guess."};
}

inline KeySpec wall_slip_key() {
  using K = KeyType;
  return {"wall_slip", K::Bool, "", "false",
          "With laminar viscosity: free-slip walls (true) or no-slip (false)."};
}

}  // namespace ryushi
