#pragma once
// Ritter's dry-bed dam break (Saigo & Koshizuka eq. 14; Castro-Orgaz & Chanson 2017): water of
// depth h0 behind a dam at x_dam released at t = 0 over a dry frictionless bed,
//   h(x, t) = (2 sqrt(g h0) - (x - x_dam) / t)^2 / (9 g)  for -sqrt(g h0) t <= x - x_dam <= 2 sqrt(g h0) t,
// h0 upstream of that fan and 0 beyond the front x_dam + 2 sqrt(g h0) t.
// The front-region depth error (docs/swe.md): over the particles downstream of the dam (x >=
// x_dam: the water that has run onto the dry bed, where it thins and particle splitting acts),
// sum |h_i - h(x_i)| / sum h(x_i). The front position (the foremost particle against the
// analytic front) and the error over the whole wave (every particle) are reported beside it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ecs/math.hpp"

namespace ryushi {

struct RitterReference {
  double dam_x = std::numeric_limits<double>::quiet_NaN(), h0 = 0, g = 9.81;
  bool enabled() const { return std::isfinite(dam_x) && h0 > 0; }
  double depth(double x, double t) const {
    const double c0 = std::sqrt(g * h0), xi = x - dam_x;
    if (t <= 0) return xi <= 0 ? h0 : 0.0;
    if (xi <= -c0 * t) return h0;
    if (xi >= 2 * c0 * t) return 0.0;
    const double s = 2 * c0 - xi / t;
    return s * s / (9 * g);
  }
};

struct RitterErrors {
  double front_depth_error = 0, depth_error = 0, front = 0, analytic_front = 0;
  std::size_t front_particles = 0;
};

template <class Positions, class Depths>
RitterErrors ritter_errors(const Positions& x, const Depths& h, const RitterReference& r, double t) {
  RitterErrors e;
  e.front = -std::numeric_limits<double>::infinity();
  for (auto& p : x) e.front = std::max(e.front, p[0]);
  e.analytic_front = r.dam_x + 2 * std::sqrt(r.g * r.h0) * t;
  double front_diff = 0, front_ref = 0, diff = 0, ref = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double ha = r.depth(x[i][0], t);
    diff += std::abs(h[i] - ha), ref += ha;
    if (x[i][0] >= r.dam_x) {
      front_diff += std::abs(h[i] - ha), front_ref += ha;
      ++e.front_particles;
    }
  }
  e.front_depth_error = front_ref > 0 ? front_diff / front_ref : std::numeric_limits<double>::quiet_NaN();
  e.depth_error = ref > 0 ? diff / ref : std::numeric_limits<double>::quiet_NaN();
  return e;
}

}  // namespace ryushi
