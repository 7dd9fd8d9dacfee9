// The fused WCSPH pair pass (src/systems/fluid/wcsph_pair_forces.hpp: the pair loop with the
// continuity + delta-SPH, pressure + artificial viscosity and Morris viscosity terms) against a
// direct evaluation of the same formulas written here, over every pair of particles with the
// divisions as the seed prints them and no neighbour list. A jittered lattice of fluid inside
// three layers of walls with random velocities, densities, pressures, viscosities, density
// gradients and wall ghost velocities, so every branch is taken (approaching and receding pairs,
// fluid-wall pairs, no-slip and slip). The two may differ only by round-off: the pass multiplies
// by 1/rho and 1/(r^2 + eta^2) where the reference divides, a few ulp per pair, summed over ~30
// pairs of either sign. The tolerance is 1e-12 of the size of the largest term of each sum (sum
// of |terms| would be tighter; this is the simplest bound that is still 1e4 above the expected
// ~1e-16 x 30). A neighbour list with a skin (pairs beyond the support) must give the same
// result: the pass skips them. Both strategies of the loop are checked: gather (each particle
// visits all its pairs) and each pair once (from the lower index, both sides accumulated; the
// sums come in another order, still round-off).
#include "systems/fluid/wcsph_pair_forces.hpp"

#include <doctest/doctest.h>

#include <random>

#include "systems/neighbour/neighbour_search.hpp"

using namespace ryushi;

namespace {

template <int D>
void fill_random_state(World<D>& w, double d, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto& kind = w.column(components::kind);
  auto& v = w.ensure(components::velocity);
  auto& rho = w.ensure(components::density);
  auto& p = w.ensure(components::pressure);
  auto& m = w.ensure(components::mass);
  auto& mu = w.ensure(components::viscosity);
  auto& grad = w.ensure(components::density_gradient);
  auto& vw = w.ensure(components::wall_velocity);
  w.ensure(components::density_rate);
  w.ensure(components::acceleration);
  for (std::size_t i = 0; i < w.size(); ++i) {
    for (int a = 0; a < D; ++a) {
      v[i][a] = kind[i] == kFluid ? u(rng) : 0.0;
      grad[i][a] = 50.0 * u(rng);
      vw[i][a] = 0.5 * u(rng);
    }
    rho[i] = 1000.0 * (1.0 + 0.02 * u(rng));
    p[i] = 2000.0 * (1.0 + u(rng));
    m[i] = rho[i] * std::pow(d, D) * (1.0 + 0.01 * u(rng));
    mu[i] = 1e-3 * (1.5 + u(rng));
  }
}

// Runs a system on the world with its own declared access (as the scheduler would).
template <int D>
void run_system(System<D>& s, World<D>& w, Resources& res) {
  auto access = s.access();
  SystemContext<D> ctx(w, res, access, "test");
  s.run(ctx);
}

// The pair terms as the seed writes them (seed 002 eqs. 17-19 and 22-24, Morris 1997), summed
// over every other particle within the support.
template <int D>
void direct_evaluation(const World<D>& w, const WcsphParameters<D>& p, std::vector<double>& drho,
                       std::vector<Vec<D>>& a) {
  const auto& x = w.column(components::position);
  const auto& v = w.column(components::velocity);
  const auto& rho = w.column(components::density);
  const auto& pr = w.column(components::pressure);
  const auto& m = w.column(components::mass);
  const auto& mu = w.column(components::viscosity);
  const auto& grad = w.column(components::density_gradient);
  const auto& vw = w.column(components::wall_velocity);
  const auto& kind = w.column(components::kind);
  const auto& normal = w.column(components::wall_normal);
  const double h = p.kernel.h(), eta2 = 0.01 * h * h, support = p.kernel.support();
  drho.assign(w.size(), 0.0);
  a.assign(w.size(), Vec<D>::Zero());
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (kind[i] != kFluid) continue;
    double divergence = 0, diffusive = 0;
    Vec<D> acc = Vec<D>::Zero();
    for (std::size_t j = 0; j < w.size(); ++j) {
      const Vec<D> xij = x[i] - x[j];
      const double r = xij.norm();
      if (j == i || r >= support) continue;
      const Vec<D> gradW = xij * p.kernel.grad_factor(r);
      const Vec<D> vij = v[i] - v[j];
      const double Vj = m[j] / rho[j];
      const bool fluid_j = kind[j] == kFluid;
      divergence += Vj * vij.dot(gradW);
      // delta-SPH's pair, or the Riemann problem's: delta h replaced by r / 2.
      if (fluid_j)
        diffusive += (p.riemann ? 0.5 * r : 1.0) * Vj *
                     (2.0 * (rho[j] - rho[i]) * (-xij).dot(gradW) / (r * r) - (grad[i] + grad[j]).dot(gradW));
      double Pi = 0;
      if (p.riemann) {
        // Zhang, Hu & Adams: 2 P* / (rho_i rho_j) with P* = (p_i + p_j)/2 + beta rho0 c0 U / 2; U
        // the approach speed along the pair, or against a wall twice the normal one (its mirror),
        // at most twice the speed along the pair.
        const double U = fluid_j ? -vij.dot(xij) / r : 2.0 * std::min(vij.dot(normal[j]), -vij.dot(xij) / r);
        if (U > 0) Pi = std::min(p.riemann_limiter * U / p.c0, 1.0) * p.rho0 * p.c0 * U / (rho[i] * rho[j]);
      } else if (vij.dot(xij) < 0) {
        const double mu_ij = h * vij.dot(xij) / (r * r + eta2);
        Pi = (-p.alpha * p.c0 * mu_ij + p.beta * mu_ij * mu_ij) / (0.5 * (rho[i] + rho[j]));
      }
      acc -= m[j] * ((pr[i] + pr[j]) / (rho[i] * rho[j]) + Pi) * gradW;
      if (fluid_j || p.wall_no_slip) {
        const double mu_j = fluid_j ? mu[j] : mu[i];
        const Vec<D> v_j = fluid_j ? v[j] : vw[j];
        acc += m[j] * (mu[i] + mu_j) / (rho[i] * rho[j]) * xij.dot(gradW) / (r * r + eta2) * (v[i] - v_j);
      }
    }
    drho[i] = rho[i] * divergence + (p.riemann ? p.c0 : p.delta * h * p.c0) * diffusive;
    a[i] = acc + p.gravity;
  }
}

template <int D>
void check_fused_matches_reference(bool no_slip, double skin, bool pairs_once, bool riemann = false) {
  const double d = 0.01;
  const int n = D == 2 ? 20 : 8, layers = 3;
  std::mt19937 rng(7 + D + (no_slip ? 1 : 0));
  std::uniform_real_distribution<double> jitter(-0.15 * d, 0.15 * d);
  World<D> w;
  std::vector<Vec<D>> xs, normals;
  std::vector<std::int32_t> kinds;
  const int lo = -layers, hi = n + layers;
  std::array<int, D> c{};
  auto fill = [&](auto&& self, int axis) -> void {
    if (axis == D) {
      bool wall = false;
      Vec<D> x, out_of_the_fluid = Vec<D>::Zero();
      for (int a = 0; a < D; ++a) {
        wall = wall || c[a] < 0 || c[a] >= n;
        x[a] = (c[a] + 0.5) * d;
        out_of_the_fluid[a] = (c[a] >= n) - (c[a] < 0);
      }
      normals.push_back(wall ? Vec<D>(out_of_the_fluid.normalized()) : Vec<D>::Zero());
      if (!wall)
        for (int a = 0; a < D; ++a) x[a] += jitter(rng);
      xs.push_back(x);
      kinds.push_back(wall ? kWall : kFluid);
      return;
    }
    for (c[axis] = lo; c[axis] < hi; ++c[axis]) self(self, axis + 1);
  };
  fill(fill, 0);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    std::size_t k = w.append(1, kinds[i]);
    w.ensure(components::position)[k] = xs[i];
    w.ensure(components::wall_normal)[k] = normals[i];
  }
  fill_random_state(w, d, rng);

  WcsphParameters<D> p;
  p.kernel = Kernel<D>(KernelType::WendlandC2, 1.5 * d);
  p.domain.min = Vec<D>::Constant(lo * d);
  p.domain.max = Vec<D>::Constant(hi * d);
  p.c0 = 20;
  p.alpha = 0.02;
  p.beta = 0.1;  // the quadratic term too
  p.delta = 0.1;
  p.mu = 1e-3;
  p.wall_no_slip = no_slip;
  p.riemann = riemann;
  p.riemann_limiter = 30;  // the limiter saturates (beta = 1) from U = 0.67 m/s: both branches
  p.gravity[D - 1] = -9.81;

  Resources res;
  auto& nl = res.ensure(neighbours_resource);
  CellGrid<D> grid;
  build_neighbour_list<D>(p.domain, p.kernel.support() + skin, w.column(components::position), grid, nl,
                          w.column(components::kind), kWall);

  WcsphPairForces<D> fused(p);
  fused.set_pairs_once(pairs_once ? PairsOnce::Always : PairsOnce::Never);
  // The viscosity's initialise() fills a uniform mu; keep the random one.
  std::vector<double> ref_drho;
  std::vector<Vec<D>> ref_a;
  direct_evaluation<D>(w, p, ref_drho, ref_a);
  run_system<D>(fused, w, res);
  const auto& drho = w.column(components::density_rate);
  const auto& a = w.column(components::acceleration);

  const auto& kind = w.column(components::kind);
  double scale_drho = 0, scale_a = 0, err_drho = 0, err_a = 0;
  std::size_t fluid = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (kind[i] != kFluid) continue;
    ++fluid;
    scale_drho = std::max(scale_drho, std::abs(ref_drho[i]));
    scale_a = std::max(scale_a, (ref_a[i] - p.gravity).norm());
    err_drho = std::max(err_drho, std::abs(drho[i] - ref_drho[i]));
    err_a = std::max(err_a, (a[i] - ref_a[i]).norm());
  }
  REQUIRE(fluid == std::size_t(std::pow(n, D)));
  REQUIRE(scale_drho > 0);
  REQUIRE(scale_a > 0);
  INFO("D = " << D << ", riemann " << riemann << ", no-slip " << no_slip << ", skin " << skin
              << ", pairs once " << pairs_once << ": |drho| max " << scale_drho << ", err " << err_drho
              << "; |a - g| max " << scale_a << ", err " << err_a);
  CHECK(err_drho <= 1e-12 * scale_drho);
  CHECK(err_a <= 1e-12 * scale_a);
}

}  // namespace

TEST_CASE(
    "wcsph pair forces: the fused pass equals continuity + momentum + viscosity to round-off, each pair once "
    "too") {
  for (bool pairs_once : {false, true})
    for (bool no_slip : {true, false})
      for (double skin : {0.0, 0.004}) {
        check_fused_matches_reference<2>(no_slip, skin, pairs_once);
        check_fused_matches_reference<3>(no_slip, skin, pairs_once);
      }
}

TEST_CASE(
    "wcsph pair forces: the Riemann dissipation (Zhang, Hu & Adams) as the paper writes it, each pair once "
    "too") {
  for (bool pairs_once : {false, true}) {
    check_fused_matches_reference<2>(true, 0.0, pairs_once, true);
    check_fused_matches_reference<3>(true, 0.004, pairs_once, true);
  }
}
