// The XSPH shifting model (I-SPH(2) eq. 9; src/systems/shifting/xsph_shifting.hpp) against its
// formula: a periodic shear u = U sin(2 pi y / L), v = 0, no viscosity, no gravity, one ISPH step
// of fixed dt. The shear is divergence-free and the pressure uniform, so the step moves each
// particle by u dt and then XSPH shifts it by
//   dr_i = eps dt sum_j 2 m_j / (rho_i + rho_j) (v_j - v_i) W_ij,
// which the test recomputes from the frame (positions before the shift = x - dr, the `shift`
// column) with the cubic spline of h = 1.2 d. The velocity is carried along x, where the shear
// does not vary, so the frame's velocity is the one the shift saw (the projection leaves v_y of
// the order of the solver's tolerance; it enters both sides alike).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

// Runs a one-step scene written to DIR/NAME.toml; the path of its first frame.
std::filesystem::path run_one_step(const std::filesystem::path& dir, const std::string& name,
                                   const std::string& text) {
  test::write_text(dir / (name + ".toml"), text);
  RunOptions opt;
  opt.scene = (dir / (name + ".toml")).string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  REQUIRE(run_scene(opt) == kExitDone);
  return dir / "out" / "frames" / "frame_00001.h5";
}

// The 2D cubic spline of smoothing length h (seed 002 eq. 11), written out here.
double cubic_spline_2d(double r, double h) {
  const double q = r / h, sigma = 10 / (7 * std::numbers::pi * h * h);
  return sigma * (q < 1 ? 1 - 1.5 * q * q + 0.75 * q * q * q : q < 2 ? 0.25 * std::pow(2 - q, 3) : 0.0);
}

}  // namespace

TEST_CASE("shifting: XSPH shifts each particle by eps dt sum 2 m_j/(rho_i + rho_j) (v_j - v_i) W_ij") {
  auto dir = test::scratch("xsph_shear");
  const double L = 0.4, d = 0.02, dt = 1e-3, eps = 0.5;
  // The shear comes from two opposite blocks per half: the velocity key is per block, so the
  // profile is a square wave in y (u = +U below L/2, -U above); W_ij then sees v_j - v_i = 2U only
  // across the two interfaces.
  const auto frame = run_one_step(dir, "shear", R"([scene]
dimension = 2
name = "xsph_shear"
[domain]
min = [0.0, 0.0]
max = [0.4, 0.4]
periodic = [true, true]
[particles]
spacing = 0.02
[material]
density = 1000.0
viscosity = 0.0
[physics]
gravity = [0.0, 0.0]
[method]
name = "isph"
[shifting]
model = "xsph"
xsph_epsilon = 0.5
max_shift = 1.0
[solver]
preconditioner = "jacobi"
[time]
end = 0.001
dt = 0.001
[output]
interval = 0.001
fields = ["shift", "mass"]
[[fluid]]
min = [0.0, 0.0]
max = [0.4, 0.2]
velocity = [0.1, 0.0]
[[fluid]]
min = [0.0, 0.2]
max = [0.4, 0.4]
velocity = [-0.1, 0.0]
)");
  auto x = test::read_dataset(frame, "position").values, shift = test::read_dataset(frame, "shift").values,
       v = test::read_dataset(frame, "velocity").values, m = test::read_dataset(frame, "mass").values,
       rho = test::read_dataset(frame, "density").values;
  const std::size_t n = m.size();
  REQUIRE(n == 400);
  const double h = 1.2 * d;
  auto W = [&](double r) { return cubic_spline_2d(r, h); };
  auto wrap = [&](double s) { return s - L * std::round(s / L); };
  double worst = 0, largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double expected[2] = {0, 0};
    for (std::size_t j = 0; j < n; ++j) {
      const double rx = wrap((x[3 * j] - shift[3 * j]) - (x[3 * i] - shift[3 * i]));
      const double ry = wrap((x[3 * j + 1] - shift[3 * j + 1]) - (x[3 * i + 1] - shift[3 * i + 1]));
      const double weight = 2 * m[j] / (rho[i] + rho[j]) * W(std::hypot(rx, ry));
      for (int a = 0; a < 2; ++a) expected[a] += weight * (v[3 * j + a] - v[3 * i + a]);
    }
    for (int a = 0; a < 2; ++a) {
      expected[a] *= eps * dt;
      worst = std::max(worst, std::abs(shift[3 * i + a] - expected[a]));
      largest = std::max(largest, std::abs(expected[a]));
    }
  }
  MESSAGE("largest XSPH shift ", largest / d, " d; largest difference from the formula ", worst / d, " d");
  CHECK(largest > 5e-4 * d);  // the interfaces did shift (measured 1.1e-3 d)
  CHECK(worst < 1e-6 * largest);  // measured 4e-8: round-off of the positions (x - dr) and the carry
}

// The optimised model (OPS, Khayyer et al. 2017) against the Fickian one on a layer of water
// translating at 1 m/s between two flat free surfaces (periodic in x, no gravity; one ISPH step).
// The lattice moves rigidly, so grad C vanishes inside and points across the layer in the rows
// whose support the surfaces cut. Fickian shifting keeps only the tangential part on the flagged
// rows and pushes the rows beneath them outwards, thinning the layer under each surface; the
// optimised model keeps only the tangential part wherever a surface particle is in the support,
// so no particle moves across the layer.
TEST_CASE("shifting: the optimised model moves no particle across a translating layer, the Fickian one does") {
  auto dir = test::scratch("ops_layer");
  const double d = 0.02;
  auto run = [&](const std::string& model) {
    test::write_text(dir / (model + ".toml"), R"([scene]
dimension = 2
name = "ops_layer"
[domain]
min = [0.0, -0.2]
max = [0.4, 0.4]
periodic = [true, false]
[particles]
spacing = 0.02
[material]
density = 1000.0
viscosity = 0.0
[physics]
gravity = [0.0, 0.0]
[method]
name = "isph"
[shifting]
model = ")" + model + R"("
[solver]
preconditioner = "jacobi"
[time]
end = 0.005
dt = 0.005
[output]
interval = 0.005
fields = ["shift", "free_surface"]
[[fluid]]
min = [0.0, 0.0]
max = [0.4, 0.2]
velocity = [1.0, 0.0]
)");
    RunOptions opt;
    opt.scene = (dir / (model + ".toml")).string();
    opt.out_dir = (dir / model).string();
    opt.quiet = true;
    REQUIRE(run_scene(opt) == kExitDone);
    return dir / model / "frames" / "frame_00001.h5";
  };
  auto across = [&](const std::filesystem::path& frame) {  // largest |dr_y| over the layer, in d
    auto shift = test::read_dataset(frame, "shift").values;
    auto surface = test::read_dataset(frame, "free_surface").values;
    REQUIRE(surface.size() == 200);
    double largest = 0;
    std::size_t flagged = 0;
    for (std::size_t i = 0; i < surface.size(); ++i) {
      largest = std::max(largest, std::abs(shift[3 * i + 1]) / d);
      flagged += surface[i] != 0;
    }
    CHECK(flagged == 40);  // the top and bottom rows, and only they
    return largest;
  };
  const double fickian = across(run("fickian")), optimised = across(run("optimised"));
  MESSAGE("largest shift across the layer in one step: fickian ", fickian, " d, optimised ", optimised, " d");
  CHECK(fickian > 1e-3);              // measured 0.0171 d (A h |v| dt |grad C| below the surface rows)
  CHECK(optimised < 1e-9 * fickian);  // round-off only
}

// The paper's density-based shifting (ISPH seed 000, eqs. 19-23; src/systems/shifting/
// density_shifting.hpp) against its formula, recomputed from the frame: a periodic box of water
// started with 20% disorder, translating at U = 0.5 m/s (no gravity, no pressure: the flow is
// uniform), one ISPH step at dt = 0.2 d / U, the step at which C_shift was tuned (scale = C h).
// Before the shift the particles only translated, so the shift saw the frame's x - dr:
//   <rho>_i = beta sum_{|x_ij| <= d*} m_j W_ij (i included), beta = 1 / (d^2 sum_lattice W),
//   dr_i = C h sum_{0 < |x_ij| <= d*} (V_j W_ij + <rho>_i / rho0 - 1 + <rho>_j / rho0 - 1) e_ij,
// d* = 1.1 sqrt(2) d, V_j = m_j / rho_j, e_ij the unit vector from j to i. The mutation check's
// C_shift x2 (tools/mutations.json) survived the whole suite until this case.
TEST_CASE(
    "shifting: density shifting moves each particle by C h (sum V_j W_ij e_ij + density excess terms)") {
  auto dir = test::scratch("density_shift_box");
  const double L = 0.4, d = 0.02, U = 0.5, dt = 0.2 * d / U, C = 0.005;
  const auto frame = run_one_step(dir, "box", R"([scene]
dimension = 2
name = "density_shift_box"
[domain]
min = [0.0, 0.0]
max = [0.4, 0.4]
periodic = [true, true]
[particles]
spacing = 0.02
disorder = 0.2
[material]
density = 1000.0
viscosity = 0.0
[physics]
gravity = [0.0, 0.0]
[method]
name = "isph"
[shifting]
model = "density"
coefficient = 0.005
[solver]
preconditioner = "jacobi"
[time]
end = 0.008
dt = 0.008
[output]
interval = 0.008
fields = ["shift", "mass", "free_surface"]
[[fluid]]
min = [0.0, 0.0]
max = [0.4, 0.4]
velocity = [0.5, 0.0]
)");
  auto x = test::read_dataset(frame, "position").values, shift = test::read_dataset(frame, "shift").values,
       m = test::read_dataset(frame, "mass").values, rho = test::read_dataset(frame, "density").values,
       surface = test::read_dataset(frame, "free_surface").values;
  const std::size_t n = m.size();
  REQUIRE(n == 400);
  CHECK(std::count_if(surface.begin(), surface.end(), [](double s) { return s != 0; }) == 0);  // no surface
  const double h = 1.2 * d, rho0 = 1000, radius = 1.1 * std::sqrt(2.0) * d;
  auto W = [&](double r) { return cubic_spline_2d(r, h); };

  double lattice = 0;  // the centre, 4 neighbours at d, 4 at sqrt(2) d: all within d*
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b) lattice += W(d * std::hypot(a, b));
  const double beta = 1 / (d * d * lattice);
  auto wrap = [&](double s) { return s - L * std::round(s / L); };
  auto offset = [&](std::size_t i, std::size_t j, int a) {  // x_j - x_i before the shift
    return wrap((x[3 * j + a] - shift[3 * j + a]) - (x[3 * i + a] - shift[3 * i + a]));
  };
  std::vector<double> smoothed(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (double r = std::hypot(offset(i, j, 0), offset(i, j, 1)); r <= radius)
        smoothed[i] += beta * m[j] * W(r);
  double worst = 0, largest = 0, excess = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double expected[2] = {0, 0};
    excess = std::max(excess, std::abs(smoothed[i] / rho0 - 1));
    for (std::size_t j = 0; j < n; ++j) {
      const double rx = offset(i, j, 0), ry = offset(i, j, 1), r = std::hypot(rx, ry);
      if (r == 0 || r > radius) continue;
      const double weight = m[j] / rho[j] * W(r) + smoothed[i] / rho0 - 1 + smoothed[j] / rho0 - 1;
      expected[0] -= weight * rx / r, expected[1] -= weight * ry / r;  // e_ij = -(x_j - x_i) / r
    }
    for (int a = 0; a < 2; ++a) {
      expected[a] *= C * h * (dt * U / (0.2 * d));  // = C h at the tuned step
      worst = std::max(worst, std::abs(shift[3 * i + a] - expected[a]));
      largest = std::max(largest, std::abs(expected[a]));
    }
  }
  MESSAGE("largest density shift ", largest / d, " d (density excess up to ", excess,
          "); largest difference from the formula ", worst / d, " d");
  CHECK(excess > 0.01);           // the disorder is there for the shift to undo
  CHECK(largest > 1e-3 * d);      // and the particles did shift
  CHECK(worst < 1e-6 * largest);  // round-off of x - dr only
}
