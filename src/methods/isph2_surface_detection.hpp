#pragma once
// The registered free-surface detection with the I-SPH(2) rule (det M_i < 0.6, then Marrone's
// test), as ISPH runs it and as WCSPH's particle shifting uses it: one definition for both.

#include "methods/system_registry.hpp"

namespace ryushi {

template <int D>
SystemPtr<D> isph2_surface_detection(const MethodContext<D>& context) {
  toml::table rule{{"rule", "isph2"}, {"beta", 0.85}, {"moment_matrix", false}};
  return make_registered_system<D>("free_surface_detection", rule, context);
}

}  // namespace ryushi
