#pragma once
// Prescribed motion of [[solid]] bodies (a piston wave maker, a rotating paddle): at the start of
// every step each particle of a moving body goes to its rest position plus the displacement
// formula at the step's time, and takes the formula's time derivative (a central difference
// over 2 microseconds) as its velocity, which the wall conditions use as the surface's, and its
// second derivative (over 0.2 ms: round-off ~1e-9 m/s^2 for centimetre strokes) as its
// acceleration, which enters Adami's wall pressure; or the tabulated displacement, its slope and
// the slope's change (functions/motion_table.hpp).
#include <string>
#include <vector>

#include "ecs/io.hpp"
#include "functions/expression.hpp"
#include "functions/motion_table.hpp"

namespace ryushi {

template <int D>
class PrescribedMotion final : public System<D> {
 public:
  struct Body {
    int index;                         // the [[solid]]'s
    std::vector<Expression> formulas;  // one per axis, of t and the rest position; or
    std::vector<MotionSample> table;   // a tabulated displacement (the same for every particle)
  };
  explicit PrescribedMotion(std::vector<Body> bodies) : bodies_(std::move(bodies)) {}
  std::string name() const override { return "prescribed_motion"; }
  // The body column says which particles move (kind is not needed, and no system writes it).
  static constexpr auto io =
      Io{reads(components::body, components::body_origin, resources::time),
         writes(components::position, components::velocity, components::body_acceleration)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [body, origin, t, x, v, acceleration] = io.fetch(ctx);
    const double h = 1e-6, ha = 2e-4;
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (body[i] < 0) continue;
      for (auto& b : bodies_) {
        if (b.index != body[i]) continue;
        const Vec<D>& o = origin[i];
        if (!b.table.empty()) {
          auto [shift, speed] = sample_motion(b.table, t);
          const auto change = motion_acceleration(b.table, t);
          for (int a = 0; a < D; ++a)
            x[i][a] = o[a] + shift[a], v[i][a] = speed[a], acceleration[i][a] = change[a];
          continue;
        }
        const double y = D > 1 ? o[1] : 0.0, z = D > 2 ? o[2] : 0.0;
        for (int a = 0; a < D; ++a) {
          x[i][a] = o[a] + b.formulas[a](o[0], y, z, t);
          v[i][a] = (b.formulas[a](o[0], y, z, t + h) - b.formulas[a](o[0], y, z, t - h)) / (2 * h);
          acceleration[i][a] =
              (b.formulas[a](o[0], y, z, t + ha) - 2 * (x[i][a] - o[a]) + b.formulas[a](o[0], y, z, t - ha)) /
              (ha * ha);
        }
      }
    }
  }

 private:
  std::vector<Body> bodies_;
};

}  // namespace ryushi
