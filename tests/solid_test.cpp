// [[solid]] bodies (src/geometry/solid_shape.hpp): their particles and normals, the fluid cut
// out around them, a sliding plate driving a Couette flow, the force of a dam break on an
// obstacle, and the errors of bad geometry.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "functions/motion_table.hpp"
#include "geometry/solid_shape.hpp"
#include "h5_read.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"
#include "wave_maker_theory.hpp"

using namespace ryushi;

namespace {

constexpr double kPi = std::numbers::pi;
std::string bin() {
  return RYUSHI_BINARY;
}

// Couette start-up between a plate at rest (y = 0) and one sliding at U (y = H), from rest.
double couette_u(double y, double t, double U, double H, double nu) {
  double u = U * y / H;
  for (int n = 1; n <= 400; ++n)
    u -= 2 * U * (n % 2 ? 1 : -1) / (n * kPi) * std::sin(n * kPi * y / H) *
         std::exp(-n * n * kPi * kPi * nu * t / (H * H));
  return u;
}
// The shear stress on the sliding plate relative to the steady mu U / H: 1 + 2 sum exp(-n^2 pi^2 nu t / H^2).
double couette_shear_ratio(double t, double H, double nu) {
  double s = 1;
  for (int n = 1; n <= 400; ++n) s += 2 * std::exp(-n * n * kPi * kPi * nu * t / (H * H));
  return s;
}

// Checks the drag probe of scenes/couette_2d.toml (the sliding plate, 2 mm long) against
// -mu U L / H (1 + 2 sum e^...) within `tolerance` from t = 0.1 s (before, the series' slope at
// the wall is steeper than the particles resolve); returns how many samples it checked.
std::size_t check_couette_drag(const std::filesystem::path& probes, double tolerance) {
  const double U = 1.25e-5, H = 1e-3, nu = 1e-6, mu = 1e-3, L = 2e-3;
  auto csv = test::read_csv(probes);
  const auto& t = csv["time"];
  const auto& drag = csv["drag_top"];
  std::size_t checked = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < 0.1 - 1e-9) continue;
    CAPTURE(t[k]);
    const double ratio = drag[k] / (-mu * U / H * L * couette_shear_ratio(t[k], H, nu));
    CHECK_MESSAGE(test::within_relative(ratio, 1.0, tolerance), "drag / series " << ratio);
    ++checked;
  }
  return checked;
}

SolidSpec round_spec(const std::string& shape, const std::vector<double>& centre, double radius, int layers) {
  SolidSpec s;
  s.shape = shape, s.centre = centre, s.radius = radius, s.layers = layers;
  s.min = s.max = centre;
  for (std::size_t a = 0; a < centre.size(); ++a) s.min[a] -= radius, s.max[a] += radius;
  return s;
}

}  // namespace

TEST_CASE("solid: shells have the layers, spacing and normals of their shape") {
  const double d = 0.01;
  SolidSpec disc = round_spec("cylinder", {0.3, 0.3}, 0.1, 3);
  auto rings = SolidShape<2>(disc).shell(d);
  std::size_t expected = 0;
  for (int k = 1; k <= 3; ++k) expected += std::lround(2 * kPi * (0.1 - (k - 0.5) * d) / d);
  CHECK(rings.size() == expected);
  for (auto& q : rings) {
    const Vec<2> r = q.position - Vec<2>(0.3, 0.3);
    CHECK(r.norm() == doctest::Approx(0.1 - (q.layer - 0.5) * d).epsilon(1e-12));
    CHECK((q.normal + r.normalized()).norm() < 1e-12);  // into the body: -r / |r|
  }
  SolidSpec ball = round_spec("sphere", {0.0, 0.0, 0.0}, 0.1, 1);
  auto shell = SolidShape<3>(ball).shell(d);
  // A Fibonacci sphere of radius R - d/2 holding 4 pi r^2 / d^2 points: one per d^2 of surface.
  CHECK(shell.size() == std::size_t(std::lround(4 * kPi * 0.095 * 0.095 / (d * d))));
  double nearest = 1e9;
  for (std::size_t i = 0; i < shell.size(); i += 37)
    for (std::size_t j = 0; j < shell.size(); ++j)
      if (j != i) nearest = std::min(nearest, (shell[i].position - shell[j].position).norm());
  CHECK(nearest > 0.8 * d);  // no two particles on top of each other; about d apart
  for (auto& q : shell) CHECK((q.normal + q.position.normalized()).norm() < 1e-12);
  SolidSpec box;
  box.shape = "box", box.min = {0.0, 0.0}, box.max = {0.1, 0.05}, box.layers = 2;
  auto lattice = SolidShape<2>(box).shell(d);
  CHECK(lattice.size() == 10 * 5 - 6 * 1);  // all but the middle row's inner 6 (deeper than 2 d)
  for (auto& q : lattice) {
    const double depth = -SolidShape<2>(box).signed_distance(q.position);
    CHECK(q.layer == int(std::ceil(depth / d - 1e-9)));
  }
  CHECK(SolidShape<2>(box).signed_distance(Vec<2>(0.13, 0.09)) == doctest::Approx(0.05));  // corner: 3-4-5
}

TEST_CASE(
    "solid: the fluid around a body is cut a spacing from its particles, and check --write-initial shows "
    "it") {
  auto dir = test::unique_scratch("solid_cut");
  const auto frame = test::initial_frame(
      dir,
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.1, -0.1]\nmax = [1.1, 1.1]\n[particles]\nspacing = 0.02\n"
      "[time]\nend = 0.1\n[[wall]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n"
      "[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, 0.6]\n"
      "[[solid]]\nshape = \"cylinder\"\ncentre = [0.5, 0.3]\nradius = 0.1\n"
      "[[solid]]\nshape = \"box\"\nmin = [0.1, 0.0]\nmax = [0.2, 0.1]\n");
  auto kind = test::read_dataset(frame, "kind").values, x = test::read_dataset(frame, "position").values,
       body = test::read_dataset(frame, "body").values;
  std::vector<std::size_t> fluid, solid;
  for (std::size_t i = 0; i < kind.size(); ++i) {
    if (kind[i] == 0) fluid.push_back(i);
    if (body[i] >= 0) solid.push_back(i);
  }
  double nearest = 1e9;
  for (auto f : fluid)
    for (auto s : solid)
      nearest = std::min(nearest, std::hypot(x[3 * f] - x[3 * s], x[3 * f + 1] - x[3 * s + 1]));
  CHECK(nearest == doctest::Approx(0.02).epsilon(1e-9));  // a spacing, not closer
  // The cut is the bodies' area: 50 x 30 lattice points less the disc's (within R + d/2 of the
  // centre) and the box's 5 x 5.
  std::size_t in_disc = 0;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 30; ++j)
      in_disc += std::hypot((i + 0.5) * 0.02 - 0.5, (j + 0.5) * 0.02 - 0.3) < 0.11 - 1e-12;
  CHECK(fluid.size() == 50 * 30 - in_disc - 25);
}

// A body standing on the floor: the foot of its wetted face is a corner of the box, but the
// bottom face lies on the wall and sees no water, so that corner's normal is the wetted face's
// (the bisector told ISPH the water there is pushed into the floor: 10x hydrostatic at a
// piston's foot in the wave flume). A corner in the open keeps the bisector.
TEST_CASE("solid: a body's corner on a wall takes the normal of its wetted face") {
  auto dir = test::unique_scratch("solid_foot");
  const auto frame = test::initial_frame(
      dir,
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.1, -0.1]\nmax = [1.1, 1.1]\n[particles]\nspacing = 0.02\n"
      "[method]\nname = \"isph\"\n[time]\nend = 0.1\n[[wall]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n"
      "[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, 0.6]\n"
      "[[solid]]\nshape = \"box\"\nmin = [0.1, 0.0]\nmax = [0.2, 0.1]\nlayers = 1\n");
  auto x = test::read_dataset(frame, "position").values, n = test::read_dataset(frame, "wall_normal").values,
       body = test::read_dataset(frame, "body").values;
  auto normal_at = [&](double px, double py) {
    for (std::size_t i = 0; i < body.size(); ++i)
      if (body[i] >= 0 && std::hypot(x[3 * i] - px, x[3 * i + 1] - py) < 1e-9)
        return Vec<2>(n[3 * i], n[3 * i + 1]);
    FAIL("no body particle at (", px, ", ", py, ")");
    return Vec<2>(0, 0);
  };
  const double h = std::sqrt(0.5);
  CHECK((normal_at(0.19, 0.01) - Vec<2>(-1, 0)).norm() < 1e-12);  // feet: the side faces'
  CHECK((normal_at(0.11, 0.01) - Vec<2>(1, 0)).norm() < 1e-12);
  CHECK((normal_at(0.19, 0.09) - Vec<2>(-h, -h)).norm() < 1e-12);  // top corners: bisectors
  CHECK((normal_at(0.11, 0.09) - Vec<2>(h, -h)).norm() < 1e-12);
  CHECK((normal_at(0.15, 0.01) - Vec<2>(0, 1)).norm() < 1e-12);  // the bottom face keeps its own
}

TEST_CASE("solid: a sliding plate drives Couette flow that follows the start-up series (WCSPH)") {
  auto dir = test::unique_scratch("couette");
  auto r = test::run_command(bin() + " run " + test::scene_path("couette_2d.toml") + " --quiet --out " +
                             dir.string() + " --set time.end=0.3");
  REQUIRE_MESSAGE(r.code == 0, r.output);
  const double U = 1.25e-5, H = 1e-3, nu = 1e-6;
  // The profile at t = 0.05 s (the series' first terms still large) and 0.2 s, as an L2 error
  // over the particles relative to U: within 2% (Morris et al. report about 1% at this
  // resolution); measured 0.38% and 0.26%.
  for (double t : {0.05, 0.2}) {
    CAPTURE(t);
    const auto frame = test::frame_path(dir, int(std::lround(t / 0.05)));
    auto kind = test::read_dataset(frame, "kind").values, x = test::read_dataset(frame, "position").values,
         v = test::read_dataset(frame, "velocity").values;
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < kind.size(); ++i)
      if (kind[i] == 0) sum += std::pow(v[3 * i] - couette_u(x[3 * i + 1], t, U, H, nu), 2), ++n;
    CHECK(n == 800);
    CHECK(std::sqrt(sum / n) / U < 0.02);
  }
  // The drag on the sliding plate (force probe, N/m): within 3%; measured within 1%.
  CHECK(check_couette_drag(dir / "probes.csv", 0.03) >= 20);
}

// MPS and ISPH keep the pressure on a body's first wall layer; their force probe integrates it
// over the surface and adds the wall shear (src/systems/probes/solid_surface_force.hpp): MPS its
// viscous term's reaction, ISPH the Shepard slope of the fluid velocity at the wall. The same
// Couette start-up as above at H / d = 10 (the bucket multigrid does not wrap periodic axes:
// Jacobi), to t = 0.2 s; the drag from t = 0.1 s within 8% of the series: their profiles are
// 2-6% off it at H / d = 20 (their no-slip holds at the first wall layer, half a spacing inside
// the plate), twice as far at half the resolution. Measured at H / d = 10: 0.946-0.981 (MPS),
// 0.964-0.989 (ISPH); at H / d = 20: 0.968-0.994 and 0.980-0.997.
TEST_CASE("solid: MPS and ISPH read the sliding plate's drag from their own wall layer") {
  for (const char* method : {"mps", "isph"}) {
    CAPTURE(method);
    auto dir = test::unique_scratch(std::string("couette_") + method);
    auto r = test::run_command(bin() + " run " + test::scene_path("couette_2d.toml") + " --quiet --out " +
                               dir.string() + " --set time.end=0.2 --set method.name=" + method +
                               " --set solver.preconditioner=jacobi --set particles.spacing=1e-4");
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CHECK(check_couette_drag(dir / "probes.csv", 0.08) >= 10);
  }
}

TEST_CASE("solid: bad geometry is bad input naming the solid and the problem") {
  const std::string base =
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.1, -0.1]\nmax = [1.1, 1.1]\n[particles]\nspacing = 0.02\n"
      "[time]\nend = 0.1\n[[wall]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[[fluid]]\nmin = [0.0, 0.0]\nmax = "
      "[1.0, 0.6]\n";
  CHECK(test::scene_error(base + "[[solid]]\nshape = \"cylinder\"\ncentre = [1.05, 0.3]\nradius = 0.1\n") ==
        "bad.toml:18:10: [[solid]] #0 lies (partly) outside the domain");
  CHECK(test::scene_error(base + "[[solid]]\nshape = \"box\"\nmin = [0.5, -0.04]\nmax = [0.6, 0.1]\n") ==
        "bad.toml:17:9: [[solid]] #0 reaches into the particle layers of [[wall]] #0 (their particles would "
        "sit on each other)");
  CHECK(test::scene_error(base + "[[solid]]\nshape = \"box\"\nmin = [0.5, 0.0]\nmax = [0.6, 0.1]\n"
                                 "[[solid]]\nshape = \"cylinder\"\ncentre = [0.6, 0.1]\nradius = 0.05\n") ==
        "bad.toml:21:9: [[solid]] #1 overlaps [[solid]] 'solid0' (their particles would sit on each other)");
  CHECK(test::scene_error(base + "[[solid]]\nshape = \"box\"\nmin = [0.5, 0.0]\n") ==
        "bad.toml:18:7: [[solid]] #0 (a box) needs min and max");
  CHECK(
      test::scene_error(base + "[[solid]]\nshape = \"cone\"\n") ==
      "bad.toml:17:9: 'shape' in [[solid]] #0 is 'cone'; allowed: box, cylinder, sphere, mesh (did you mean "
      "'box'?)");
  CHECK(test::scene_error(base + "[[solid]]\nshape = \"box\"\nmin = [0.5, 0.0]\nmax = [0.6, 0.1]\n"
                                 "[[probe]]\nname = \"f\"\ntype = \"force\"\nsolid = \"block\"\n") ==
        "bad.toml:23:9: [[probe]] 'f': there is no [[solid]] named 'block'");
  CHECK(test::scene_error(base + "[[solid]]\nshape = \"box\"\nmin = [0.5, 0.0]\nmax = [0.53, 0.1]\n") ==
        "bad.toml:19:7: [[solid]] #0 is 1.5 spacings wide on axis 0: a box body takes whole spacings (its "
        "particles sit on min + (k + 1/2) d); make max - min a multiple of 0.02");
  // Nothing is written on bad input.
  auto dir = test::unique_scratch("solid_bad");
  test::write_text(dir / "bad.toml",
                   base + "[[solid]]\nshape = \"cylinder\"\ncentre = [1.05, 0.3]\nradius = 0.1\n");
  auto r =
      test::run_command(bin() + " run " + (dir / "bad.toml").string() + " --out " + (dir / "out").string());
  CHECK(r.code == 2);
  CHECK(!std::filesystem::exists(dir / "out"));
}

TEST_CASE("solid: a piston wave maker makes the waves of linear wave-maker theory (WCSPH)") {
  // scenes/wave_flume_2d.toml at d = 0.02 m (h / d = 10) to t = 5 s: the wave height 0.6 m
  // (three depths) from the paddle in periods 2-4 against Biesel's. Within 10% (the issue's
  // bound; measured -5.6% here and -8% 1 m from the paddle: the scheme's damping).
  auto dir = test::unique_scratch("wave_flume");
  auto r = test::run_command(bin() + " run " + test::scene_path("wave_flume_2d.toml") + " --quiet --out " +
                             dir.string() + " --set particles.spacing=0.02 --set time.end=5");
  REQUIRE_MESSAGE(r.code == 0, r.output);
  CHECK_MESSAGE(test::within_relative(test::biesel_height(), 0.0406, 0.001),
                "Biesel height " << test::biesel_height());
  auto csv = test::read_csv(dir / "probes.csv");
  for (double h : test::wave_heights(csv, "eta_0.6m"))
    CHECK_MESSAGE(test::within_relative(h, 1.0, 0.10), "height over Biesel's " << h);
  // The force on the paddle over whole periods: the water's hydrostatic thrust -rho g h^2 / 2 =
  // -196 N/m (the waves' mean momentum flux adds about 1%); within 10%, measured -188 N/m.
  CHECK_MESSAGE(test::within_relative(test::mean_paddle_force(csv), -1000 * 9.81 * 0.2 * 0.2 / 2, 0.10),
                "mean paddle force " << test::mean_paddle_force(csv) << " N/m");
}

// The same flume under ISPH (scenes/wave_flume_isph_2d.toml: the violent-flow set-up, h / d = 20),
// the paddle's velocity in its wall rows (eq. 17). Heights 0.6 m and 1 m from the paddle in
// periods 2-4 within 10% of Biesel's on average, each within 15% (measured below). At h / d =
// 10 the heights stray by up to 17%. The mean force on the paddle over whole periods: the
// hydrostatic thrust within 10%, as under WCSPH (measured -196.9 N/m; -203 N/m from the wall
// layer's own pressure before the surface pressure of issue 57; samples 0.01 s apart within
// 169 N/m of each other). Before the paddle's foot took its face's normal (geometry: a corner on
// a wall) the bisector there made pressure spikes of 20 kPa and the force swung by +-3 kN/m.
TEST_CASE("solid: an ISPH piston wave maker makes the waves of linear wave-maker theory at h/d = 20") {
  auto dir = test::unique_scratch("wave_flume_isph");
  auto r = test::run_command(bin() + " run " + test::scene_path("wave_flume_isph_2d.toml") +
                             " --quiet --out " + dir.string() + " --set time.end=5");
  REQUIRE_MESSAGE(r.code == 0, r.output);
  auto csv = test::read_csv(dir / "probes.csv");
  for (const char* probe : {"eta_0.6m", "eta_1m"}) {
    CAPTURE(probe);
    auto heights = test::wave_heights(csv, probe);
    MESSAGE(std::string(probe), ": heights over Biesel's in periods 2-4: ", heights[0], ", ", heights[1],
            ", ", heights[2]);
    // Each period's height within 15% and their mean within the 10%. Measured 2026-11-29:
    // 1.064, 1.025, 0.984 at 0.6 m and 0.861, 0.989, 1.020 at 1 m (mean 0.957): the second
    // period's wave at 1 m is 14% low since the ISPH step rule of 8d18fb7 (1.03 before), which
    // issue 49 owns. Until 2026-11-29 this was doctest's Approx(1).epsilon(0.1), which accepts
    // 0.80-1.22 (test audit round three, row 5).
    double mean = 0;
    for (double h : heights) {
      CHECK_MESSAGE(test::within_relative(h, 1.0, 0.15), "height over Biesel's " << h);
      mean += h / heights.size();
    }
    CHECK_MESSAGE(test::within_relative(mean, 1.0, 0.10), "mean height over Biesel's " << mean);
  }
  MESSAGE("mean force on the paddle over t = 2-5 s: ", test::mean_paddle_force(csv),
          " N/m (hydrostatic thrust -196 N/m)");
  CHECK_MESSAGE(test::within_relative(test::mean_paddle_force(csv), -1000 * 9.81 * 0.2 * 0.2 / 2, 0.10),
                "mean paddle force " << test::mean_paddle_force(csv) << " N/m");
}

TEST_CASE(
    "solid: a tabulated displacement moves a body along the table, and imported fluid may not sit in a "
    "body") {
  auto dir = test::unique_scratch("solid_table");
  std::filesystem::create_directories(dir);
  test::write_text(dir / "motion.csv", "t, dx, dy\n0.0, 0.0, 0.0\n1.0, 0.1, 0.0\n2.0, 0.1, 0.05\n");
  const std::string base =
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.1, -0.1]\nmax = [1.1, 1.1]\n[particles]\nspacing = 0.02\n"
      "[physics]\ngravity = [0.0, 0.0]\n[time]\nend = 1.5\n[output]\ninterval = 1.5\nfields = "
      "[\"body_origin\", \"body\"]\n"
      "[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.2, 0.2]\n";
  test::write_text(dir / "s.toml", base +
                                       "[[solid]]\nshape = \"box\"\nmin = [0.5, 0.5]\nmax = [0.6, 0.6]\n"
                                       "displacement_table = \"motion.csv\"\n");
  auto r = test::run_command(bin() + " run " + (dir / "s.toml").string() + " --quiet --out " +
                             (dir / "out").string());
  REQUIRE_MESSAGE(r.code == 0, r.output);
  // The frame at t = 1.5 s shows the body where the last step started (t = 1.5 s - dt), on the
  // table's second segment: dx = 0.1, dy = 0.05 (t - 1), velocity (0, 0.05).
  const auto frame = test::last_frame(dir / "out");
  auto body = test::read_dataset(frame, "body").values, x = test::read_dataset(frame, "position").values,
       o = test::read_dataset(frame, "body_origin").values, v = test::read_dataset(frame, "velocity").values;
  std::size_t moved = 0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (body[i] != 0) continue;
    ++moved;
    CHECK(x[3 * i] - o[3 * i] == doctest::Approx(0.1).epsilon(1e-12));
    CHECK_MESSAGE(test::within_relative(x[3 * i + 1] - o[3 * i + 1], 0.025, 0.01),  // t - dt for t = 1.5
                  "dy " << x[3 * i + 1] - o[3 * i + 1]);
    CHECK(v[3 * i] == 0.0);
    CHECK(v[3 * i + 1] == doctest::Approx(0.05).epsilon(1e-12));
  }
  CHECK(moved == 25);
  test::write_text(dir / "bad.csv", "t, dx, dy\n0.0, 0.0, 0.0\n0.0, 0.1, 0.0\n");
  CHECK(test::scene_error(base +
                          "[[solid]]\nshape = \"box\"\nmin = [0.5, 0.5]\nmax = [0.6, 0.6]\n"
                          "displacement_table = \"" +
                          (dir / "bad.csv").string() + "\"\n") ==
        "bad.toml:22:22: [[solid]] #0 displacement_table: " + (dir / "bad.csv").string() +
            ":3: the times must increase");
  CHECK(test::scene_error(
            base +
            "[method]\nname = \"isph\"\n[[solid]]\nshape = \"box\"\nmin = [0.5, 0.5]\nmax = [0.6, 0.6]\n"
            "displacement = [\"t\", \"0\"]\n") ==
        "");  // a moving body under ISPH (its wall rows take the wall's velocity, eq. 17)
  CHECK(test::scene_error(
            base + "[method]\nname = \"isph\"\ndescription = \"eulerian\"\n[[solid]]\nshape = \"box\"\n"
                   "min = [0.5, 0.5]\nmax = [0.6, 0.6]\ndisplacement = [\"t\", \"0\"]\n") ==
        "bad.toml:25:16: [[solid]] #0 moves, but method isph with description = \"eulerian\" keeps every "
        "particle in place");
  test::write_text(dir / "in_body.csv", "x, y\n0.55, 0.55\n");
  CHECK(test::scene_error(base +
                          "[[solid]]\nshape = \"box\"\nmin = [0.5, 0.5]\nmax = [0.6, 0.6]\n"
                          "[[import]]\nfile = \"" +
                          (dir / "in_body.csv").string() + "\"\n") ==
        "bad.toml:23:8: [[import]] #0: a particle at (0.55, 0.55) lies in [[solid]] 'solid0'");
}

// A table's acceleration (Adami's wall pressure takes it): the change of slope over one row
// interval around t. Rows of x = a t^2 / 2 every 0.1 s read a between them and at the rows
// (each window holds one change of slope, a 0.1); before the table and after it the body rests.
TEST_CASE("solid: a tabulated motion's acceleration is its change of slope per row interval") {
  std::vector<MotionSample> table;
  const double a = 2.5;
  for (int k = 0; k <= 20; ++k) table.push_back({0.1 * k, {0.5 * a * 0.01 * k * k, 0.0, 0.0}});
  for (double t : {0.33, 0.5, 1.0, 1.37, 1.9})
    CHECK(motion_acceleration(table, t)[0] == doctest::Approx(a).epsilon(1e-9));
  CHECK(motion_acceleration(table, -1.0)[0] == 0.0);
  CHECK(motion_acceleration(table, 3.0)[0] == 0.0);
  CHECK(motion_acceleration(table, 0.37)[1] == 0.0);
}
