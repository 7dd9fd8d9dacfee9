// Kernels: normalisation (radial Gauss-Legendre quadrature per piece, to 1e-6), gradient
// against a central finite difference, compact support, continuity at the piece joints.
#include "kernels/kernel.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "test_util.hpp"

using namespace ryushi;

namespace {

// 20-point Gauss-Legendre on [a, b], composite over n panels.
template <class F>
double integrate(F f, double a, double b, int panels = 64) {
  static const double x[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195, 0.5108670019508271,
                               0.6360536807265150, 0.7463319064601508, 0.8391169718222188, 0.9122344282513259,
                               0.9639719272779138, 0.9931285991850949};
  static const double w[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183820, 0.1316886384491766,
                               0.1181945319615184, 0.1019301198172404, 0.0832767415767048, 0.0626720483341091,
                               0.0406014298003869, 0.0176140071391521};
  double sum = 0, hpan = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    double m = a + (p + 0.5) * hpan, r = 0.5 * hpan;
    for (int k = 0; k < 10; ++k) sum += w[k] * r * (f(m - r * x[k]) + f(m + r * x[k]));
  }
  return sum;
}

// Radii where the piecewise definition changes (in units of h).
std::vector<double> joints(KernelType t) {
  switch (t) {
    case KernelType::CubicSpline:
      return {1.0};
    case KernelType::QuinticSpline:
      return {1.0, 2.0};
    default:
      return {};
  }
}

template <int D>
void check_kernel(KernelType type) {
  const double h = 0.37;
  Kernel<D> k(type, h);
  const double R = k.support();
  auto shell = [&](double r) {
    return k.w(r) * (D == 2 ? 2 * std::numbers::pi * r : 4 * std::numbers::pi * r * r);
  };
  // Integrate piece by piece so the quadrature never straddles a kink.
  std::vector<double> cuts{0.0};
  for (double j : joints(type)) cuts.push_back(j * h);
  cuts.push_back(R);
  double total = 0;
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) total += integrate(shell, cuts[p], cuts[p + 1]);
  CHECK_MESSAGE(std::abs(total - 1.0) < 1e-6, "normalisation " << total);

  for (double q = 0.05; q < 0.999 * k.support_factor(); q += 0.0731) {
    const double r = q * h, eps = 1e-6 * h;
    const double fd = (k.w(r + eps) - k.w(r - eps)) / (2 * eps);
    CHECK_MESSAGE(k.grad_factor(r) * r == doctest::Approx(fd).epsilon(1e-6).scale(k.w(0.05 * h) / h),
                  "dW/dr at q = " << q);
  }
  // Exactly zero beyond the support (at R itself q = R/h may round a hair below the cut-off).
  CHECK(k.w(R * (1 + 1e-12)) == 0.0);
  CHECK(std::abs(k.w(R)) < 1e-12 * k.w(0.5 * h));
  CHECK(k.w(1.5 * R) == 0.0);
  CHECK(k.grad_factor(R * (1 + 1e-12)) == 0.0);
  CHECK(k.grad_factor(R * 1.01) == 0.0);
  CHECK(k.w(0.999999 * R) < 1e-6 * k.w(0.5 * R) + (type == KernelType::Mps ? 1e-5 * k.w(0.5 * R) : 0.0));
  for (double j : joints(type)) {
    const double eps = 1e-9 * h;
    // Relative: at the quintic's joint q = 2 w is 0.05 (h = 0.37), where Approx's 1e-7 is 2e-6.
    CHECK_MESSAGE(test::within_relative(k.w(j * h - eps), k.w(j * h + eps), 1e-7), "w at q = " << j);
    CHECK_MESSAGE(test::within_relative(k.grad_factor(j * h - eps), k.grad_factor(j * h + eps), 1e-6),
                  "grad_factor at q = " << j);
  }
}

}  // namespace

TEST_CASE("kernels: normalised, differentiable, compact, continuous at joints (2D and 3D)") {
  for (const auto& name : kernel_names()) {
    CAPTURE(name);
    check_kernel<2>(kernel_from_name(name));
    check_kernel<3>(kernel_from_name(name));
  }
  CHECK_THROWS_AS(kernel_from_name("gaussian"), std::invalid_argument);
}

// Pointwise values against the kernels' formulas, written out here (the normalisation test alone
// passes a wrong but normalised shape): W(0) and W at the joints, with h = 0.3.
TEST_CASE("kernels: W(0) and W at the joints match the published formulas (2D and 3D)") {
  const double h = 0.3, pi = std::numbers::pi, h2 = h * h, h3 = h * h * h;
  struct Point {
    KernelType type;
    int dimension;
    double r, expected;
  };
  const Point points[] = {
      // cubic spline (seed 002 eq. 11): sigma (1 - 3/2 q^2 + 3/4 q^3) for q < 1, sigma/4 (2 - q)^3 to 2
      {KernelType::CubicSpline, 2, 0.0, 10 / (7 * pi * h2)},
      {KernelType::CubicSpline, 2, h, 10 / (7 * pi * h2) * 0.25},
      {KernelType::CubicSpline, 3, 0.0, 1 / (pi * h3)},
      {KernelType::CubicSpline, 3, h, 1 / (pi * h3) * 0.25},
      {KernelType::CubicSpline, 3, 1.5 * h, 1 / (pi * h3) * 0.25 * 0.125},
      // quintic spline (Morris 1997): sigma ((3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5), 7/(478 pi h^2), 1/(120 pi
      // h^3)
      {KernelType::QuinticSpline, 2, 0.0, 7 / (478 * pi * h2) * (243 - 6 * 32 + 15)},
      {KernelType::QuinticSpline, 2, h, 7 / (478 * pi * h2) * (32 - 6)},
      {KernelType::QuinticSpline, 2, 2 * h, 7 / (478 * pi * h2)},
      {KernelType::QuinticSpline, 3, h, 1 / (120 * pi * h3) * 26},
      // Wendland C2: sigma (1 - q/2)^4 (2q + 1), 7/(4 pi h^2), 21/(16 pi h^3)
      {KernelType::WendlandC2, 2, 0.0, 7 / (4 * pi * h2)},
      {KernelType::WendlandC2, 2, h, 7 / (4 * pi * h2) * 3 / 16},
      {KernelType::WendlandC2, 3, h, 21 / (16 * pi * h3) * 3 / 16},
      // spiky (shallow-water paper eq. 8): sigma (2 - q)^3, 5/(16 pi h^2), 15/(64 pi h^3)
      {KernelType::Spiky, 2, 0.0, 5 / (16 * pi * h2) * 8},
      {KernelType::Spiky, 3, h, 15 / (64 * pi * h3)},
      // MPS weight (MPS paper eq. 5): sigma (h/r - 1), 1/(pi h^2), 3/(2 pi h^3)
      {KernelType::Mps, 2, 0.5 * h, 1 / (pi * h2)},
      {KernelType::Mps, 3, 0.25 * h, 3 / (2 * pi * h3) * 3},
  };
  for (auto& p : points) {
    double w = p.dimension == 2 ? Kernel<2>(p.type, h).w(p.r) : Kernel<3>(p.type, h).w(p.r);
    CAPTURE(static_cast<int>(p.type));
    CAPTURE(p.dimension);
    CAPTURE(p.r);
    CHECK(std::abs(w / p.expected - 1) < 1e-12);
  }
}

TEST_CASE(
    "kernels: the Wendland sum of an array of squared distances is the sum of w, and zero past the support") {
  // MPS's smooth source density sums the Wendland kernel over each narrowed row in one loop
  // (wendland_sum); it must be the kernel's own values summed (to round-off), nothing from
  // beyond the support, and refuse another kernel.
  const double h = 0.0014;
  const Kernel<2> k(KernelType::WendlandC2, h);
  std::vector<double> squared;
  double expected = 0;
  for (int i = 1; i <= 300; ++i) {
    const double r = 2.4 * h * i / 300.0;  // to 1.2 times the support 2h
    squared.push_back(r * r);
    expected += k.w(r);
  }
  CHECK(k.wendland_sum(squared.data(), squared.size()) == doctest::Approx(expected).epsilon(1e-13));
  const std::vector<double> outside{4.0 * h * h, 5.0 * h * h, 100.0 * h * h};
  CHECK(k.wendland_sum(outside.data(), outside.size()) == 0.0);
  CHECK_THROWS_AS(Kernel<2>(KernelType::Mps, h).wendland_sum(squared.data(), 1), std::logic_error);
}

TEST_CASE("kernels: the MPS weights of an array of squared distances are w's values, bit for bit") {
  // The MPS systems compute their pair weights with mps_weights (vectorised) and keep them for
  // the pressure rows and the pressure gradient: those must see exactly what w gives, inside r_e,
  // at it and beyond it, so that a run is the same whichever path computed a weight.
  const double re = 0.0031;
  const Kernel<2> k(KernelType::Mps, re);
  std::vector<double> r;
  for (int i = 1; i <= 400; ++i) r.push_back(re * i / 300.0);  // to 1.33 r_e
  r.push_back(re);
  r.push_back(std::nextafter(re, 0.0));
  std::vector<double> squared(r.size()), weights(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) squared[i] = r[i] * r[i];
  k.mps_weights(squared.data(), weights.data(), squared.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    CAPTURE(r[i]);
    CHECK(weights[i] == k.w(std::sqrt(squared[i])));
    if (r[i] < 0.99 * re) CHECK(weights[i] > 0);
    if (r[i] > 1.001 * re) CHECK(weights[i] == 0);  // at r_e itself sqrt(r^2) may round below it
  }
  k.mps_weights(squared.data(), squared.data(), squared.size());  // in place, as the systems do
  CHECK(squared == weights);
  CHECK_THROWS_AS(Kernel<2>(KernelType::CubicSpline, re).mps_weights(squared.data(), weights.data(), 1),
                  std::logic_error);
}
