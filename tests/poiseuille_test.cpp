// Poiseuille flow in a 2D channel under Eulerian ISPH (ISPH paper section 6(1); issue 8 test 1):
// water between walls l = 1 mm apart, a pressure drop of 1 Pa over L = 2 mm held by the
// [[fixed_pressure]] inlet and outlet, from rest. The pressure is linear from the first step, so
// the flow is the start-up of Morris, Fox & Zhu (1997, eq. 21) with the body force
// F = dp / (rho L) = 0.5 m/s^2:
//   u(y, t) = F/(2 nu) y (l - y) - sum_n 4 F l^2 / (nu pi^3 (2n+1)^3) sin((2n+1) pi y / l)
//                                        exp(-(2n+1)^2 pi^2 nu t / l^2),
// computed here. Asserted at l/d = 10, 16 and 20 (the paper's 16 and 20; its 50 is in docs/isph.md):
// the profile across the channel's middle within 1% (L2, relative to the centreline speed) of
// the series at t = 0.05 and 0.1 s (the start-up) and at 0.5 s (the paper's time, 0.7% short of
// steady), and the error falling with resolution at each time at order 1.5 or better.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

constexpr double kWidth = 1e-3, kLength = 2e-3, kNu = 1e-6, kForce = 1.0 / (1000 * kLength);

double morris(double y, double t) {
  const double pi = std::numbers::pi;
  double u = kForce / (2 * kNu) * y * (kWidth - y);
  for (int n = 0; n < 200; ++n) {
    const double k = 2 * n + 1;
    u -= 4 * kForce * kWidth * kWidth / (kNu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / kWidth) *
         std::exp(-k * k * pi * pi * kNu * t / (kWidth * kWidth));
  }
  return u;
}

// Runs a Poiseuille scene with the given overrides into a scratch folder; the frames at t = 0.05,
// 0.1 and 0.5 s (output every 0.05 s: frames 1, 2 and 10).
constexpr double kTimes[] = {0.05, 0.1, 0.5};
std::array<std::filesystem::path, 3> run_poiseuille(const std::string& scene, const std::string& name,
                                                    std::vector<std::string> sets) {
  auto dir = test::scratch(name);
  RunOptions opt;
  opt.scene = test::scene_path(scene);
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  opt.sets = std::move(sets);
  REQUIRE(run_scene(opt) == kExitDone);
  std::array<std::filesystem::path, 3> frames;
  const int numbers[] = {1, 2, 10};
  for (int k = 0; k < 3; ++k) frames[k] = test::frame_path(dir / "out", numbers[k]);
  return frames;
}

// scenes/poiseuille_isph_2d.toml at spacing d: the geometry moves with d (the wall particles stay
// on y = 0 and y = l, the buffers are three spacings long), set on the shipped scene.
std::vector<std::string> channel_at(double d) {
  const double b = 3 * d;
  auto vec = [](double x, double y) {
    char s[96];
    std::snprintf(s, sizeof s, "[%.9g, %.9g]", x, y);
    return std::string(s);
  };
  char spacing[48];
  std::snprintf(spacing, sizeof spacing, "particles.spacing=%.9g", d);  // std::to_string keeps 6 decimals
  return {spacing,
          "domain.min=" + vec(-b - 5e-4, -5e-4),
          "domain.max=" + vec(kLength + b + 5e-4, kWidth + 5e-4),
          "fluid.0.min=" + vec(-b, d / 2),
          "fluid.0.max=" + vec(kLength + b, kWidth - d / 2),
          "wall.0.min=" + vec(-b, d / 2),
          "wall.0.max=" + vec(kLength + b, kWidth - d / 2),
          "fixed_pressure.0.min=" + vec(-b, 0),
          "fixed_pressure.1.max=" + vec(kLength + b, kWidth)};
}

// L2 error of u across the column nearest x = L/2, relative to the series' centreline speed.
double profile_error(const std::filesystem::path& frame, double t) {
  auto x = test::read_dataset(frame, "position").values, v = test::read_dataset(frame, "velocity").values,
       kind = test::read_dataset(frame, "kind").values;
  double column = 1e9;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 0 && std::abs(x[3 * i] - kLength / 2) < std::abs(column - kLength / 2)) column = x[3 * i];
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 0 && std::abs(x[3 * i] - column) < 1e-12) {
      const double e = v[3 * i] - morris(x[3 * i + 1], t);
      sum += e * e, ++count;
    }
  REQUIRE(count > 5);
  return std::sqrt(sum / count) / morris(kWidth / 2, t);
}

}  // namespace

TEST_CASE("isph poiseuille: the Eulerian channel follows the Morris start-up and converges at l/d = 10, 16, 20") {
  std::vector<std::array<double, 3>> errors;
  for (int cells : {10, 16, 20}) {
    const auto frames =
        run_poiseuille("poiseuille_isph_2d.toml", "poiseuille_" + std::to_string(cells), channel_at(kWidth / cells));
    std::array<double, 3> e{};
    for (int k = 0; k < 3; ++k) {
      e[k] = profile_error(frames[k], kTimes[k]);
      CHECK(e[k] < 0.01);
    }
    MESSAGE("l/d = ", cells, ": L2 error against Morris at t = 0.05, 0.1, 0.5 s: ", 100 * e[0], "%, ",
            100 * e[1], "%, ", 100 * e[2], "%");
    errors.push_back(e);
  }
  // Converges at an order, not by any decrease (test audit round three, issue 50, row 39). The
  // corrected operators are second order on a lattice. Measured error ratios, l/d = 10 over 16 and
  // 16 over 20: 3.95 and 1.68 at 0.05 s, 3.51 and 1.92 at 0.1 s, 2.97 and 1.73 at 0.5 s (order
  // 2.3-2.9). Asserted: at least order 1.5 (a factor 2.8 per halving), i.e. (16/10)^1.5 = 2.02
  // and (20/16)^1.5 = 1.40; the closest, 1.68 against 1.40, is the finest step at 0.05 s.
  for (int k = 0; k < 3; ++k) {
    const double first = errors[0][k] / errors[1][k], second = errors[1][k] / errors[2][k];
    MESSAGE("t = ", kTimes[k], " s: error ratio l/d = 10 over 16 ", first, ", 16 over 20 ", second,
            " (first order: 1.6, 1.25)");
    CHECK(first >= std::pow(16.0 / 10, 1.5));
    CHECK(second >= std::pow(20.0 / 16, 1.5));
  }
}

// The 3D pipe (ISPH paper section 6(1), issue 8 test 1): radius R = l/2 = 0.5 mm, the same
// pressure drop, length and fluid. From rest the axial speed is the start-up series of
// Szymanski (1932), with F = dp / (rho L) and lambda_n the zeros of J0:
//   u(r, t) = F/(4 nu) (R^2 - r^2) - sum_n 2 F R^2 / nu J0(lambda_n r/R) / (lambda_n^3 J1(lambda_n))
//                                          exp(-lambda_n^2 nu t / R^2),
// which is 0 at t = 0 (the Fourier-Bessel series of 1 - (r/R)^2 has the coefficients 8 / (lambda^3 J1)).
namespace {

constexpr double kRadius = kWidth / 2;

double bessel_zero_j0(int n) {  // McMahon's estimate (n - 1/4) pi, then Newton (J0' = -J1)
  double x = (n - 0.25) * std::numbers::pi;
  for (int k = 0; k < 20; ++k) x += std::cyl_bessel_j(0.0, x) / std::cyl_bessel_j(1.0, x);
  return x;
}

double szymanski(double r, double t) {
  static const std::vector<double> zeros = [] {
    std::vector<double> z;
    for (int n = 1; n <= 200; ++n) z.push_back(bessel_zero_j0(n));
    return z;
  }();
  double u = kForce / (4 * kNu) * (kRadius * kRadius - r * r);
  for (double lambda : zeros) {
    u -= 2 * kForce * kRadius * kRadius / kNu * std::cyl_bessel_j(0.0, lambda * r / kRadius) /
         (lambda * lambda * lambda * std::cyl_bessel_j(1.0, lambda)) *
         std::exp(-lambda * lambda * kNu * t / (kRadius * kRadius));
  }
  return u;
}

// scenes/poiseuille_isph_3d.toml at spacing d: the pipe's wall ring stays at r = R (the
// container's radius R - d/2), the fluid block is the square around the section, the buffers
// are three spacings long and the domain along the axis is the pipe.
std::vector<std::string> pipe_at(double d) {
  const double b = 3 * d;
  auto vec = [](double x, double y, double z) {
    char s[128];
    std::snprintf(s, sizeof s, "[%.9g, %.9g, %.9g]", x, y, z);
    return std::string(s);
  };
  char spacing[48], radius[48];
  std::snprintf(spacing, sizeof spacing, "particles.spacing=%.9g", d);
  std::snprintf(radius, sizeof radius, "solid.0.radius=%.9g", kRadius - d / 2);
  return {spacing,
          radius,
          "domain.min=" + vec(-b, -2 * kRadius, -2 * kRadius),
          "domain.max=" + vec(kLength + b, 2 * kRadius, 2 * kRadius),
          "fluid.0.min=" + vec(-b, -kRadius, -kRadius),
          "fluid.0.max=" + vec(kLength + b, kRadius, kRadius),
          "fixed_pressure.0.min=" + vec(-b, -2 * kRadius, -2 * kRadius),
          "fixed_pressure.1.max=" + vec(kLength + b, 2 * kRadius, 2 * kRadius)};
}

// L2 error of u over the cross-section nearest x = L/2, relative to the series' centreline speed;
// also the largest velocity across the axis there (relative to the same), which should be nil.
std::pair<double, double> pipe_error(const std::filesystem::path& frame, double t) {
  auto x = test::read_dataset(frame, "position").values, v = test::read_dataset(frame, "velocity").values,
       kind = test::read_dataset(frame, "kind").values;
  double section = 1e9;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 0 && std::abs(x[3 * i] - kLength / 2) < std::abs(section - kLength / 2)) section = x[3 * i];
  double sum = 0, across = 0;
  int count = 0;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 0 && std::abs(x[3 * i] - section) < 1e-12) {
      const double e = v[3 * i] - szymanski(std::hypot(x[3 * i + 1], x[3 * i + 2]), t);
      sum += e * e, ++count;
      across = std::max(across, std::hypot(v[3 * i + 1], v[3 * i + 2]));
    }
  REQUIRE(count > 20);
  const double centre = szymanski(0, t);
  return {std::sqrt(sum / count) / centre, across / centre};
}

}  // namespace

TEST_CASE("isph poiseuille: the Eulerian 3D pipe follows the Bessel start-up and converges at l/d = 10, 16, 20") {
  // The series against its own limits: 0 at t = 0, the parabola once steady.
  CHECK(std::abs(szymanski(0.3 * kRadius, 0)) < 1e-7 * szymanski(0, 10));  // 200 terms: 3e-8 short
  CHECK(szymanski(0.3 * kRadius, 10) == doctest::Approx(kForce / (4 * kNu) * 0.91 * kRadius * kRadius).epsilon(1e-12));
  std::vector<std::array<double, 3>> errors;
  for (int cells : {10, 16, 20}) {
    const auto frames =
        run_poiseuille("poiseuille_isph_3d.toml", "poiseuille_pipe_" + std::to_string(cells), pipe_at(kWidth / cells));
    std::array<double, 3> e{};
    for (int k = 0; k < 3; ++k) {
      const auto [error, across] = pipe_error(frames[k], kTimes[k]);
      e[k] = error;
      CHECK(e[k] < 0.01);
      CHECK(across < 1e-4);  // axisymmetric: nothing flows across the axis
    }
    MESSAGE("pipe l/d = ", cells, ": L2 error against the series at t = 0.05, 0.1, 0.5 s: ", 100 * e[0], "%, ",
            100 * e[1], "%, ", 100 * e[2], "%");
    errors.push_back(e);
  }
  // The start-up converges with resolution; at 0.5 s the flow is steady (the series is 1e-5
  // from the parabola) and the corrected Laplacian holds a quadratic profile exactly, so the
  // error there is the time stepping's, not the spacing's: asserted below 1e-4 at each.
  // The start-up converges at an order, as the channel's (above). Measured error ratios, l/d = 10
  // over 16 and 16 over 20: 5.57 and 1.82 at 0.05 s, 5.41 and 2.15 at 0.1 s (order 2.7-3.7).
  // Asserted: at least order 1.5, (16/10)^1.5 = 2.02 and (20/16)^1.5 = 1.40.
  for (int k = 0; k < 2; ++k) {
    const double first = errors[0][k] / errors[1][k], second = errors[1][k] / errors[2][k];
    MESSAGE("pipe t = ", kTimes[k], " s: error ratio l/d = 10 over 16 ", first, ", 16 over 20 ", second,
            " (first order: 1.6, 1.25)");
    CHECK(first >= std::pow(16.0 / 10, 1.5));
    CHECK(second >= std::pow(20.0 / 16, 1.5));
  }
  for (auto& e : errors) CHECK(e[2] < 1e-4);
}
