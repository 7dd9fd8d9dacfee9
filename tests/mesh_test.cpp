// STL meshes ([[mesh]], src/geometry/triangle_mesh.cpp): filling a closed mesh with fluid, a mesh
// as a solid body with outward surface normals, and the errors of bad meshes. The meshes are
// written by tools/make_stl.py into the test's scratch folder.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "h5_read.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

std::string bin() {
  return RYUSHI_BINARY;
}

std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = test::unique_scratch(name);
  std::filesystem::create_directories(dir);
  return dir;
}

void make_stl(const std::string& args) {
  auto r = test::run_command("/usr/bin/python3 " + (test::source_dir() / "tools" / "make_stl.py").string() +
                             " " + args);
  REQUIRE_MESSAGE(r.code == 0, r.output);
}

// A 3D scene in [-0.2, 0.5]^3 at d = 0.01 with `body` appended; ISPH by default (one wall layer,
// with normals).
std::string scene_3d(const std::string& body, const std::string& method = "isph") {
  return "[scene]\ndimension = 3\n[domain]\nmin = [-0.2, -0.2, -0.2]\nmax = [0.5, 0.5, 0.5]\n[particles]\n"
         "spacing = 0.01\n[method]\nname = \"" +
         method + "\"\n[time]\nend = 0.1\n" + body;
}

}  // namespace

TEST_CASE("mesh: an STL cube and an STL sphere fill with volume / d^3 particles") {
  auto dir = fresh_dir("mesh_fill");
  make_stl("cube 0.2 " + (dir / "cube.stl").string());                               // ASCII
  make_stl("sphere 0.1 4 " + (dir / "sphere.stl").string() + " --binary --inward");  // binary, wound inward
  auto frame = test::initial_frame(
      dir, scene_3d("[[mesh]]\nname = \"cube\"\nfile = \"cube.stl\"\ntranslate = [0.25, 0.25, 0.25]\n"
                    "[[mesh]]\nname = \"ball\"\nfile = \"sphere.stl\"\n"
                    "[[fluid]]\nmin = [0.15, 0.15, 0.15]\nmax = [0.35, 0.35, 0.35]\nmesh = \"cube\"\n"
                    "[[fluid]]\nmin = [-0.1, -0.1, -0.1]\nmax = [0.1, 0.1, 0.1]\nmesh = \"ball\"\n"));
  auto kind = test::read_dataset(frame, "kind").values, x = test::read_dataset(frame, "position").values;
  std::size_t cube = 0, ball = 0;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 0) (x[3 * i] > 0.125 ? cube : ball) += 1;
  // The cube's faces lie on the lattice's cell faces: exactly (0.2 / 0.01)^3.
  CHECK(cube == 8000);
  // The sphere, R = 10 d: within 2% of 4/3 pi R^3 / d^3 (the 1280-face mesh holds 0.4% less
  // volume; the lattice count measured +0.8%). A mesh wound inward is turned outward on reading
  // (inverted, every point would be "outside" and nothing filled).
  const double expected = 4.0 / 3 * std::numbers::pi * 1000;
  CHECK(std::abs(ball / expected - 1) < 0.02);
}

TEST_CASE("mesh: an STL sphere as a solid has its surface normals pointing outward") {
  auto dir = fresh_dir("mesh_normals");
  make_stl("sphere 0.1 4 " + (dir / "sphere.stl").string() + " --binary");
  auto frame =
      test::initial_frame(dir, scene_3d("[[mesh]]\nname = \"ball\"\nfile = \"sphere.stl\"\n"
                                        "[[fluid]]\nmin = [0.15, 0.15, 0.15]\nmax = [0.35, 0.35, 0.35]\n"
                                        "[[solid]]\nshape = \"mesh\"\nmesh = \"ball\"\n"));
  auto body = test::read_dataset(frame, "body").values, x = test::read_dataset(frame, "position").values,
       n = test::read_dataset(frame, "wall_normal").values;
  std::size_t count = 0;
  double worst = 0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (body[i] != 0) continue;
    ++count;
    const double r =
        std::sqrt(x[3 * i] * x[3 * i] + x[3 * i + 1] * x[3 * i + 1] + x[3 * i + 2] * x[3 * i + 2]);
    // wall_normal points from the fluid into the body: the surface's outward normal is its negative.
    const double cosine =
        -(n[3 * i] * x[3 * i] + n[3 * i + 1] * x[3 * i + 1] + n[3 * i + 2] * x[3 * i + 2]) / r;
    worst = std::max(worst, std::acos(std::min(1.0, cosine)) * 180 / std::numbers::pi);
    CHECK(r > 0.1 - 0.01 - 1e-9);  // the one ISPH layer: within a spacing of the surface
  }
  // At d = R / 10 every normal within 5 degrees of the radial direction (measured 2.4; the
  // facets of the 1280-face mesh are about 4 degrees across).
  CHECK(count > 1000);
  CHECK(worst < 5.0);
}

TEST_CASE("mesh: an open surface is a wall with its layers behind it, and cannot be filled") {
  auto dir = fresh_dir("mesh_open");
  make_stl("open-box 0.2 " + (dir / "open.stl").string() + " --inward");  // faces towards the water
  // A box open at the top as a tank, its faces turned towards the water: three layers outside its
  // floor and sides (behind the faces), fluid inside.
  auto frame = test::initial_frame(
      dir, scene_3d("[[mesh]]\nname = \"tank\"\nfile = \"open.stl\"\ntranslate = [0.15, 0.15, 0.15]\n"
                    "[[fluid]]\nmin = [0.05, 0.05, 0.05]\nmax = [0.25, 0.25, 0.15]\n"
                    "[[solid]]\nshape = \"mesh\"\nmesh = \"tank\"\nlayers = 3\n",
                    "wcsph"));
  auto body = test::read_dataset(frame, "body").values, x = test::read_dataset(frame, "position").values,
       kind = test::read_dataset(frame, "kind").values;
  CHECK(std::count(kind.begin(), kind.end(), 0.0) == 20 * 20 * 10);  // the water, none cut
  std::size_t walls = 0, inside = 0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (body[i] != 0) continue;
    ++walls;
    bool in_box = true;
    for (int a = 0; a < 3; ++a) in_box = in_box && x[3 * i + a] > 0.05 && x[3 * i + a] < 0.25;
    inside += in_box;
  }
  CHECK(walls > 0);
  CHECK(inside == 0);
  CHECK(test::scene_error(
            scene_3d("[[mesh]]\nname = \"tank\"\nfile = \"" + (dir / "open.stl").string() +
                     "\"\n[[fluid]]\nmin = [0.0, 0.0, 0.0]\nmax = [0.1, 0.1, 0.1]\nmesh = \"tank\"\n")) ==
        "bad.toml:18:8: [[fluid]] #0: [[mesh]] 'tank' is not closed, so it has no inside to fill (it can be "
        "a [[solid]] "
        "surface)");
}

TEST_CASE("mesh: a missing or malformed STL file is bad input naming the file") {
  auto dir = fresh_dir("mesh_bad");
  make_stl("garbage " + (dir / "bad.stl").string());
  const std::string fluid = "[[fluid]]\nmin = [0.0, 0.0, 0.0]\nmax = [0.1, 0.1, 0.1]\n";
  CHECK(test::scene_error(
            scene_3d("[[mesh]]\nname = \"m\"\nfile = \"" + (dir / "none.stl").string() + "\"\n" + fluid)) ==
        "bad.toml:14:8: [[mesh]] 'm': cannot open " + (dir / "none.stl").string());
  CHECK(test::scene_error(
            scene_3d("[[mesh]]\nname = \"m\"\nfile = \"" + (dir / "bad.stl").string() + "\"\n" + fluid)) ==
        "bad.toml:14:8: [[mesh]] 'm': " + (dir / "bad.stl").string() +
            " is not a triangle mesh CGAL can read (STL, ASCII or binary; a surface without degenerate or "
            "non-manifold faces)");
  // 300 random triangles crossing each other became a solid body without a word; a NaN vertex
  // was reported as a particle outside the domain (issue 51, point 4).
  make_stl("random 300 0.2 " + (dir / "random.stl").string());
  make_stl("nan-cube 0.2 " + (dir / "nan.stl").string());
  const std::string solid = "[[solid]]\nname = \"b\"\nshape = \"mesh\"\nmesh = \"m\"\n";
  const auto random = test::scene_error(
      scene_3d("[[mesh]]\nname = \"m\"\nfile = \"" + (dir / "random.stl").string() + "\"\n" + fluid + solid));
  CHECK_MESSAGE(random.find("bad.toml:14:8: [[mesh]] 'm': " + (dir / "random.stl").string() +
                            ": face 1 crosses face ") == 0,
                random);
  CHECK(random.find(" pairs of faces intersect; a surface to fill or stand on may not cross itself)") !=
        std::string::npos);
  CHECK(test::scene_error(scene_3d("[[mesh]]\nname = \"m\"\nfile = \"" + (dir / "nan.stl").string() + "\"\n" +
                                   fluid + solid)) ==
        "bad.toml:14:8: [[mesh]] 'm': " + (dir / "nan.stl").string() +
            ": face 4 has a vertex that is not a finite number (nan, 0, 0)");
  CHECK(test::scene_error(scene_3d(fluid + "mesh = \"nothing\"\n")) ==
        "bad.toml:15:8: [[fluid]] #0: there is no [[mesh]] named 'nothing'");
  // Nothing written.
  test::write_text(dir / "run.toml", scene_3d("[[mesh]]\nname = \"m\"\nfile = \"bad.stl\"\n" + fluid));
  auto r =
      test::run_command(bin() + " run " + (dir / "run.toml").string() + " --out " + (dir / "out").string());
  CHECK(r.code == 2);
  CHECK(!std::filesystem::exists(dir / "out"));
}

// A closed mesh as a container under ISPH: until 2026-11-27 refused (one wall layer with normals
// on a curve was not stable: the ball of the analytic shape blew up at t = 0.36 s); now the
// lattice's layers with Adami's wall pressure as their rows (wall_rows = "adami", the default for
// a round or mesh container). The STL sphere (R = 0.2 m = 8 d, 1,280 faces), half full, at rest
// to t = 1 s. Measured 2026-11-27: kinetic energy at most 7.6e-5 J (17 kg of water), the force on
// the vessel within 0.5% of the water's weight, as the analytic ball (tests/container_test.cpp).
TEST_CASE("mesh: water at rest in a closed STL vessel stays at rest and weighs its weight (ISPH)") {
  auto dir = fresh_dir("mesh_vessel_isph");
  make_stl("sphere 0.2 4 " + (dir / "vessel.stl").string() + " --binary");
  test::write_text(
      dir / "run.toml",
      "[scene]\ndimension = 3\n[domain]\nmin = [-0.1, -0.1, -0.1]\nmax = [0.5, 0.5, 0.5]\n[particles]\n"
      "spacing = 0.025\n[material]\ndensity = 1000.0\nviscosity = 1.0e-3\n[method]\nname = "
      "\"isph\"\n[time]\nend = 1.0\n"
      "[output]\ninterval = 1.0\nprobe_interval = 0.05\n[[mesh]]\nname = \"vessel\"\nfile = \"vessel.stl\"\n"
      "translate = [0.2, 0.2, 0.2]\n[[fluid]]\nmin = [0.0, 0.0, 0.0]\nmax = [0.4, 0.4, 0.2]\n[[solid]]\nname "
      "= \"vessel\"\n"
      "shape = \"mesh\"\nmesh = \"vessel\"\ncontainer = true\n[[probe]]\nname = \"ke\"\ntype = "
      "\"kinetic_energy\"\n"
      "[[probe]]\nname = \"fz\"\ntype = \"force\"\nsolid = \"vessel\"\naxis = 2\n");
  auto r = test::run_command(bin() + " run " + (dir / "run.toml").string() + " --out " +
                             (dir / "out").string() + " --quiet");
  REQUIRE_MESSAGE(r.code == 0, r.output);
  auto probes = test::read_csv(dir / "out" / "probes.csv");
  const double weight = test::json_number(test::read_text(dir / "out" / "summary.json"), "fluid_mass") * 9.81;
  double largest = 0, force = 0;
  int samples = 0;
  for (std::size_t k = 0; k < probes["time"].size(); ++k) {
    largest = std::max(largest, probes["ke"][k]);
    if (probes["time"][k] >= 0.5) force += probes["fz"][k], ++samples;
  }
  REQUIRE(samples >= 5);
  MESSAGE("kinetic energy at most ", largest, " J; force ", -force / samples, " N against the weight ",
          weight, " N");
  CHECK(largest < 1e-3);
  CHECK(std::abs(-force / samples / weight - 1) < 0.01);
}
