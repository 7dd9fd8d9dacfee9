// Shallow-water MPS with particle splitting (issue 12; Saigo & Koshizuka, seed 000): Ritter's
// dry-bed dam break against the analytic solution, a lake at rest over a bump, the run-up and
// raster-terrain scenes, bad rasters and scene keys.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

namespace {

struct Outcome {
  int code;
  std::string summary;
  fs::path out;
};

Outcome run(const std::string& scene, const std::string& name, std::vector<std::string> sets = {}) {
  RunOptions opt;
  opt.scene = test::scene_path(scene);
  opt.out_dir = test::unique_scratch(name).string();
  opt.quiet = true;
  opt.sets = std::move(sets);
  int code = run_scene(opt);
  return {code, test::read_text(fs::path(opt.out_dir) / "summary.json"), opt.out_dir};
}

// scenes/terrain/valley.asc's no-data cells: 3.0 <= x <= 3.3, 1.5 <= y <= 1.8. Inside: more than
// `margin` from its edges (1e-9: a lattice point on an edge may fall in either cell).
bool in_no_data_box(double x, double y, double margin = 1e-9) {
  return x > 3.0 + margin && x < 3.3 - margin && y > 1.5 + margin && y < 1.8 - margin;
}
double distance_to_no_data_box(double x, double y) {
  return std::hypot(std::max({3.0 - x, 0.0, x - 3.3}), std::max({1.5 - y, 0.0, y - 1.8}));
}

struct Ritter {
  double front_error, wave_error, front, analytic_front, splits, volume_change;
};
Ritter ritter(double spacing, bool splitting) {
  auto r = run("dam_break_ritter_swe.toml", "ritter",
               {"particles.spacing=" + std::to_string(spacing),
                std::string("splitting.enabled=") + (splitting ? "true" : "false")});
  REQUIRE(r.code == kExitDone);
  return {test::json_number(r.summary, "ritter_front_depth_error"),
          test::json_number(r.summary, "ritter_depth_error"),
          test::json_number(r.summary, "front_position"),
          test::json_number(r.summary, "ritter_front_position"),
          splitting ? test::json_number(r.summary, "splits") : 0.0,
          test::json_number(r.summary, "fluid_volume_relative_change")};
}

}  // namespace

TEST_CASE("swe: Ritter's dam break with splitting resolves the front better than without, and converges") {
  // The paper's case (d = 0.1 m) and one finer, with the scene's momentum = "sph". The issue's
  // bound (front-region depth error within 3% with splitting) is below what eq. 7 allows: the
  // exact solution itself, its particles placed where it moves them, ideally split at 1.5 A0 and
  // their depths summed by eqs. 7-9, has a front-region error of 0.055 at d = 0.1 and 0.049 at
  // d = 0.05 (0.049 at 0.025: it does not fall with the spacing), and 0.77 / 0.59 unsplit
  // (tools/ritter_floor.py; docs/swe.md, "Ritter"). Asserted instead, against that floor:
  //  - with splitting the front-region error is within 3x the floor (measured 0.153 = 2.8x at
  //    d = 0.1, 0.098 = 2.0x at 0.05; momentum = "mps": 0.289 = 5.3x and 0.130 = 2.7x);
  //  - without splitting it is more than twice that (measured 0.634, 0.540: the paper's "71%");
  //  - the front with splitting is ahead of the unsplit one and closer to the analytic front,
  //    and moves towards it as the spacing halves; the unsplit front stays behind (its particles
  //    drift apart, and the SPH depth of eq. 7 cannot thin with them).
  const double floor_coarse = 0.055, floor_fine = 0.049;  // tools/ritter_floor.py --spacing 0.1 0.05
  const Ritter split_coarse = ritter(0.1, true), plain_coarse = ritter(0.1, false);
  const Ritter split_fine = ritter(0.05, true), plain_fine = ritter(0.05, false);
  for (auto* r : {&split_coarse, &plain_coarse, &split_fine, &plain_fine})
    MESSAGE("front-region error " << r->front_error << ", wave " << r->wave_error << ", front " << r->front
                                  << " m (analytic " << r->analytic_front << " m), splits " << r->splits);
  CHECK(split_coarse.front_error < 3 * floor_coarse);
  CHECK(split_fine.front_error < 3 * floor_fine);
  CHECK(plain_coarse.front_error > 2 * split_coarse.front_error);
  CHECK(plain_fine.front_error > 2 * split_fine.front_error);
  for (auto [split, plain] : {std::pair{split_coarse, plain_coarse}, std::pair{split_fine, plain_fine}}) {
    CHECK(split.splits > 0);
    CHECK(split.front > plain.front);
    CHECK(std::abs(split.front - split.analytic_front) < std::abs(plain.front - plain.analytic_front));
    CHECK(split.wave_error < plain.wave_error);
    // Splitting halves volumes exactly, and nothing else changes them: the fluid volume is
    // sum m / rho with rho fixed at rho0 and m = rho0 V (src/methods/swe.cpp), so this checks
    // the split's halving, not the flow (sum h A is the same sum: A = V / h, swe_systems.hpp).
    CHECK(std::abs(split.volume_change) < 1e-12);
  }
  CHECK(split_fine.front > split_coarse.front + 0.1);  // 5.40 -> 5.68 m (analytic 6.22)
  // Converges (audit row 12): the finer run's front-region error is smaller (0.153 -> 0.098) and
  // its front nearer the analytic one, each a strict comparison of two computed figures.
  CHECK(split_fine.front_error < split_coarse.front_error);
  CHECK(std::abs(split_fine.front - split_fine.analytic_front) <
        std::abs(split_coarse.front - split_coarse.analytic_front));
}

TEST_CASE("swe: a lake at rest over a bumpy bed stays at rest for 10 s (well balanced)") {
  auto r = run("lake_at_rest_swe.toml", "lake");
  REQUIRE(r.code == kExitDone);
  // The shallowest water (over the hump's top) is 0.15 m deep.
  const double h_min = 0.15, c = std::sqrt(9.81 * h_min);
  CHECK(test::json_number(r.summary, "max_speed") < 1e-3 * c);
  auto last = r.out / "frames" / "frame_00010.h5";
  auto zs = test::read_dataset(last, "surface_elevation").values;
  auto h = test::read_dataset(last, "depth").values;
  REQUIRE(zs.size() > 1000);
  double flat = 0, shallowest = 1;
  for (std::size_t i = 0; i < zs.size(); ++i)
    flat = std::max(flat, std::abs(zs[i] - 0.3)), shallowest = std::min(shallowest, h[i]);
  CHECK(shallowest < 0.16);  // the bump is there
  CHECK(flat < 1e-3 * h_min);
  // ParaView draws the particles on the surface: the frame's z is z_s.
  auto x = test::read_dataset(last, "position").values;
  for (std::size_t i = 0; i < zs.size(); ++i) REQUIRE(x[3 * i + 2] == zs[i]);
}

TEST_CASE("swe: the run-up on a 10% slope runs to 1.6 s with splitting, its front thin and on the slope") {
  auto r = run("runup_slope_swe.toml", "runup");
  REQUIRE(r.code == kExitDone);
  auto probes = test::read_csv(r.out / "probes.csv");
  const auto& front = probes["front"];
  const auto& depth = probes["front_depth"];
  const auto& count = probes["particles"];
  MESSAGE("t = 1.6 s: front at " << front.back() << " m, front depth " << depth.back() * 1000
                                 << " mm (paper 2.8 mm), " << count.back() << " particles (" << count.front()
                                 << " at the start)");
  CHECK(front.back() > 3.4 + 0.5);  // up the slope, which starts at x = 3.4 m
  CHECK(depth.back() > 0);
  CHECK(depth.back() < 0.01 * 0.25);    // the tip thins to under 1% of the initial depth
  CHECK(count.back() > count.front());  // splitting keeps the resolution
  // The splits halve volumes exactly (the only check this is: see Ritter's case above).
  CHECK(std::abs(test::json_number(r.summary, "fluid_volume_relative_change")) < 1e-12);
}

TEST_CASE(
    "swe: a flood on raster terrain completes, its splits halving volumes, and no particle on its no-data "
    "cells") {
  auto r = run("valley_flood_swe.toml", "valley");  // to the scene's 2 s: the front reaches x = 4 m
  REQUIRE(r.code == kExitDone);
  CHECK(test::json_number(r.summary, "splits") > 0);
  // Volume is kept by construction but for the splits (Ritter's case above; issue 50, audit row 27).
  CHECK(std::abs(test::json_number(r.summary, "fluid_volume_relative_change")) < 1e-12);
  // The no-data cells (3.0 <= x <= 3.3, 1.5 <= y <= 1.8) are dry high ground: the bed there reads
  // the raster's highest value, 0.35 m, and water runs up against them as against a bank. The bed
  // is bilinear between cell centres, so it climbs to 0.35 m over the half cell (0.05 m) inside
  // the box's edge and is 0.35 m, above the reservoir's 0.25 m surface, within the centres'
  // square. No particle reaches that square in any frame (audit round three, row 42). Measured:
  // the water comes to the box at t = 1.8 s (before, 0.47 m from it at 1 s, the test's old end),
  // 2 particles 0.044 m up the bank then, none inside at 1.9 and 2 s.
  int frames = 0, on_bank = 0;
  double nearest = 1e9;  // the water's closest approach to the no-data box
  for (; fs::exists(test::frame_path(r.out, frames)); ++frames) {
    const auto x = test::read_dataset(test::frame_path(r.out, frames), "position").values;
    REQUIRE(!x.empty());
    std::size_t on_top = 0;
    for (std::size_t i = 0; i < x.size(); i += 3) {
      on_top += in_no_data_box(x[i], x[i + 1], 0.05);
      on_bank += in_no_data_box(x[i], x[i + 1]);
      nearest = std::min(nearest, distance_to_no_data_box(x[i], x[i + 1]));
    }
    CHECK_MESSAGE(on_top == 0, on_top << " particles on the no-data cells' top in frame " << frames);
  }
  MESSAGE("valley flood: " << frames
                           << " frames to t = 2 s, the water's closest approach to the no-data cells "
                           << nearest << " m, " << on_bank << " particle-frames up their bank");
  REQUIRE(frames == 21);  // 0 to 2 s every 0.1 s
  CHECK(nearest < 0.05);  // the water did reach them (0 m measured)
  // No particle starts on them, with the reservoir over them: the block stretched over the whole
  // valley with its surface at 0.5 m, above the cells' 0.35 m bed, so only the no-data rule keeps
  // them dry. The particles around them show that the block covered them.
  auto covered = run("valley_flood_swe.toml", "valley_covered",
                     {"fluid.0.max=[4.0, 2.0]", "fluid.0.surface_elevation=0.5", "time.max_steps=1"});
  REQUIRE(covered.code == kExitDone);
  const auto x = test::read_dataset(test::frame_path(covered.out, 0), "position").values;
  std::size_t inside = 0, around = 0;
  for (std::size_t i = 0; i < x.size(); i += 3) {
    inside += in_no_data_box(x[i], x[i + 1]);
    const double d = distance_to_no_data_box(x[i], x[i + 1]);
    around += d > 0 && d < 0.06;
  }
  MESSAGE("reservoir over the no-data cells: " << x.size() / 3 << " particles, " << inside
                                               << " on the cells, " << around << " within 0.06 m of them");
  CHECK(inside == 0);
  CHECK(around == 28);  // the whole ring of lattice points 0.05 m outside them: the block covered them
}

TEST_CASE("swe: bad rasters and scene keys are exit code 2 with the file and line") {
  auto dir = test::scratch("swe_bad_input");
  const std::string bin = RYUSHI_BINARY;
  auto scene_with = [&](const std::string& raster_text, const std::string& extra = "") {
    test::write_text(dir / "bad.asc", raster_text);
    auto scene = dir / "scene.toml";
    test::write_text(scene,
                     "[scene]\ndimension = 2\n[domain]\nmin = [-1.0, -1.0]\nmax = [3.0, 3.0]\n"
                     "[particles]\nspacing = 0.1\n[method]\nname = \"swe\"\n[bed]\nraster = \"bad.asc\"\n"
                     "[time]\nend = 0.01\n[[fluid]]\nmin = [0.0, 0.0]\nmax = [2.0, 1.0]\ndepth = 0.1\n" +
                         extra);
    return test::run_command(bin + " run " + scene.string() + " --out " + (dir / "out").string() +
                             " --quiet");
  };
  const std::string header = "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
  struct Case {
    std::string text, expect;
  } cases[] = {
      {"ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\n1 2 3\n4 5 6\n",
       "bad.asc:5: missing header key 'cellsize'"},
      {header + "1 2 3\n4 5\n", "bad.asc:7: row 2 has 2 values, ncols = 3"},
      {header + "1 2 3\n", "bad.asc:6: only 1 data rows, nrows = 2"},
      {header + "1 x 3\n4 5 6\n", "bad.asc:6: 'x' is not a number"},
      {header + "1 nan 3\n4 5 6\n", "bad.asc:6: non-finite elevation 'nan'"},
      {header + "NODATA_value -9999\n-9999 -9999 -9999\n-9999 -9999 -9999\n", "every cell is NODATA_value"},
  };
  for (auto& c : cases) {
    auto r = scene_with(c.text);
    CHECK(r.code == kExitBadInput);
    CHECK_MESSAGE(r.output.find(c.expect) != std::string::npos, r.output);
    CHECK_MESSAGE(r.output.find("scene.toml:") != std::string::npos, r.output);  // and the scene's key
  }
  // No-data cells are dry: the block's particles on them are left out, the run completes.
  auto ok = scene_with(header + "NODATA_value -9999\n0 0 0\n-9999 0 0\n");
  CHECK(ok.code == kExitDone);
  // The block's 200 lattice points: the 100 on the south-west cell ([0, 1] x [0, 1]) are dry.
  auto x0 = test::read_dataset(dir / "out" / "frames" / "frame_00000.h5", "position").values;
  CHECK(x0.size() == 3 * 100);
  for (std::size_t i = 0; i < x0.size(); i += 3) CHECK_FALSE((x0[i] < 1 && x0[i + 1] < 1));
  // Keys of other methods, and a block without a depth.
  auto bad_key = [&](const std::string& body, const std::string& expect) {
    auto scene = dir / "keys.toml";
    test::write_text(scene, body);
    auto r = test::run_command(bin + " check " + scene.string());
    CHECK(r.code == kExitBadInput);
    CHECK_MESSAGE(r.output.find(expect) != std::string::npos, r.output);
  };
  const std::string base =
      "[scene]\ndimension = 2\n[domain]\nmin = [-1.0, -1.0]\nmax = [3.0, 3.0]\n[particles]\nspacing = "
      "0.1\n[time]\nend = 0.01\n";
  bad_key(base + "[method]\nname = \"swe\"\n[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n",
          "method swe needs one of depth and surface_elevation");
  bad_key(base + "[bed]\nelevation = 1.0\n[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n",
          "[bed] is for [method] name = \"swe\"");
  bad_key(base +
              "[method]\nname = \"swe\"\n[physics]\ngravity = [0.0, -9.81]\n[[fluid]]\nmin = [0.0, 0.0]\nmax "
              "= [1.0, 1.0]\ndepth = 0.1\n",
          "method 'swe' has no in-plane gravity");
  bad_key(base + "[method]\nname = \"swe\"\n[swe]\nmomentum = \"sp\"\n[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, "
                 "1.0]\ndepth = 0.1\n",
          "keys.toml:13:12: 'momentum' in [swe] is 'sp'; allowed: mps, sph");
}
