#pragma once
// Runs a shipped scene in-process with more text appended (a probe, a metric) and overrides, in a
// fresh scratch folder; requires the run to complete and returns its output folder.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "test_util.hpp"

namespace ryushi::test {

inline std::filesystem::path run_shipped_scene(const std::string& name, const std::string& scene_file,
                                               const std::string& appended, std::vector<std::string> sets) {
  auto dir = unique_scratch(name);
  write_text(dir / "scene.toml", read_text(scene_path(scene_file)) + "\n" + appended);
  RunOptions opt;
  opt.scene = (dir / "scene.toml").string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  opt.sets = std::move(sets);
  REQUIRE(run_scene(opt) == kExitDone);
  return dir / "out";
}

}  // namespace ryushi::test
