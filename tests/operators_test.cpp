// Operators: exactness where theory says so, the documented fallback, and the patch tests of the
// V&V paper (section 3) with their convergence orders.
#include <doctest/doctest.h>

#include <random>

#include "systems/neighbour/neighbour_search.hpp"
#include "systems/operators/divergence.hpp"
#include "systems/operators/gradient.hpp"
#include "systems/operators/laplacian.hpp"
#include "systems/operators/mps_reference.hpp"
#include "systems/operators/second_derivatives.hpp"
#include "verification/patch_test.hpp"

using namespace ryushi;

namespace {

// A 20%-disordered lattice in [0, 1]^D with spacing d, and its neighbour list.
template <int D>
struct Cloud {
  std::vector<Vec<D>> x;
  std::vector<double> volume;
  NeighbourList nl;
  CellGrid<D> grid;
  Domain<D> domain;
  Kernel<D> kernel;
  Cloud(double d, double disorder, KernelType type = KernelType::WendlandC2, double ratio = 1.5)
      : kernel(type, ratio * d) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-disorder * d, disorder * d);
    long n = std::lround(1.0 / d), total = D == 2 ? n * n : n * n * n;
    for (long k = 0; k < total; ++k) {
      Vec<D> p;
      long rest = k;
      for (int a = 0; a < D; ++a) {
        p[a] = (rest % n + 0.5) * d + u(rng);
        rest /= n;
      }
      x.push_back(p);
    }
    volume.assign(x.size(), std::pow(d, D));
    domain.min.setConstant(-1.0);
    domain.max.setConstant(2.0);
    build_neighbour_list<D>(domain, kernel.support(), x, grid, nl);
  }
  ParticleView<D> view() const { return {x, volume, nl, kernel, domain}; }
  bool interior(std::size_t i) const {
    for (int a = 0; a < D; ++a)
      if (x[i][a] < kernel.support() || x[i][a] > 1 - kernel.support()) return false;
    return true;
  }
};

template <int D>
void check_exactness() {
  Cloud<D> c(D == 2 ? 0.05 : 0.1, 0.2);
  auto v = c.view();
  // f = a.x + 1/2 x^T H x with a fixed, non-trivial H.
  Vec<D> a;
  Mat<D> H;
  for (int p = 0; p < D; ++p) {
    a[p] = 0.3 + p;
    for (int q = 0; q < D; ++q) H(p, q) = (p == q ? 1.5 + p : 0.4 - 0.1 * (p + q));
  }
  std::vector<double> linear(c.x.size()), quadratic(c.x.size());
  std::vector<Vec<D>> field(c.x.size());
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    linear[i] = a.dot(c.x[i]);
    quadratic[i] = linear[i] + 0.5 * c.x[i].dot(H * c.x[i]);
    field[i] = H * c.x[i];  // divergence = trace H
  }
  std::size_t checked = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    if (!c.interior(i)) continue;
    ++checked;
    CHECK((gradient_corrected(v, linear, i) - a).norm() < 1e-10);
    CHECK(divergence_corrected(v, std::span<const Vec<D>>(field), i) == doctest::Approx(H.trace()).epsilon(1e-10));
    auto s = second_derivatives_sph2(v, quadratic, i);
    CHECK(s.corrected);
    CHECK((s.hessian - H).norm() < 1e-8 * H.norm());
    CHECK((s.gradient - (a + H * c.x[i])).norm() < 1e-8);
    CHECK(laplacian_corrected(v, quadratic, i) == doctest::Approx(H.trace()).epsilon(1e-8));
    // The weight forms the pressure equations assemble from (also off the interior).
    std::vector<double> w;
    CHECK(laplacian_weights_sph2(v, i, w));
    CHECK(std::abs(apply_weights(v, quadratic, i, w) - H.trace()) < 1e-8 * H.trace());
    std::vector<Vec<D>> g;
    gradient_weights_corrected(v, i, g);
    Vec<D> grad = Vec<D>::Zero();
    auto nb = c.nl.of(i);
    for (std::size_t k = 0; k < nb.size(); ++k) grad += g[k] * (linear[nb[k]] - linear[i]);
    CHECK((grad - a).norm() < 1e-10);
  }
  CHECK(checked > 10);
  // Near the boundary (a cut support) the weights still give the operators' values.
  std::vector<double> w;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    if (c.interior(i)) continue;
    laplacian_weights_sph2(v, i, w);
    CHECK(apply_weights(v, quadratic, i, w) ==
          doctest::Approx(second_derivatives_sph2(v, quadratic, i).hessian.trace()).scale(0).epsilon(1e-8));
  }
}

}  // namespace

TEST_CASE("operators: corrected gradient, divergence, Laplacian and SPH(2) are exact on 20%-disordered particles") {
  check_exactness<2>();
  check_exactness<3>();
}

// lambda0 is defined so that the MPS Laplacian of |x|^2 is 2d on the reference lattice (a check
// of the construction only). On 10%-disordered particles the operator is not consistent (its
// error does not vanish with l0): measured mean 4.11 (+2.8%) and RMS deviation 28% of 2d. The
// bounds (mean 5%, RMS 40%) catch a broken n0 or lambda0, which moves the mean by its own error.
TEST_CASE("operators: MPS Laplacian of |x|^2 is 2d on the reference lattice and on average on disordered particles") {
  for (double disorder : {0.0, 0.1}) {
    CAPTURE(disorder);
    Cloud<2> c(0.05, disorder, KernelType::Mps, 3.1);  // r_e = 3.1 l0
    auto v = c.view();
    auto ref = mps_reference<2>(c.kernel, 0.05);
    std::vector<double> f(c.x.size());
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = c.x[i].squaredNorm();
    double sum = 0, sum2 = 0;
    int n = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
      if (c.interior(i)) {
        double lap = laplacian_mps(v, f, i, ref.n0, ref.lambda0);
        if (disorder == 0) CHECK(std::abs(lap / 4.0 - 1) < 1e-10);
        sum += lap, sum2 += lap * lap, ++n;
      }
    REQUIRE(n > 50);
    double mean = sum / n, rms = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
    MESSAGE("disorder ", disorder, ": mean ", mean, ", RMS deviation ", rms / 4.0, " of 2d");
    CHECK(std::abs(mean / 4.0 - 1) < 0.05);
    CHECK(rms / 4.0 < (disorder == 0 ? 1e-9 : 0.4));
  }
}

TEST_CASE("operators: an ill-conditioned support falls back to the uncorrected operator") {
  // Two particles: M_i has rank 1, so L_i cannot be formed.
  std::vector<Vec<2>> x{Vec<2>(0.5, 0.5), Vec<2>(0.52, 0.5)};
  std::vector<double> volume{4e-4, 4e-4}, f{1.0, 2.0};
  Domain<2> dom;
  CellGrid<2> grid;
  NeighbourList nl;
  Kernel<2> kernel(KernelType::WendlandC2, 0.03);
  build_neighbour_list<2>(dom, kernel.support(), x, grid, nl);
  ParticleView<2> v{x, volume, nl, kernel, dom};
  bool corrected = true;
  CHECK(renormalisation(v, 0, &corrected) == Mat<2>::Identity());
  CHECK_FALSE(corrected);
  CHECK(gradient_corrected(v, f, 0) == gradient_standard(v, f, 0));
  CHECK(laplacian_corrected(v, f, 0) == laplacian_standard(v, f, 0));
  auto s = second_derivatives_sph2(v, f, 0);
  CHECK_FALSE(s.corrected);
  CHECK(s.hessian.trace() == doctest::Approx(laplacian_standard(v, f, 0)));
  CHECK(s.hessian.allFinite());
}

TEST_CASE("patch test 2D: SPH(2) and corrected operators converge, the standard Laplacian does not") {
  auto order = [](const std::string& op, double disorder) {
    PatchTestOptions o;
    o.op = op;
    o.disorder = disorder;
    auto r = run_patch_test(o);
    MESSAGE(op, " disorder ", disorder, ": order_interior=", r.order_interior, " order_boundary=", r.order_boundary);
    return r;
  };
  // 20% disorder costs SPH(2) some order: measured 1.71 (Laplacian) and 1.57 (mixed) against
  // 1.97 and 2.00 on the lattice (docs/operators.md). 1.3 is below both and above first order,
  // which a lost correction term would leave (test audit round three, issue 50, row 30).
  CHECK(order("laplacian-sph2", 0.0).order_interior >= 1.8);
  CHECK(order("laplacian-sph2", 0.2).order_interior >= 1.3);
  CHECK(order("mixed-sph2", 0.0).order_interior >= 1.8);
  CHECK(order("mixed-sph2", 0.2).order_interior >= 1.3);
  CHECK(order("gradient-corrected", 0.0).order_interior >= 1.8);
  CHECK(order("laplacian-corrected", 0.0).order_interior >= 1.8);
  // Standard Laplacian. With disorder its error grows as d shrinks (at 1/160 it is above its
  // value at 1/40). On a perfect lattice it stalls at a floor set by the kernel's lattice sums
  // (about 1.6% for Wendland C2 at h = 1.5 d, 2-5% for the other kernels tried): the last
  // halving of d gains less than a factor 2^0.4, where a second-order operator gains 4.
  auto disordered = order("laplacian-standard", 0.2).rows;
  CHECK(disordered.back().rmse_interior >= disordered[1].rmse_interior);
  auto regular = order("laplacian-standard", 0.0).rows;
  double last_order = std::log2(regular[2].rmse_interior / regular[3].rmse_interior);
  CHECK(last_order < 0.4);
}

TEST_CASE("patch test 3D: the same orders with the 3D Franke analogue at 1/20 ... 1/40") {
  auto order = [](const std::string& op, double disorder) {
    PatchTestOptions o;
    o.dimension = 3;
    o.op = op;
    o.disorder = disorder;
    double r = run_patch_test(o).order_interior;
    MESSAGE(op, " 3D disorder ", disorder, ": order_interior=", r);
    return r;
  };
  // Measured: SPH(2) Laplacian 2.00 regular and 1.99 disordered, mixed 1.92 and 1.85, corrected
  // gradient 1.94, corrected Laplacian 2.00 (issue 50, audit rows 30 and 40: docs/operators.md
  // says the corrected Laplacian's >= 1.8 is asserted in 3D too).
  CHECK(order("laplacian-sph2", 0.0) >= 1.8);
  CHECK(order("laplacian-sph2", 0.2) >= 1.3);
  CHECK(order("mixed-sph2", 0.0) >= 1.8);
  CHECK(order("mixed-sph2", 0.2) >= 1.3);
  CHECK(order("gradient-corrected", 0.0) >= 1.8);
  CHECK(order("laplacian-corrected", 0.0) >= 1.8);
}

TEST_CASE("patch test: an unknown operator is refused and the order fit is exact on a clean power law") {
  PatchTestOptions o;
  o.op = "no-such-operator";
  CHECK_THROWS_AS(run_patch_test(o), std::invalid_argument);
  CHECK(least_squares_order({0.1, 0.05, 0.025}, {1e-2, 2.5e-3, 6.25e-4}) == doctest::Approx(2.0));
}

// ISPH's hybrid gradient asks for the corrected gradient only where det M_i reaches a bound. On
// the disordered cloud the interior reaches 0.8 and gets the exact gradient of a linear field; a
// particle at the cloud's corner has a quarter of a support (det M_i far below 0.8) and gets
// nothing, so the corrector takes the symmetric form there.
TEST_CASE(
    "operators: the corrected gradient where det M_i reaches a bound, nothing where the support is cut") {
  Cloud<2> c(0.05, 0.2);
  auto v = c.view();
  std::vector<double> linear(c.x.size());
  for (std::size_t i = 0; i < c.x.size(); ++i) linear[i] = 0.3 * c.x[i][0] - 1.7 * c.x[i][1];
  std::size_t interior = 0, cut = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    const double det = moment_matrix(gathered_stencil(v, i)).determinant();
    auto g = gradient_corrected_where(v, linear, i, 0.8);
    CHECK(g.has_value() == (det >= 0.8));
    if (c.interior(i)) {
      ++interior;
      REQUIRE(g.has_value());
      CHECK((*g - Vec<2>(0.3, -1.7)).norm() < 1e-10);
    }
    if (!g) {
      ++cut;
      CHECK_FALSE(c.interior(i));
    }
  }
  MESSAGE(interior, " interior particles, ", cut, " with a support too cut for the corrected form");
  CHECK(interior > 100);
  CHECK(cut > 0);
  const std::size_t corner = 0;  // the lattice's first point, at (d/2, d/2) before the disorder
  CHECK_FALSE(gradient_corrected_where(v, linear, corner, 0.8).has_value());
}
