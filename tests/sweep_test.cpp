// `ryushi sweep` (issue 9): the cartesian product of overrides, one directory per run, resumable,
// collected into sweep.csv with wall time, steps, diagnostics and system shares; bad input is
// exit code 2 before anything runs.
#include <doctest/doctest.h>

#include <cstdlib>

#include "app/exit_codes.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

TEST_CASE("sweep: runs the product of --vary values, collects sweep.csv, and keeps completed runs on a re-run") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("sweep");
  const std::string cmd = bin + " sweep " + test::scene_path("dam_break_ritter_swe.toml") +
                          " --vary splitting.area_ratio=1.5,3.0 --vary particles.spacing=0.1,0.05 --out " + dir.string() +
                          " --jobs 2 --error ritter_front_depth_error";
  auto first = test::run_command(cmd);
  REQUIRE_MESSAGE(first.code == kExitDone, first.output);
  auto csv = test::read_csv(dir / "sweep.csv");
  const auto& ratio = csv["splitting.area_ratio"];
  const auto& spacing = csv["particles.spacing"];
  REQUIRE(ratio.size() == 4);
  CHECK(ratio == std::vector<double>{1.5, 1.5, 3.0, 3.0});  // the last key varies fastest
  CHECK(spacing == std::vector<double>{0.1, 0.05, 0.1, 0.05});
  for (double t : csv["wall_time_s"]) CHECK(t > 0);
  for (double n : csv["particles"]) CHECK(n >= 460);
  for (double e : csv["ritter_front_depth_error"]) CHECK((e > 0 && e < 2));
  for (double s : csv["share_swe_depth"]) CHECK((s > 0 && s < 1));
  // Each run is the run `ryushi run --set ...` gives: at d = 0.1 splitting at 1.5 A0 splits.
  CHECK(csv["splits"][0] > 0);
  // Re-run: everything kept, nothing run again.
  const auto kept_run = dir / "splitting.area_ratio=1.5__particles.spacing=0.1";
  const auto stamp = fs::last_write_time(kept_run / "summary.json");
  auto second = test::run_command(cmd);
  CHECK(second.code == kExitDone);
  CHECK_MESSAGE(second.output.find("4 of 4 runs were already complete and kept") != std::string::npos, second.output);
  CHECK(fs::last_write_time(kept_run / "summary.json") == stamp);
  // A run that did not complete (here: its summary gone) runs again, alone.
  fs::remove(dir / "splitting.area_ratio=3.0__particles.spacing=0.05" / "summary.json");
  auto third = test::run_command(cmd);
  CHECK(third.code == kExitDone);
  CHECK(third.output.find("3 of 4 runs were already complete and kept") != std::string::npos);
  CHECK(fs::exists(dir / "splitting.area_ratio=3.0__particles.spacing=0.05" / "summary.json"));
  if (std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0) CHECK(fs::exists(dir / "sweep.png"));
}

TEST_CASE("sweep: a bad --vary or key is exit code 2 before any run") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("sweep_bad");
  auto bad_key = test::run_command(bin + " sweep " + test::scene_path("dam_break_ritter_swe.toml") +
                                   " --vary splitting.area_rato=1.5,2 --out " + dir.string());
  CHECK(bad_key.code == kExitBadInput);
  CHECK_MESSAGE(bad_key.output.find("area_rato") != std::string::npos, bad_key.output);
  CHECK(!fs::exists(dir));
  auto no_value = test::run_command(bin + " sweep " + test::scene_path("dam_break_ritter_swe.toml") +
                                    " --vary splitting.area_ratio=1.5,,2 --out " + dir.string());
  CHECK(no_value.code == kExitBadInput);
  CHECK_MESSAGE(no_value.output.find("an empty value") != std::string::npos, no_value.output);
}
