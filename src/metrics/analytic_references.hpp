#pragma once
// Closed-form references the [[metric]] types compare against (formulas written from the cited
// papers).
#include <array>
#include <cmath>
#include <numbers>

namespace ryushi {

// Start-up of plane Poiseuille flow from rest under a body force F between no-slip walls l
// apart (Morris, Fox & Zhu 1997, eq. 21), y measured from one wall:
//   u(y, t) = F/(2 nu) y (l - y) - sum_n 4 F l^2 / (nu pi^3 (2n+1)^3) sin((2n+1) pi y / l)
//                                        exp(-(2n+1)^2 pi^2 nu t / l^2).
inline double poiseuille_startup(double y, double t, double width, double force, double nu) {
  const double pi = std::numbers::pi;
  double u = force / (2 * nu) * y * (width - y);
  for (int n = 0; n < 200; ++n) {
    const double k = 2 * n + 1;
    u -= 4 * force * width * width / (nu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / width) *
         std::exp(-k * k * pi * pi * nu * t / (width * width));
  }
  return u;
}

// The pressure of a square patch of side L in rigid rotation at omega (Colagrossi's rotating
// square; ISPH paper section 6(2)): lap p = 2 rho omega^2 inside, p = 0 on the edges. With
// X, Y in [0, L] measured from a corner, expanding the constant in sine modes:
//   p = -32 rho omega^2 / pi^2 sum_{m,n odd} sin(m pi X / L) sin(n pi Y / L)
//                                            / (m n ((m pi / L)^2 + (n pi / L)^2)).
// The terms fall as 1/(m n (m^2 + n^2)); 200 odd modes each way leave < 1e-6 of the centre value.
inline double rotating_square_series(double X, double Y, double side, double rho, double omega) {
  const double pi = std::numbers::pi;
  constexpr int kModes = 200;  // odd m, n = 1, 3, ..., 399
  std::array<double, kModes> sy;
  for (int b = 0; b < kModes; ++b) sy[b] = std::sin((2 * b + 1) * pi * Y / side);
  double sum = 0;
  for (int a = 0; a < kModes; ++a) {
    const double m = 2 * a + 1, sx = std::sin(m * pi * X / side), km = m * pi / side;
    for (int b = 0; b < kModes; ++b) {
      const double n = 2 * b + 1, kn = n * pi / side;
      sum += sx * sy[b] / (m * n * (km * km + kn * kn));
    }
  }
  return -32 * rho * omega * omega / (pi * pi) * sum;
}

}  // namespace ryushi
