#include "systems/free_surface/free_surface_detection.hpp"

#include <stdexcept>

namespace ryushi {

FreeSurfaceRule free_surface_rule(const std::string& name) {
  if (name == "marrone") return FreeSurfaceRule::Marrone;
  if (name == "isph2") return FreeSurfaceRule::Isph2;
  if (name == "mps") return FreeSurfaceRule::Mps;
  throw std::invalid_argument("unknown free-surface rule '" + name + "' (marrone, isph2, mps)");
}

}  // namespace ryushi
