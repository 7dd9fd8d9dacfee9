// The lid-driven cavity at Re = 100 (scenes/cavity_re100_2d.toml, 50 x 50, ISPH Eulerian; issue
// 56) against Ghia, Ghia & Shin (1982, tools/reference/ghia_1982_re100.csv): velocity probes at
// Ghia's own points on the two centrelines (x = 0.5 for u, y = 0.5 for v; Shepard-interpolated from
// the particles, docs/output.md), read at the steady stop.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "shipped_scene_run.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

struct GhiaPoint {
  double y, u, x, v;
};

std::vector<GhiaPoint> ghia_re100() {
  auto table = test::read_csv(test::source_dir() / "tools" / "reference" / "ghia_1982_re100.csv");
  std::vector<GhiaPoint> points;
  for (std::size_t k = 0; k < table["y"].size(); ++k)
    points.push_back({table["y"][k], table["u"][k], table["x"][k], table["v"][k]});
  REQUIRE(points.size() == 17);
  return points;
}

}  // namespace

// Measured 2026-11-29 (1 thread, 20 s): steady at t = 13.7 s; u within 1.9% of U at Ghia's points
// below the lid's boundary layer (y <= 0.86) and 4.7-6.4% low in it (y = 0.953-0.977: the layer
// is 2-3 spacings thick at this resolution and the lid's no-slip acts at its one particle layer,
// first order); v within 1.9% at every interior point. Asserted: 3% outside the layer (the issue's
// bound, which it sets at 100 x 100), and 8% in it so that a change that makes the layer worse
// fails (docs/validation.md, "Lid-driven cavity", has the finer run).
TEST_CASE("cavity: the Re = 100 lid-driven cavity reaches Ghia's centreline velocities") {
  const auto ghia = ghia_re100();
  std::string probes;
  for (std::size_t k = 0; k < ghia.size(); ++k) {
    if (ghia[k].y > 0 && ghia[k].y < 1)
      probes += "[[probe]]\nname = \"ghia_u_" + std::to_string(k) +
                "\"\ntype = \"velocity\"\nposition = [0.5, " + std::to_string(ghia[k].y) + "]\n";
    if (ghia[k].x > 0 && ghia[k].x < 1)
      probes += "[[probe]]\nname = \"ghia_v_" + std::to_string(k) +
                "\"\ntype = \"velocity\"\naxis = 1\nposition = [" + std::to_string(ghia[k].x) + ", 0.5]\n";
  }
  const auto out = test::run_shipped_scene("cavity_re100", "cavity_re100_2d.toml", probes, {});
  const auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "steady");
  auto csv = test::read_csv(out / "probes.csv");
  for (std::size_t k = 0; k < ghia.size(); ++k) {
    if (ghia[k].y > 0 && ghia[k].y < 1) {
      const double got = csv["ghia_u_" + std::to_string(k)].back(), error = std::abs(got - ghia[k].u);
      MESSAGE("u at y = ", ghia[k].y, ": ", got, " against ", ghia[k].u);
      CHECK_MESSAGE(error < (ghia[k].y <= 0.9 ? 0.03 : 0.08), "y = " << ghia[k].y);
    }
    if (ghia[k].x > 0 && ghia[k].x < 1) {
      const double got = csv["ghia_v_" + std::to_string(k)].back();
      MESSAGE("v at x = ", ghia[k].x, ": ", got, " against ", ghia[k].v);
      CHECK_MESSAGE(std::abs(got - ghia[k].v) < 0.03, "x = " << ghia[k].x);
    }
  }
}
