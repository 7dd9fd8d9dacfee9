#pragma once
// A Laplacian chosen by name in a scene (standard | corrected | sph2), as weights
// (laplacian.hpp's convention), for the systems that let the user pick the operator order.
#include <stdexcept>
#include <string>
#include <vector>

#include "systems/operators/laplacian.hpp"
#include "systems/operators/second_derivatives.hpp"

namespace ryushi {

enum class LaplacianOrder { Standard, Corrected, Sph2 };

inline LaplacianOrder laplacian_order(const std::string& name) {
  if (name == "standard") return LaplacianOrder::Standard;
  if (name == "corrected") return LaplacianOrder::Corrected;
  if (name == "sph2") return LaplacianOrder::Sph2;
  throw std::invalid_argument("unknown Laplacian '" + name + "' (standard, corrected or sph2)");
}

template <int D>
void laplacian_weights(LaplacianOrder order, const Stencil<D>& s, std::vector<double>& w) {
  switch (order) {
    case LaplacianOrder::Standard:
      laplacian_weights_standard(s, w);
      break;
    case LaplacianOrder::Corrected:
      laplacian_weights_corrected(s, w);
      break;
    case LaplacianOrder::Sph2:
      laplacian_weights_sph2(s, w);
      break;
  }
}

template <int D>
void laplacian_weights(LaplacianOrder order, const ParticleView<D>& v, std::size_t i,
                       std::vector<double>& w) {
  laplacian_weights(order, gathered_stencil(v, i), w);
}

}  // namespace ryushi
