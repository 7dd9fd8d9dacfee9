#include "verification/free_surface_check.hpp"

#include <tbb/parallel_for.h>

#include <functional>
#include <random>
#include <stdexcept>

#include "ecs/lattice.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/neighbour/neighbour_search.hpp"

namespace ryushi {

const std::vector<std::string>& free_surface_shapes() {
  static const std::vector<std::string> s{"square", "disc", "square_with_hole", "column", "cube"};
  return s;
}

namespace {

enum Site { kEmpty, kFluidSite, kWallSite };

template <int D>
FreeSurfaceScore score(const std::string& shape, const std::function<Site(const Vec<D>&)>& site,
                       const std::string& rule_name, double disorder, unsigned seed, double d, double beta) {
  const auto rule = free_surface_rule(rule_name);
  const long n = std::lround(1.4 / d);  // lattice over [-0.2, 1.2]^D
  std::vector<Vec<D>> x;
  std::vector<int> kind;
  std::vector<char> outer;  // 2 outer, 1 ambiguous, 0 interior
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0, 1);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::array<long, D> lo{}, hi;
  hi.fill(n);
  for_each_lattice_point<D>(Vec<D>::Constant(-0.2), d, lo, hi, [&](Vec<D> p) {
    Site s = site(p);
    if (s == kEmpty) return;
    // 2: an axial lattice neighbour is empty (outer layer); 1: only a diagonal one (a corner of
    // a staircase boundary, not scored); 0: none (interior).
    char edge = 0;
    for (int o = 0; o < (D == 2 ? 9 : 27) && s == kFluidSite; ++o) {
      Vec<D> q = p;
      int rest = o, moved = 0;
      for (int a = 0; a < D; ++a) {
        int step = rest % 3 - 1;
        q[a] += step * d;
        moved += step != 0;
        rest /= 3;
      }
      if (moved > 0 && site(q) == kEmpty) edge = std::max<char>(edge, moved == 1 ? 2 : 1);
    }
    if (disorder > 0 && s == kFluidSite) {
      Vec<D> dir;
      for (int a = 0; a < D; ++a) dir[a] = normal(rng);
      p += dir.normalized() * (disorder * d * uniform(rng));
    }
    x.push_back(p);
    kind.push_back(s == kFluidSite ? kFluid : kWall);
    outer.push_back(edge);
  });
  std::vector<double> volume(x.size(), std::pow(d, D));
  // SPH rules use Wendland C2 at h = 1.5 d; the MPS rule its own weight with r_e = 2.1 l0, the
  // radius its beta = 0.97 was set for (Koshizuka & Oka 1996).
  Kernel<D> kernel = rule == FreeSurfaceRule::Mps ? Kernel<D>(KernelType::Mps, 2.1 * d)
                                                  : Kernel<D>(KernelType::WendlandC2, 1.5 * d);
  Domain<D> domain;
  domain.min.setConstant(-0.5);
  domain.max.setConstant(1.5);
  CellGrid<D> grid;
  NeighbourList nl;
  build_neighbour_list<D>(domain, kernel.support(), x, grid, nl);
  ParticleView<D> view{x, volume, nl, kernel, domain};
  FreeSurfaceParameters params;
  params.beta = beta;
  const double n0 = mps_reference<D>(kernel, d).n0;
  std::vector<char> flagged(x.size(), 0);
  tbb::parallel_for(std::size_t(0), x.size(), [&](std::size_t i) {
    if (kind[i] == kFluid) flagged[i] = detect_free_surface(view, i, rule, params, n0).surface;
  });
  FreeSurfaceScore sc{shape};
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (kind[i] != kFluid || outer[i] == 1) continue;
    if (outer[i] == 2) {
      ++sc.outer;
      sc.outer_flagged += flagged[i];
    } else {
      ++sc.interior;
      sc.interior_flagged += flagged[i];
    }
  }
  return sc;
}

}  // namespace

FreeSurfaceScore score_free_surface(const std::string& shape, const std::string& rule, double disorder,
                                    unsigned seed, double d, double beta) {
  auto in_box = [](const auto& p, double lo, double hi) {
    for (int a = 0; a < p.size(); ++a)
      if (p[a] < lo || p[a] > hi) return false;
    return true;
  };
  if (shape == "square")
    return score<2>(shape, [&](const Vec<2>& p) { return in_box(p, 0.2, 0.8) ? kFluidSite : kEmpty; }, rule, disorder, seed, d, beta);
  if (shape == "disc")
    return score<2>(shape, [](const Vec<2>& p) { return (p - Vec<2>(0.5, 0.5)).norm() < 0.3 ? kFluidSite : kEmpty; },
                    rule, disorder, seed, d, beta);
  if (shape == "square_with_hole")
    return score<2>(shape, [&](const Vec<2>& p) {
      return in_box(p, 0.15, 0.85) && (p - Vec<2>(0.5, 0.5)).norm() > 0.15 ? kFluidSite : kEmpty;
    }, rule, disorder, seed, d, beta);
  if (shape == "column")  // a dam-break column against a wall (x < 0) on a floor (y < 0)
    return score<2>(shape, [d](const Vec<2>& p) {
      bool wall = (p[0] < 0 && p[0] > -3 * d && p[1] < 1.0) || (p[1] < 0 && p[1] > -3 * d && p[0] > -3 * d && p[0] < 1.0);
      if (wall) return kWallSite;
      return p[0] > 0 && p[0] < 0.4 && p[1] > 0 && p[1] < 0.8 ? kFluidSite : kEmpty;
    }, rule, disorder, seed, d, beta);
  if (shape == "cube")
    return score<3>(shape, [&](const Vec<3>& p) { return in_box(p, 0.3, 0.7) ? kFluidSite : kEmpty; }, rule,
                    disorder, seed, 2 * d, beta);
  throw std::invalid_argument("unknown shape '" + shape + "'");
}

}  // namespace ryushi
