#include "methods/wcsph.hpp"

#include <cmath>

#include "ecs/lattice.hpp"
#include "methods/system_registry.hpp"
#include "systems/boundary/adami_wall.hpp"
#include "systems/fluid/continuity_delta_sph.hpp"
#include "systems/fluid/laminar_viscosity_morris.hpp"
#include "systems/fluid/momentum.hpp"
#include "systems/fluid/renormalised_density_gradient.hpp"
#include "systems/fluid/tait_equation_of_state.hpp"
#include "systems/integrate/midpoint.hpp"
#include "systems/integrate/time_step.hpp"
#include "systems/neighbour/neighbour_search.hpp"

namespace ryushi {

template <int D>
WcsphParameters<D> wcsph_parameters(const Scene& s) {
  WcsphParameters<D> p;
  p.kernel = Kernel<D>(kernel_from_name(s.kernel), s.smoothing_length());
  for (int a = 0; a < D; ++a) {
    p.domain.min[a] = s.domain_min[a];
    p.domain.max[a] = s.domain_max[a];
    p.domain.periodic[a] = s.periodic[a];
    p.gravity[a] = s.gravity[a];
  }
  p.spacing = s.spacing;
  p.rho0 = s.density;
  p.c0 = s.resolved_sound_speed();
  p.gamma = s.gamma;
  p.delta = s.delta;
  p.alpha = s.alpha;
  p.beta = s.beta;
  p.mu = s.viscosity;
  p.wall_no_slip = !s.wall_slip;
  return p;
}

namespace {

template <int D>
Vec<D> to_vec(const std::vector<double>& v) {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = v[a];
  return x;
}

}  // namespace

template <int D>
void populate_world(const Scene& s, const WcsphParameters<D>& p, World<D>& world) {
  const double d = s.spacing, volume = std::pow(d, D);
  const double g_up = -p.gravity[D - 1];  // gravity along the vertical (last) axis
  std::vector<Vec<D>> points;
  std::vector<double> depth;
  for (auto& b : s.fluid) {
    Vec<D> lo = to_vec<D>(b.min);
    std::array<long, D> from{}, to{};
    for (int a = 0; a < D; ++a) to[a] = std::lround((b.max[a] - b.min[a]) / d);
    double top = b.min[D - 1] + to[D - 1] * d;
    for_each_lattice_point<D>(lo, d, from, to, [&](const Vec<D>& x) {
      points.push_back(x);
      depth.push_back(top - x[D - 1]);
    });
  }
  std::size_t first = world.append(points.size(), kFluid);
  auto& x = world.ensure(components::position);
  auto& m = world.ensure(components::mass);
  auto& rho = world.ensure(components::density);
  auto& pr = world.ensure(components::pressure);
  world.ensure(components::velocity);
  for (std::size_t k = 0; k < points.size(); ++k) {
    std::size_t i = first + k;
    x[i] = points[k];
    double pressure = s.hydrostatic_init ? p.rho0 * g_up * depth[k] : 0.0;
    rho[i] = p.density(pressure);
    pr[i] = p.pressure(rho[i]);
    m[i] = rho[i] * volume;  // the lattice volume d^D holds the (compressed) fluid
  }

  for (auto& w : s.walls) {
    std::vector<Vec<D>> wall;
    Vec<D> lo = to_vec<D>(w.min), hi = to_vec<D>(w.max);
    std::array<long, D> from{}, to{};
    for (int a = 0; a < D; ++a) {
      from[a] = -w.layers;
      to[a] = std::lround((w.max[a] - w.min[a]) / d) + ((a == D - 1 && w.open_top) ? 0 : w.layers);
    }
    for_each_lattice_point<D>(lo, d, from, to, [&](const Vec<D>& q) {
      bool inside = true;
      for (int a = 0; a < D; ++a) inside = inside && q[a] > lo[a] && q[a] < hi[a];
      if (!inside) wall.push_back(q);
    });
    std::size_t wfirst = world.append(wall.size(), kWall);
    auto& xw = world.column(components::position);
    auto& mw = world.column(components::mass);
    auto& rw = world.column(components::density);
    for (std::size_t k = 0; k < wall.size(); ++k) {
      xw[wfirst + k] = wall[k];
      mw[wfirst + k] = p.rho0 * volume;
      rw[wfirst + k] = p.rho0;
    }
  }
}

template <int D>
std::vector<SystemPtr<D>> wcsph_pipeline(const Scene& s, const WcsphParameters<D>& p) {
  auto neighbours = std::make_shared<NeighbourSearch<D>>(p.kernel.support(), /*skip_wall_pairs=*/true);
  auto wall = std::make_shared<AdamiWall<D>>(p);
  auto gradient = std::make_shared<RenormalisedDensityGradient<D>>(p);
  auto continuity = std::make_shared<ContinuityDeltaSph<D>>(p);
  auto momentum = std::make_shared<Momentum<D>>(p);
  auto viscosity = std::make_shared<LaminarViscosityMorris<D>>(p);
  auto eos = std::make_shared<TaitEquationOfState<D>>(p);

  std::vector<SystemPtr<D>> list{neighbours};
  auto stage = [&] {
    if (!s.walls.empty()) list.push_back(wall);
    if (p.delta > 0) list.push_back(gradient);
    list.push_back(continuity);
    list.push_back(momentum);
    if (p.mu > 0) list.push_back(viscosity);
  };
  stage();
  list.push_back(std::make_shared<MidpointPredictor<D>>());
  list.push_back(eos);
  stage();
  list.push_back(std::make_shared<MidpointCorrector<D>>());
  list.push_back(eos);
  if (s.fixed_dt <= 0) list.push_back(std::make_shared<TimeStepControl<D>>(p, s.cfl));
  for (auto& extra : s.systems) list.push_back(make_registered_system<D>(extra.name, extra.params, p));
  return list;
}

template WcsphParameters<2> wcsph_parameters<2>(const Scene&);
template WcsphParameters<3> wcsph_parameters<3>(const Scene&);
template void populate_world<2>(const Scene&, const WcsphParameters<2>&, World<2>&);
template void populate_world<3>(const Scene&, const WcsphParameters<3>&, World<3>&);
template std::vector<SystemPtr<2>> wcsph_pipeline<2>(const Scene&, const WcsphParameters<2>&);
template std::vector<SystemPtr<3>> wcsph_pipeline<3>(const Scene&, const WcsphParameters<3>&);

}  // namespace ryushi
