// Stability at the extremes (issue 9, first cases): each case either keeps physical bounds or
// fails cleanly with exit code 2 or 3 and a message that names the place.
#include <doctest/doctest.h>

#include <cmath>

#include "app/exit_codes.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

namespace {
std::string bin() { return RYUSHI_BINARY; }
}  // namespace

TEST_CASE("stability: a single fluid particle falls freely, v = g t, under every method") {
  auto dir = test::scratch("stability_single");
  auto scene = dir / "single.toml";
  // One particle 0.3 m above the floor of a box: it falls 0.196 m in 0.2 s, touching nothing.
  test::write_text(scene, test::block_scene("[0.5, 0.5]", "[0.55, 0.55]", 0.2,
                                            "[[wall]]\nmin = [0.2, 0.2]\nmax = [0.8, 0.8]\n"));
  for (const char* method : {"wcsph", "mps", "isph"}) {
    auto out = dir / method;
    auto r = test::run_command(bin() + " run " + scene.string() + " --out " + out.string() +
                               " --quiet --set method.name=" + method);
    REQUIRE_MESSAGE(r.code == kExitDone, method << ": " << r.output);
    auto summary = test::read_text(out / "summary.json");
    CHECK(test::json_number(summary, "fluid_particles") == 1);
    // Constant acceleration: every integrator here is exact for it, to round-off.
    CHECK_MESSAGE(test::json_number(summary, "max_speed") == doctest::Approx(9.81 * 0.2).epsilon(1e-9), method);
  }
}

TEST_CASE("stability: 1e-6 m particles 5 km from the origin keep their density, and a 1e4 m box for them is refused") {
  auto dir = test::scratch("stability_tiny");
  const std::string body =
      "[scene]\ndimension = 2\n[particles]\nspacing = 1e-6\n[time]\nend = 1e-5\n"
      "[[fluid]]\nmin = [5000.0, 0.00001]\nmax = [5000.00002, 0.00003]\n"
      "[[wall]]\nmin = [4999.99999, 0.00001]\nmax = [5000.00003, 0.00005]\n";
  // The relative precision at 5 km is 1e-12 of a spacing: the run is an ordinary small tank.
  test::write_text(dir / "near.toml", body + "[domain]\nmin = [4999.99, 0.0]\nmax = [5000.01, 0.01]\n");
  auto r = test::run_command(bin() + " run " + (dir / "near.toml").string() + " --out " + (dir / "out").string() + " --quiet");
  REQUIRE_MESSAGE(r.code == kExitDone, r.output);
  auto summary = test::read_text(dir / "out" / "summary.json");
  CHECK(test::json_number(summary, "fluid_particles") == 400);
  CHECK(test::json_number(summary, "max_density_deviation") < 0.01);  // WCSPH's ~1% compressibility
  // A 1e4 m domain at this spacing is 1e19 cells of the neighbour search: refused before any
  // allocation, with the key's place.
  test::write_text(dir / "huge.toml", body + "[domain]\nmin = [0.0, 0.0]\nmax = [10000.0, 10000.0]\n");
  auto huge = test::run_command(bin() + " run " + (dir / "huge.toml").string() + " --out " + (dir / "huge").string() + " --quiet");
  CHECK(huge.code == kExitBadInput);
  CHECK_MESSAGE(huge.output.find("huge.toml:") != std::string::npos, huge.output);
  CHECK_MESSAGE(huge.output.find("shrink [domain]") != std::string::npos, huge.output);
}
