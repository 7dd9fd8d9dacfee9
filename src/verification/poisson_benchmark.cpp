#include "verification/poisson_benchmark.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <tuple>

#include "ecs/lattice.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/operators/mps_reference.hpp"

namespace ryushi {

namespace {

template <int D>
PoissonProblem build(int n, unsigned seed, double jitter) {
  const double l0 = 1.0 / n, re = (D == 2 ? 3.1 : 2.1) * l0;
  const double pi = std::numbers::pi;
  auto source = [&](const Vec<D>& x) {
    double s = 1;
    for (int a = 0; a < D; ++a) s *= std::sin(2 * pi * x[a]);
    return s;
  };
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * l0, jitter * l0);
  std::vector<Vec<D>> x;
  std::vector<char> unknown;
  std::array<long, D> lo, hi;  // two Dirichlet layers on every side
  lo.fill(-2);
  hi.fill(n + 2);
  for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& k) {
    bool inside = true;
    Vec<D> p;
    for (int a = 0; a < D; ++a) {
      inside = inside && k[a] >= 0 && k[a] < n;
      p[a] = (k[a] + 0.5) * l0;
    }
    for (int a = 0; a < D; ++a) p[a] += u(rng);
    x.push_back(p);
    unknown.push_back(inside);
  });
  Kernel<D> w(KernelType::Mps, re);
  auto ref = mps_reference<D>(w, l0);
  const double coeff = 2.0 * D / (ref.lambda0 * ref.n0);
  Domain<D> domain;
  domain.min.setConstant(-1.0);
  domain.max.setConstant(2.0);
  CellGrid<D> grid;
  NeighbourList nl;
  build_neighbour_list<D>(domain, re, x, grid, nl);

  PoissonProblem P;
  P.dimension = D;
  P.spacing = l0;
  P.influence_radius = re;
  std::vector<std::uint32_t> row_of(x.size(), UINT32_MAX);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (unknown[i]) {
      row_of[i] = static_cast<std::uint32_t>(P.b.size());
      P.b.push_back(0);
      double e = source(x[i]) / (4 * pi * pi * D);
      P.exact.push_back(e);
      for (int a = 0; a < D; ++a) P.coordinates.push_back(x[i][a]);
    }
  std::vector<std::tuple<std::uint32_t, std::uint32_t, double>> t;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!unknown[i]) continue;
    const auto r = row_of[i];
    double diag = 0;
    P.b[r] = source(x[i]);
    for (auto j : nl.of(i)) {
      double wij = coeff * w.w((x[j] - x[i]).norm());
      diag += wij;
      if (unknown[j])
        t.emplace_back(r, row_of[j], -wij);
      else
        P.b[r] += wij * source(x[j]) / (4 * pi * pi * D);  // Dirichlet value moved to the right-hand side
    }
    t.emplace_back(r, r, diag);
  }
  P.A = solvers::csr_from_triplets<double>(P.b.size(), P.b.size(), std::move(t));
  return P;
}

}  // namespace

PoissonProblem mps_poisson_problem(int dimension, int n, unsigned seed, double jitter) {
  return dimension == 2 ? build<2>(n, seed, jitter) : build<3>(n, seed, jitter);
}

}  // namespace ryushi
