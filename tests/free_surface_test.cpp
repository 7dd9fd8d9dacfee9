// Free-surface detection on a square, a disc, a square with a hole and a dam-break-like column
// against walls, at 0% and 10% disorder: every outer-layer particle flagged, no interior one
// (verification/free_surface_check.hpp defines the layers). Normals point outwards.
#include <doctest/doctest.h>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"
#include "verification/free_surface_check.hpp"

using namespace ryushi;

TEST_CASE("free surface: outer layer flagged, interior untouched, for every rule at 0% and 10% disorder") {
  for (std::string rule : {"marrone", "isph2", "mps"})
    for (double disorder : {0.0, 0.1})
      for (std::string shape : {"square", "disc", "square_with_hole", "column"}) {
        CAPTURE(rule);
        CAPTURE(disorder);
        CAPTURE(shape);
        auto s = score_free_surface(shape, rule, disorder);
        CHECK(s.outer > 50);
        CHECK(s.interior > 500);
        CHECK(s.outer_flagged == s.outer);
        CHECK(s.interior_flagged == 0);
      }
}

TEST_CASE("free surface: normals of a square's faces point outwards") {
  const double d = 0.02;
  std::vector<Vec<2>> x;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) x.push_back(Vec<2>(0.2 + (i + 0.5) * d, 0.2 + (j + 0.5) * d));
  std::vector<double> volume(x.size(), d * d);
  Domain<2> dom;
  CellGrid<2> grid;
  NeighbourList nl;
  Kernel<2> kernel(KernelType::WendlandC2, 1.5 * d);
  build_neighbour_list<2>(dom, kernel.support(), x, grid, nl);
  ParticleView<2> v{x, volume, nl, kernel, dom};
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto r = detect_free_surface(v, i, FreeSurfaceRule::Marrone, {});
    int col = static_cast<int>(i) / 30, row = static_cast<int>(i) % 30;
    bool mid = row > 3 && row < 26 && col > 3 && col < 26;
    if (col == 29 && row > 3 && row < 26) CHECK(r.normal.dot(Vec<2>(1, 0)) > 0.99);   // right face
    if (row == 0 && col > 3 && col < 26) CHECK(r.normal.dot(Vec<2>(0, -1)) > 0.99);  // bottom face
    if (mid) CHECK_FALSE(r.surface);
    CHECK(r.normal.norm() == doctest::Approx(1.0));
  }
}

TEST_CASE("free surface: the registered system writes flags and normals in a scene") {
  auto dir = test::scratch("free_surface_system");
  test::write_text(dir / "s.toml", test::block_scene("[0.2, 0.2]", "[0.6, 0.6]", 0.001,
                                                     "[physics]\ngravity = [0.0, 0.0]\n[output]\ninterval = 0.001\n"
                                                     "fields = [\"free_surface\", \"surface_normal\"]\n"
                                                     "[[systems]]\nname = \"free_surface_detection\"\nrule = \"marrone\"\n"));
  RunOptions opt;
  opt.scene = (dir / "s.toml").string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  REQUIRE(run_scene(opt) == kExitDone);
  CHECK(test::read_text(dir / "out" / "particles.xdmf").find(":/free_surface") != std::string::npos);
  // Read back after the step: the block's outer ring is flagged, its inside is not, and the
  // normals of the flagged edge particles point out of the block (an 8 x 8 block, d = 0.05).
  auto frame = dir / "out" / "frames" / "frame_00001.h5";
  auto x = test::read_dataset(frame, "position").values, n = test::read_dataset(frame, "surface_normal").values;
  auto flag = test::read_dataset(frame, "free_surface").values, kind = test::read_dataset(frame, "kind").values;
  int outer = 0, inner_flagged = 0, outward = 0;
  for (std::size_t i = 0; i < kind.size(); ++i) {
    if (kind[i] != 0) continue;
    const double px = x[3 * i], py = x[3 * i + 1];
    const bool edge = px < 0.25 || px > 0.55 || py < 0.25 || py > 0.55;
    const bool deep = px > 0.3 && px < 0.5 && py > 0.3 && py < 0.5;
    if (edge) {
      ++outer;
      CHECK_MESSAGE(flag[i] == 1, "edge particle at (" << px << ", " << py << ") not flagged");
      // Out of the block: the normal points away from its centre (0.4, 0.4).
      if (n[3 * i] * (px - 0.4) + n[3 * i + 1] * (py - 0.4) > 0) ++outward;
    }
    if (deep && flag[i] == 1) ++inner_flagged;
  }
  CHECK(outer == 28);
  CHECK(outward == outer);
  CHECK(inner_flagged == 0);
}
