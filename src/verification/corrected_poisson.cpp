#include "verification/corrected_poisson.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <tuple>

#include "systems/neighbour/neighbour_search.hpp"
#include "systems/operators/gradient.hpp"
#include "systems/operators/laplacian.hpp"

namespace ryushi {

CorrectedPoissonProblem corrected_poisson_problem(int n, unsigned seed) {
  const double pi = std::numbers::pi, d = 1.0 / n;
  auto phi = [&](const Vec<2>& x) { return std::sin(pi * x[0]) * std::cos(pi * x[1]) + x[0] * x[1]; };
  auto source = [&](const Vec<2>& x) { return 2 * pi * pi * std::sin(pi * x[0]) * std::cos(pi * x[1]); };
  auto dphi_dy = [&](const Vec<2>& x) { return -pi * std::sin(pi * x[0]) * std::sin(pi * x[1]) + x[0]; };
  enum Role { kUnknown, kWallRow, kDirichlet };
  std::vector<Vec<2>> x;
  std::vector<Role> role;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2 * d, 0.2 * d);
  const int layers = 3;  // Dirichlet ghosts cover the 3 d support
  for (int i = -layers; i < n + layers; ++i)
    for (int j = -1; j < n + layers; ++j) {
      Vec<2> p((i + 0.5) * d, (j + 0.5) * d);
      bool inside_x = i >= 0 && i < n;
      Role r = kDirichlet;
      if (inside_x && j >= 0 && j < n) {
        r = kUnknown;
        p += Vec<2>(jitter(rng), jitter(rng));
      } else if (inside_x && j == -1) {
        r = kWallRow;  // one layer of wall particles just below y = 0
      }
      x.push_back(p);
      role.push_back(r);
    }
  std::vector<double> volume(x.size(), d * d);
  Domain<2> domain;
  domain.min.setConstant(-1);
  domain.max.setConstant(2);
  CellGrid<2> grid;
  NeighbourList nl;
  Kernel<2> kernel(KernelType::WendlandC2, 1.5 * d);
  build_neighbour_list<2>(domain, kernel.support(), x, grid, nl);
  ParticleView<2> view{x, volume, nl, kernel, domain};

  CorrectedPoissonProblem P;
  P.spacing = d;
  P.coupling_radius = kernel.support();
  std::vector<std::uint32_t> row(x.size(), UINT32_MAX);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (role[i] != kDirichlet) {
      row[i] = static_cast<std::uint32_t>(P.b.size());
      P.b.push_back(0);
      P.exact.push_back(phi(x[i]));
      P.coordinates.push_back(x[i][0]);
      P.coordinates.push_back(x[i][1]);
      P.wall_rows += role[i] == kWallRow;
    }
  std::vector<std::tuple<std::uint32_t, std::uint32_t, double>> t;
  std::vector<double> unit(x.size(), 0.0);
  const Vec<2> normal(0, -1);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (role[i] == kDirichlet) continue;
    std::vector<std::uint32_t> support(nl.of(i).begin(), nl.of(i).end());
    support.push_back(static_cast<std::uint32_t>(i));
    // Wall rows are scaled by 1/d so that they weigh like the Laplacian rows (1/d^2).
    const bool wall = role[i] == kWallRow;
    double rhs = wall ? normal.dot(Vec<2>(0, dphi_dy(x[i]))) / d : source(x[i]);
    for (auto j : support) {
      unit[j] = 1.0;
      double c = wall ? normal.dot(gradient_corrected(view, unit, i)) / d : -laplacian_corrected(view, unit, i);
      unit[j] = 0.0;
      if (c == 0) continue;
      if (role[j] == kDirichlet)
        rhs -= c * phi(x[j]);
      else
        t.emplace_back(row[i], row[j], c);
    }
    P.b[row[i]] = rhs;
  }
  P.A = solvers::csr_from_triplets<double>(P.b.size(), P.b.size(), std::move(t));
  return P;
}

}  // namespace ryushi
