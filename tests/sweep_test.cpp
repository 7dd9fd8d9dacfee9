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
  if (std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0)
    CHECK(fs::exists(dir / "sweep.png"));
  else
    MESSAGE("sweep.png not checked: /usr/bin/python3 cannot import matplotlib");
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

// Ctrl-C (SIGINT) stops the sweep: no new run starts, the running one stops as `ryushi run`
// does, sweep.csv is written for what there is, exit 130 (before, the sweep died without its
// table). The signal goes to the sweep alone here, which passes it on to its run.
TEST_CASE("sweep: SIGINT stops the sweep, writes its table and starts no new run") {
  auto dir = test::unique_scratch("sweep_interrupt");
  const std::string cmd = std::string(RYUSHI_BINARY) + " sweep " + test::scene_path("dam_break_2d.toml") +
                          " --vary time.cfl=0.1,0.15,0.2 --quiet --out " + dir.string();
  // Each run takes seconds (a/d = 40 to t = 1 s); the signal comes after one.
  auto r = test::run_command("sh -c '" + cmd + " & pid=$!; sleep 1; kill -INT $pid; wait $pid; echo exit=$?'");
  CHECK_MESSAGE(r.output.find("exit=130") != std::string::npos, r.output);
  const auto csv = test::read_text(dir / "sweep.csv");
  CHECK(csv.find("completed") == std::string::npos);
  CHECK(csv.find("0.2,time.cfl=0.2,missing") != std::string::npos);
  CHECK(!std::filesystem::exists(dir / "time.cfl=0.15"));
  CHECK(!std::filesystem::exists(dir / "time.cfl=0.2"));
}
