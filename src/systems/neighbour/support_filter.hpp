#pragma once
// Narrows the step's neighbour list to the kernel's support at the positions as they now are.
// A method that evaluates its operators at predicted positions x* (ISPH: the free surface, the
// pressure rows and the corrector) searches at x^n with the support plus the step's motion,
// 3 cfl d more: in 2D at CFL 0.2 a third of those pairs lie beyond the support at x* and add
// exact zeros to every kernel sum. After the predictor this system keeps the pairs within the
// support at x*, so the systems after it walk only pairs that contribute. Every kernel weight
// and gradient beyond the support is exactly zero (kernel.hpp), so what those systems compute
// is the same to the last bit wherever they evaluate at x*; the shifting, which evaluates after
// the corrector has moved the particles by dt (v - v*), may lose a pair that came within the
// support during the correction (a change below the step's own truncation error).
#include <span>
#include <vector>

#include "ecs/io.hpp"
#include "systems/neighbour/filter_rows.hpp"
#include "systems/neighbour/neighbour_search.hpp"

namespace ryushi {

template <int D>
class SupportFilter final : public System<D> {
 public:
  explicit SupportFilter(double support) : support_(support) {}
  std::string name() const override { return "support_filter"; }
  static constexpr auto io = Io{reads(components::position, domain_resource<D>), writes(neighbours_resource)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, domain, list] = io.fetch(ctx);
    filter_neighbour_list<D>(domain, support_, x, list, list);  // in place
  }

 private:
  double support_;
};

}  // namespace ryushi
