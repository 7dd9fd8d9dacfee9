// ISPH (corrected ALE-ISPH, ISPH paper seed 000): the resting tank against rho g depth, the
// rotating square's first pressure against Colagrossi's series, the shifting constant from its
// definition, and bad input of the new keys.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "isph_one_set_up.hpp"
#include "shipped_scene_run.hpp"
#include "systems/isph/compression_density.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/shifting/density_shifting.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

// Hydrostatic tank, H/d = 40, one wall layer with Neumann rows, p = 0 extrapolated half a
// spacing outside the surface particles. Measured over t = 0.5-2 s: every probe within 0.014% of
// rho g depth; at t = 2 s speeds below 7e-5 sqrt(g H) under the top four rows, up to
// 5e-4 sqrt(g H) in them (the issue asks 1e-4 everywhere: not met near the surface).
namespace {
// The resting tank (scenes/hydrostatic_isph_2d.toml, H/d = 40) to t = 2 s under `sets`: every probe
// and wall sensor within 0.5% of rho g depth over t = 0.5-2 s, and the largest speed at the end below
// `interior` sqrt(g H) under the top four rows and `surface` sqrt(g H) in them (issue 49 asks 1e-4 and
// 1e-3).
void check_resting_tank(const std::string& label, const std::vector<std::string>& sets,
                        double interior_bound = 1e-4, double surface_bound = 1e-3) {
  auto out = test::scratch(label);
  RunOptions opt;
  opt.scene = test::scene_path("hydrostatic_isph_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.end_time = 2.0;
  opt.sets = sets;
  REQUIRE(run_scene(opt) == kExitDone);
  auto probes = test::read_csv(out / "probes.csv");
  const double rho_g = 1000 * 9.81, H = 0.5;
  for (auto [name, depth] : {std::pair{"p_depth_0.10", 0.10},
                             {"p_depth_0.25", 0.25},
                             {"p_depth_0.40", 0.40},
                             {"p_depth_0.45", 0.45},
                             {"sensor_left_0.40", 0.40},
                             {"sensor_right_0.25", 0.25},
                             {"sensor_floor_0.50", 0.50}}) {
    REQUIRE_MESSAGE(probes[name].size() > 10, name);
    // The 0.5% on every sample, so that a NaN (an empty support, probes.cpp) fails:
    // std::max(worst, NaN) would drop it.
    double worst = 0;
    std::size_t samples = 0;
    for (std::size_t k = 0; k < probes["time"].size(); ++k) {
      if (probes["time"][k] < 0.5) continue;
      const double deviation = std::abs(probes[name][k] / (rho_g * depth) - 1);
      CHECK_MESSAGE(deviation < 0.005, name << " at t = " << probes["time"][k] << ": " << probes[name][k]);
      worst = std::max(worst, deviation), ++samples;
    }
    MESSAGE(label, ", ", std::string(name), ": largest deviation from rho g depth over t = 0.5-2 s: ", worst);
    REQUIRE(samples > 10);
  }
  // Speeds after settling, from the last frame: below the surface row the water is still.
  auto last = out / "frames" / "frame_00020.h5";
  auto x = test::read_dataset(last, "position").values, v = test::read_dataset(last, "velocity").values;
  auto kind = test::read_dataset(last, "kind").values;
  const double d = 0.0125, scale = std::sqrt(9.81 * H);
  double interior = 0, surface = 0;
  for (std::size_t i = 0; i < kind.size(); ++i) {
    if (kind[i] != 0) continue;
    double speed = std::hypot(v[3 * i], v[3 * i + 1]) / scale;
    double& band = x[3 * i + 1] < H - 4 * d ? interior : surface;
    band = std::max(band, speed);
  }
  MESSAGE(label, ": max speed / sqrt(gH): below the top four rows ", interior, ", top four rows ", surface);
  CHECK(interior < interior_bound);
  CHECK(surface < surface_bound);  // the rows near the surface jitter (reported in docs/isph.md)
}
}  // namespace

TEST_CASE("isph: a resting tank keeps rho g depth and stays still") {
  check_resting_tank("isph_hydrostatic", {});
}

// The one-set-up candidate (isph_one_set_up.hpp). Measured 2026-11-28: 5.7e-5 and 3.8e-4 sqrt(g H),
// the probes within 8e-5 of rho g depth (the paper's set-up: 7.0e-5, 4.0e-4, 1.6e-4). Without the
// compression term's dead band 1.3e-4 and 3.7% (docs/isph.md).
TEST_CASE("isph: a resting tank keeps rho g depth and stays still with the one-set-up candidate") {
  check_resting_tank("isph_hydrostatic_one_set_up", test::isph_one_set_up());
}

// formulation = "implicit_density" (src/systems/isph/implicit_density_solve.hpp) as it now
// stands: settled before t = 0 (settle_steps, 1,000 steps) and undamped. Measured 2026-11-29: the
// probes and sensors within 0.14% of rho g depth over t = 0.5-2 s (the floor sensor; the others
// 0.03% or less); at t = 2 s 7.7e-5 sqrt(g H) below the top four rows and 1.9e-5 in them: issue
// 49's 1e-4 and 1e-3, asserted. The 7.7e-5 is the bottom row's answer to the step shortened to land
// on each frame (at a fixed step that divides the frame interval 0.5-1.1e-5); without the settle
// 6.4e-4 (the contact lines' start-up, docs/isph.md), with the particle-scale damping at 0.2 instead
// of the settle 8.4e-5.
TEST_CASE("isph: a resting tank keeps rho g depth with the implicit density formulation") {
  check_resting_tank("isph_hydrostatic_implicit_density", {"method.formulation=\"implicit_density\""});
}

namespace {
// Colagrossi's series for the rotating square's pressure: lap p = 2 rho omega^2 inside the
// square |x|, |y| < L/2, p = 0 on its edge; at the centre
//   p = -32 rho omega^2 / pi^2 sum_{m,n odd} sin(m pi/2) sin(n pi/2) / (m n ((m pi/L)^2 + (n pi/L)^2)).
double rotating_square_centre_pressure(double rho, double omega, double L) {
  const double pi = std::numbers::pi;
  double sum = 0;
  for (int m = 1; m < 800; m += 2)
    for (int n = 1; n < 800; n += 2)
      sum += std::sin(m * pi / 2) * std::sin(n * pi / 2) / (m * n * (std::pow(m * pi / L, 2) + std::pow(n * pi / L, 2)));
  return -32 * rho * omega * omega / (pi * pi) * sum;
}
}  // namespace

// The projection at the predicted positions sees the divergence 2 omega^2 dt that straight-line
// motion creates in a rigid rotation, so the first step already holds the whole pressure
// field. Measured: -146.84 Pa against -147.34 Pa (0.34%).
TEST_CASE("isph: the rotating square's first pressure matches Colagrossi's series") {
  auto out = test::scratch("isph_rotating_square");
  RunOptions opt;
  opt.scene = test::scene_path("rotating_square_isph_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.sets = {"time.max_steps=1", "output.probe_interval=1e-6"};
  REQUIRE(run_scene(opt) == kExitDone);
  auto probes = test::read_csv(out / "probes.csv");
  REQUIRE(probes["p_centre"].size() == 2);
  const double exact = rotating_square_centre_pressure(1000, 1, 1);
  MESSAGE("centre pressure after one step ", probes["p_centre"].back(), " Pa, series ", exact, " Pa");
  CHECK(exact == doctest::Approx(-147.34).epsilon(1e-4));  // the series itself (ISPH paper Fig. 6 starts there)
  CHECK(std::abs(probes["p_centre"].back() / exact - 1) < 0.03);
}

namespace {
// The rotating square's interior at one frame: the particles that started in the inner square
// |x|, |y| < 0.3 m (followed by id) and have no free-surface particle within 2 h, and their mean
// numerical density over the whole support, sum_j W_ij / (the same sum on the starting lattice):
// the fluid's volume, which an incompressible flow keeps. (Eq. 19's small radius d* is not used:
// shear moves diagonal neighbours out past d* and that sum falls 3% with no change of volume.)
struct InteriorDensity {
  std::size_t count = 0;
  double mean = 0;
};
InteriorDensity rotating_square_interior(const fs::path& run, int frame) {
  const double d = 0.02, h = 1.2 * d, support = 2 * h;
  auto W = [&](double r) {  // the cubic spline without its constant (it cancels in the ratio)
    const double q = r / h;
    return q < 1 ? 1 - 1.5 * q * q + 0.75 * q * q * q : q < 2 ? 0.25 * std::pow(2 - q, 3) : 0.0;
  };
  double lattice = 0;
  for (int a = -3; a <= 3; ++a)
    for (int b = -3; b <= 3; ++b) lattice += W(d * std::hypot(a, b));
  std::map<long, bool> started_inside;
  auto x0 = test::read_dataset(test::frame_path(run, 0), "position").values,
       id0 = test::read_dataset(test::frame_path(run, 0), "id").values;
  for (std::size_t i = 0; i < id0.size(); ++i)
    started_inside[long(id0[i])] = std::max(std::abs(x0[3 * i]), std::abs(x0[3 * i + 1])) < 0.3;
  auto x = test::read_dataset(test::frame_path(run, frame), "position").values;
  auto id = test::read_dataset(test::frame_path(run, frame), "id").values;
  auto surface = test::read_dataset(test::frame_path(run, frame), "free_surface").values;
  const std::size_t n = id.size();
  InteriorDensity out;
  for (std::size_t i = 0; i < n; ++i) {
    if (!started_inside.at(long(id[i])) || surface[i] != 0) continue;
    double sum = 0;
    bool cut = false;
    for (std::size_t j = 0; j < n; ++j) {
      const double r = std::hypot(x[3 * j] - x[3 * i], x[3 * j + 1] - x[3 * i + 1]);
      if (r >= support) continue;
      sum += W(r);
      cut = cut || surface[j] != 0;
    }
    if (cut) continue;
    ++out.count;
    out.mean += sum / lattice;
  }
  if (out.count) out.mean /= double(out.count);
  return out;
}
}  // namespace

// Issue 8's rotating square to omega t = 2 (the ISPH paper's Fig. 5 time) with density shifting,
// the optimised shifting and none. The patch thins into four arms a few particles across (its
// area of 1 m^2 spread along arms whose tips fly out to 0.71 sqrt(1 + (omega t)^2) m), so the
// particles with a full support dwindle: 584 of the inner square's 900 at omega t = 2, 24 at 4,
// none from 5 with every model (docs/isph.md): an interior density at omega t = 10 does not
// exist to measure. Measured, mean interior density at omega t = 0.5 / 1 / 1.5 / 2: density
// shifting 1.0029 / 1.0058 / 1.0087 / 1.0087; optimised 1.0063 / 1.0125 / 1.0141 / 1.0159 (printed,
// not asserted: the paper finds OPS worse here too, its Fig. 5); none 1.0030 / 1.0065 / 1.0092 /
// 1.0110. Asserted: the density model within 1% at every frame, with at least half the inner
// square still interior, and closer to 1 than no shifting at omega t = 2, where the two part
// (0.0087 against 0.0110, measured 2026-11-29 as before; at omega t = 0.5-1.5 they are 0.00007-
// 0.0006 apart, too close to assert; test audit round three, issue 50, row 38).
TEST_CASE(
    "isph: density shifting keeps the rotating square's interior volume within 1% to omega t = 2, closer "
    "than "
    "no shifting") {
  double deviation_density = -1, deviation_none = -1;  // |mean - 1| at omega t = 2
  for (const char* model : {"density", "optimised", "none"}) {
    auto out = test::scratch(std::string("isph_rotating_square_") + model);
    RunOptions opt;
    opt.scene = test::scene_path("rotating_square_isph_2d.toml");
    opt.out_dir = out.string();
    opt.quiet = true;
    opt.end_time = 2.0;
    opt.sets = {std::string("shifting.model=") + model, "output.fields=[\"free_surface\"]",
                "output.interval=0.5"};
    REQUIRE(run_scene(opt) == kExitDone);
    for (int frame = 1; frame <= 4; ++frame) {
      auto interior = rotating_square_interior(out, frame);
      MESSAGE(std::string(model), ": omega t = ", 0.5 * frame, ": ", interior.count,
              " interior particles, mean density ", interior.mean);
      if (frame == 4 && std::string(model) == "none") {
        REQUIRE(interior.count >= 450);
        deviation_none = std::abs(interior.mean - 1);
      }
      if (std::string(model) != "density") continue;
      if (frame == 4) deviation_density = std::abs(interior.mean - 1);
      CHECK(interior.count >= 450);
      CHECK(std::abs(interior.mean - 1) < 0.01);
    }
  }
  REQUIRE(deviation_density >= 0);
  REQUIRE(deviation_none >= 0);
  MESSAGE("omega t = 2: interior density deviation ", deviation_density, " (density shifting) against ",
          deviation_none, " (none)");
  CHECK(deviation_density < deviation_none);
}

// beta of eq. 19 makes the numerical density rho0 on the lattice: summed here from the cubic
// spline's formula, independently of the kernel library. The paper quotes 1.028 for the cubic
// spline, h = 1.2 d, 3D; its own definition gives 1.0124 (the paper's figure is not reproduced;
// docs/isph.md).
TEST_CASE("isph: the shifting constant beta follows from its definition") {
  const double h = 1.2, pi = std::numbers::pi;
  auto cubic = [&](double r) {
    double q = r / h, sigma = 1 / (pi * h * h * h);
    return sigma * (q < 1 ? 1 - 1.5 * q * q + 0.75 * q * q * q : q < 2 ? 0.25 * std::pow(2 - q, 3) : 0.0);
  };
  double sum = 0, radius = 1.1 * std::sqrt(3.0);
  for (int a = -2; a <= 2; ++a)
    for (int b = -2; b <= 2; ++b)
      for (int c = -2; c <= 2; ++c) {
        double r = std::sqrt(double(a * a + b * b + c * c));
        if (r <= radius) sum += cubic(r);
      }
  double beta = shifting_beta<3>(Kernel<3>(KernelType::CubicSpline, h), 1.0);
  MESSAGE("beta (cubic spline, h = 1.2 d, 3D) = ", beta);
  CHECK(beta == doctest::Approx(1 / sum).scale(0).epsilon(1e-12));
}

// The stabilised source's density error (compression_density.hpp) on a lattice of water over a
// one-layer floor, scaled by s: the density is s^-2 times the lattice's. first_shell answers
// compression only; full_support reads both ways (the floor's missing layers completed), a
// dilation at most 1%, and falls back to first_shell where the support holds a surface particle.
TEST_CASE("isph: the compression error reads a dilation both ways only over a full support") {
  const Kernel<2> kernel(KernelType::CubicSpline, 1.2);
  auto error_at = [&](double scale, CompressionDensity measure, Vec<2> at) {
    std::vector<Vec<2>> x;
    std::vector<std::int32_t> kind, surface;
    std::vector<Vec<2>> normal;
    for (int a = -6; a < 26; ++a) {  // the floor: one layer at y = -0.5, normals into the wall
      x.push_back(scale * Vec<2>(a + 0.5, -0.5)), kind.push_back(kWall), surface.push_back(0);
      normal.push_back(Vec<2>(0, -1));
    }
    for (int a = 0; a < 20; ++a)
      for (int b = 0; b < 12; ++b) {
        x.push_back(scale * Vec<2>(a + 0.5, b + 0.5)), kind.push_back(kFluid), surface.push_back(b == 11);
        normal.push_back(Vec<2>::Zero());
      }
    std::vector<double> volume(x.size(), 1.0);
    Domain<2> domain;
    CellGrid<2> grid;
    NeighbourList nl;
    build_neighbour_list<2>(domain, kernel.support(), x, grid, nl);
    ParticleView<2> view{x, volume, nl, kernel, domain};
    std::size_t i = 0;
    while ((x[i] - scale * at).norm() > 1e-9) ++i;
    Stencil<2> stencil;
    stencil.gather(view, i);
    return CompressionError<2>(kernel, 1.0, measure)(stencil, kind, surface, normal);
  };
  const Vec<2> interior(10.5, 5.5), on_floor(10.5, 0.5), under_surface(10.5, 9.5);
  for (auto measure : {CompressionDensity::FirstShell, CompressionDensity::FullSupport})
    for (auto at : {interior, on_floor, under_surface}) CHECK(std::abs(error_at(1.0, measure, at)) < 1e-12);
  // 0.1% apart: the density 0.2% lower, or higher. The kernel sum follows the density to within
  // a hundredth of the change (measured -0.1979% and +0.1985% against -0.1998% and +0.2003%).
  const double dilated = error_at(1.001, CompressionDensity::FullSupport, interior);
  const double compressed = error_at(0.999, CompressionDensity::FullSupport, interior);
  MESSAGE("full support: dilated 0.1% reads ", dilated, ", compressed ", compressed);
  CHECK_MESSAGE(test::within_relative(dilated, std::pow(1.001, -2) - 1, 0.02), "dilated " << dilated);
  CHECK_MESSAGE(test::within_relative(compressed, std::pow(0.999, -2) - 1, 0.02),
                "compressed " << compressed);
  const double floor_dilated = error_at(1.001, CompressionDensity::FullSupport, on_floor);
  CHECK_MESSAGE(test::within_relative(floor_dilated, dilated, 0.02), "on the floor " << floor_dilated);
  CHECK(error_at(1.001, CompressionDensity::FirstShell, interior) == 0.0);
  CHECK(error_at(0.999, CompressionDensity::FirstShell, interior) > 0.0);
  CHECK(error_at(1.001, CompressionDensity::FullSupport, under_surface) == 0.0);  // the first shell's
  CHECK(error_at(1.05, CompressionDensity::FullSupport, interior) == -CompressionError<2>::kDilationCap);
}

TEST_CASE("isph: bad method and shifting keys exit 2 with the place") {
  auto dir = test::scratch("isph_bad");
  const std::string base = test::block_scene("[0.2, 0.2]", "[0.6, 0.6]", 0.1, "[method]\nname = \"isph\"\n");
  auto check = [&](const std::string& extra, const std::string& expected) {
    test::write_text(dir / "bad.toml", base + extra);
    auto r = test::run_command(std::string(RYUSHI_BINARY) + " check " + (dir / "bad.toml").string());
    CHECK(r.code == 2);
    CHECK_MESSAGE(r.output.find(expected) != std::string::npos, r.output);
  };
  check("description = \"langrangian\"\n", "bad.toml:15:15: 'description' in [method] is 'langrangian'");
  check("[shifting]\nmodel = \"fick\"\n", "'model' in [shifting] is 'fick'");
  check("wall_rows = \"shepherd\"\n", "bad.toml:15:13: 'wall_rows' in [method] is 'shepherd'");
  check("compression_relaxation = -0.1\n", "'compression_relaxation' in [method] is -0.1");
  check("compression_density = \"support\"\n",
        "bad.toml:15:23: 'compression_density' in [method] is 'support'");
  check("[shifting]\nfickian_coefficient = -2.0\n", "'fickian_coefficient' in [shifting] is -2");
  check("[shifting]\nmax_shift = 1.5\n", "'max_shift' in [shifting] is 1.5");
  check("[shifting]\ncoefficient = -1.0\n", "'coefficient' in [shifting] is -1");
  check("[[wall]]\nmin = [0.2, 0.2]\nmax = [0.8, 0.8]\nlayers = 3\n", "method isph uses one layer of wall particles");
  check("[[fixed_pressure]]\nmin = [0.2, 0.2]\nmax = [0.3, 0.6]\npressure = 1.0\n",
        "[[fixed_pressure]] #0 needs [method] name = \"isph\" with description = \"eulerian\"");
  check("description = \"eulerian\"\n[[fixed_pressure]]\nmin = [0.2, 0.2]\nmax = [0.3, 0.6]\n",
        "'pressure'");
  check("description = \"eulerian\"\n[[fixed_pressure]]\nmin = [0.3, 0.2]\nmax = [0.2, 0.6]\npressure = 1.0\n",
        "[[fixed_pressure]] #0 is empty (max <= min)");
  check("[[wall]]\nmin = [0.2, 0.2]\nmax = [0.8, 0.8]\nopen_ends = [true]\n", "'open_ends' in [[wall]]");
  check("formulation = \"implicit\"\n", "bad.toml:15:15: 'formulation' in [method] is 'implicit'");
  check("formulation = \"implicit_density\"\ndescription = \"eulerian\"\n",
        "bad.toml:15:15: formulation = \"implicit_density\" moves the particles");
  check("density_tolerance = 0.5\n", "'density_tolerance' in [method] is 0.5");
}

// A step shortened to land on a frame or the end time (issue 10) leaves the frame's pressure
// physical: the velocity-divergence source scales with the step it integrates. Resting tank,
// fixed dt = 0.7984 ms: 125 full steps to 0.0998 s against 124 full and two of 0.55 dt to
// 0.09988 s; the fluid pressures (matched by id) differ by 6.8e-6 (L2, relative).
TEST_CASE("isph: a frame after shortened steps shows the pressure of a full step") {
  auto run = [](const std::string& name, double end) {
    auto out = test::scratch(name);
    RunOptions opt;
    opt.scene = test::scene_path("hydrostatic_isph_2d.toml");
    opt.out_dir = out.string();
    opt.quiet = true;
    opt.end_time = end;
    opt.sets = {"time.dt=7.984e-4", "output.interval=1"};
    REQUIRE(run_scene(opt) == kExitDone);
    auto frame = out / "frames" / "frame_00001.h5";
    auto id = test::read_dataset(frame, "id").values, p = test::read_dataset(frame, "pressure").values;
    auto kind = test::read_dataset(frame, "kind").values;
    std::map<long, double> by_id;
    for (std::size_t i = 0; i < id.size(); ++i)
      if (kind[i] == 0) by_id[std::lround(id[i])] = p[i];
    return std::pair{by_id, test::json_number(test::read_text(out / "summary.json"), "steps")};
  };
  auto [full, full_steps] = run("isph_full_steps", 0.0998);
  auto [shortened, shortened_steps] = run("isph_shortened_steps", 0.09988);
  CHECK(full_steps == 125);
  CHECK(shortened_steps == 126);
  double diff = 0, norm = 0;
  for (auto& [id, p] : full) {
    diff += std::pow(shortened.at(id) - p, 2);
    norm += p * p;
  }
  MESSAGE("relative L2 difference of the fluid pressure: ", std::sqrt(diff / norm));
  CHECK(std::sqrt(diff / norm) < 2e-5);  // measured 6.8e-6
}

// The 3D path (one wall layer with corner normals in three axes, the 6x6 corrected-Laplacian
// system): a coarse tank (H/d = 10) keeps rho g depth at 0.1 m. Measured 979.6-979.9 Pa over
// t = 0.2-0.3 s against 981 (0.14%).
TEST_CASE("isph: a resting 3D tank keeps rho g depth") {
  auto out = test::scratch("isph_hydrostatic_3d");
  RunOptions opt;
  opt.scene = test::scene_path("hydrostatic_isph_3d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  REQUIRE(run_scene(opt) == kExitDone);
  auto probes = test::read_csv(out / "probes.csv");
  REQUIRE(probes["time"].back() >= 0.3 - 1e-9);  // the scene's end: the window below is not empty
  double worst = 0;
  std::size_t samples = 0;
  for (std::size_t k = 0; k < probes["time"].size(); ++k) {
    if (probes["time"][k] < 0.2) continue;
    const double deviation = std::abs(probes["p_depth_0.1"][k] / 981.0 - 1);  // NaN fails here
    CHECK_MESSAGE(deviation < 0.005,
                  "t = " << probes["time"][k] << ": " << probes["p_depth_0.1"][k] << " Pa");
    worst = std::max(worst, deviation), ++samples;
  }
  MESSAGE("3D: largest deviation from rho g depth over t = 0.2-0.3 s: ", worst, " in ", samples, " samples");
  REQUIRE(samples >= 10);  // every 0.01 s
}

// The same tank left for 3 s (21 sqrt(H/g)): it must stay at rest. Before the wetting rule took a
// distance instead of an angle (isph_pressure_equation.hpp), the wall particle on each vertical
// edge one spacing above the water was wetted alone in its row, at -148 Pa, and pulled the
// corner's surface particles in: the kinetic energy, 1.3e-5 J at 1 s, grew tenfold every 0.2 s
// from t = 1.6 s (0.026 J at 2.4 s, then the blow-up). Now 1-2e-5 J to t = 4 s (docs/isph.md,
// "Open": a slower growth from 4 s is not resolved). Bound: 1e-4 J, a speed of 5 mm/s over the
// 8 kg, five times the start-up level that the run settles to.
TEST_CASE("isph: a resting 3D tank stays at rest for 3 s (its vertical edges stay dry above the water)") {
  const auto out = test::run_shipped_scene("isph_hydrostatic_3d_long", "hydrostatic_isph_3d.toml",
                                           "[[probe]]\nname = \"ke\"\ntype = \"kinetic_energy\"\n",
                                           {"time.end=3.0", "output.interval=0.5"});
  auto probes = test::read_csv(out / "probes.csv");
  double largest = 0;
  for (double e : probes["ke"]) largest = std::max(largest, e);
  MESSAGE("3D tank at rest: largest kinetic energy to t = 3 s: ", largest, " J");
  CHECK(largest < 1e-4);
  CHECK(std::abs(probes["p_depth_0.1"].back() / 981.0 - 1) < 0.005);
}
