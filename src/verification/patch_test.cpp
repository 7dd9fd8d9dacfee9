#include "verification/patch_test.hpp"

#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>

#include "ecs/lattice.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/operators/divergence.hpp"
#include "systems/operators/gradient.hpp"
#include "systems/operators/laplacian.hpp"
#include "systems/operators/mps_reference.hpp"
#include "systems/operators/second_derivatives.hpp"
#include "verification/franke.hpp"

namespace ryushi {

const std::vector<std::string>& patch_test_operators() {
  static const std::vector<std::string> ops{
      "gradient-standard",   "gradient-symmetric",   "gradient-corrected",  "gradient-sph2", "gradient-mps",
      "divergence-standard", "divergence-corrected", "laplacian-standard", "laplacian-corrected",
      "laplacian-sph2",      "laplacian-mps",        "mixed-sph2"};
  return ops;
}

double least_squares_order(const std::vector<double>& d, const std::vector<double>& e) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (!(e[k] > 0)) continue;
    double x = std::log(d[k]), y = std::log(e[k]);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return n < 2 ? 0.0 : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

namespace {

// An operator result has up to D components; exact and approximate values are compared as
// vectors (scalar results in component 0, the others left zero).
template <int D>
using Evaluate = std::function<void(const ParticleView<D>&, std::size_t, Vec<D>& approx, Vec<D>& exact)>;

template <int D>
Evaluate<D> make_operator(const std::string& op, std::span<const double> f, std::span<const Vec<D>> u,
                          const std::vector<FrankeValue<D>>& exact, const MpsReference& mps) {
  auto scalar = [](double a, double e, Vec<D>& approx, Vec<D>& ex) {
    approx[0] = a;
    ex[0] = e;
  };
  if (op == "gradient-standard" || op == "gradient-symmetric" || op == "gradient-corrected" ||
      op == "gradient-sph2" || op == "gradient-mps")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      if (op == "gradient-standard") a = gradient_standard(v, f, i);
      else if (op == "gradient-symmetric") a = gradient_symmetric(v, f, i);
      else if (op == "gradient-corrected") a = gradient_corrected(v, f, i);
      else if (op == "gradient-sph2") a = second_derivatives_sph2(v, f, i).gradient;
      else a = gradient_mps(v, f, i, mps.n0);
      e = exact[i].gradient;
    };
  if (op == "divergence-standard")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      scalar(divergence_standard(v, u, i), exact[i].hessian.trace(), a, e);
    };
  if (op == "divergence-corrected")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      scalar(divergence_corrected(v, u, i), exact[i].hessian.trace(), a, e);
    };
  if (op == "laplacian-standard")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      scalar(laplacian_standard(v, f, i), exact[i].hessian.trace(), a, e);
    };
  if (op == "laplacian-corrected")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      scalar(laplacian_corrected(v, f, i), exact[i].hessian.trace(), a, e);
    };
  if (op == "laplacian-sph2")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      scalar(second_derivatives_sph2(v, f, i).hessian.trace(), exact[i].hessian.trace(), a, e);
    };
  if (op == "laplacian-mps")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      scalar(laplacian_mps(v, f, i, mps.n0, mps.lambda0), exact[i].hessian.trace(), a, e);
    };
  if (op == "mixed-sph2")
    return [=, &exact](const ParticleView<D>& v, std::size_t i, Vec<D>& a, Vec<D>& e) {
      scalar(second_derivatives_sph2(v, f, i).hessian(0, 1), exact[i].hessian(0, 1), a, e);
    };
  std::string list;
  for (auto& o : patch_test_operators()) list += (list.empty() ? "" : ", ") + o;
  throw std::invalid_argument("unknown operator '" + op + "'; available: " + list);
}

template <int D>
PatchTestRow run_one(const PatchTestOptions& o, double d) {
  const long n = std::lround(1.0 / d);
  std::mt19937 rng(o.seed + static_cast<unsigned>(n));
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec<D>> x;
  std::array<long, D> lo{}, hi;
  hi.fill(n);
  for_each_lattice_point<D>(Vec<D>::Zero(), d, lo, hi, [&](Vec<D> p) {
    if (o.disorder > 0) {  // a random direction, a length uniform in [0, disorder d]
      Vec<D> dir;
      for (int a = 0; a < D; ++a) dir[a] = normal(rng);
      p += dir.normalized() * (o.disorder * d * uniform(rng));
    }
    x.push_back(p);
  });
  std::vector<double> volume(x.size(), std::pow(d, D)), f(x.size());
  std::vector<Vec<D>> u(x.size());
  std::vector<FrankeValue<D>> exact(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    exact[i] = franke<D>(x[i]);
    f[i] = exact[i].value;
    u[i] = exact[i].gradient;
  }
  Kernel<D> kernel(kernel_from_name(o.kernel), o.smoothing_ratio * d);
  Domain<D> domain;
  domain.min.setConstant(-kernel.support());
  domain.max.setConstant(1.0 + kernel.support());
  CellGrid<D> grid;
  NeighbourList nl;
  build_neighbour_list<D>(domain, kernel.support(), x, grid, nl);
  ParticleView<D> view{x, volume, nl, kernel, domain};
  auto mps = mps_reference<D>(kernel, d);
  auto evaluate = make_operator<D>(o.op, f, u, exact, mps);

  std::vector<Vec<D>> approx(x.size()), truth(x.size());
  auto t0 = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, x.size(), 512), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      approx[i].setZero();
      truth[i].setZero();
      evaluate(view, i, approx[i], truth[i]);  // scalars use component 0; the rest stay zero
    }
  });
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double num[2] = {0, 0}, den[2] = {0, 0};
  std::size_t count[2] = {0, 0};
  const double R = kernel.support();
  for (std::size_t i = 0; i < x.size(); ++i) {
    bool cut = false;
    for (int a = 0; a < D; ++a) cut = cut || x[i][a] < R || x[i][a] > 1.0 - R;
    num[cut] += (approx[i] - truth[i]).squaredNorm();
    den[cut] += truth[i].squaredNorm();
    ++count[cut];
  }
  auto rmse = [&](int k) { return den[k] > 0 ? std::sqrt(num[k] / den[k]) : 0.0; };
  return {d, count[0], count[1], rmse(0), rmse(1), seconds};
}

}  // namespace

PatchTestResult run_patch_test(const PatchTestOptions& options) {
  PatchTestOptions o = options;
  if (o.dimension != 2 && o.dimension != 3) throw std::invalid_argument("--dim must be 2 or 3");
  if (!(o.disorder >= 0 && o.disorder < 0.5)) throw std::invalid_argument("--disorder must be in [0, 0.5)");
  kernel_from_name(o.kernel);  // throws for an unknown kernel
  if (o.spacings.empty())
    o.spacings = o.dimension == 2 ? std::vector<double>{1.0 / 20, 1.0 / 40, 1.0 / 80, 1.0 / 160}
                                  : std::vector<double>{1.0 / 20, 1.0 / 30, 1.0 / 40};
  PatchTestResult result;
  std::vector<double> d, ei, eb;
  for (double s : o.spacings) {
    auto row = o.dimension == 2 ? run_one<2>(o, s) : run_one<3>(o, s);
    result.rows.push_back(row);
    d.push_back(s);
    ei.push_back(row.rmse_interior);
    eb.push_back(row.rmse_boundary);
  }
  result.order_interior = least_squares_order(d, ei);
  result.order_boundary = least_squares_order(d, eb);
  return result;
}

}  // namespace ryushi
