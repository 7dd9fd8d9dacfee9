#pragma once
// Shared by the stability cases (issue 9, "stability at the extremes"): run a scene in-process
// and read what it left, and the two outcomes a case may assert: physical bounds on a run that
// completed, or a clean failure (exit 3, a message naming the step, the system and the particle,
// and the last frame readable).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

namespace ryushi::test {

struct Outcome {
  int code = -1;
  std::filesystem::path out;
  std::string summary;
};

// The scene text with kinetic and potential energy probes appended.
inline std::string with_energy_probes(std::string scene) {
  return scene +
         "\n[[probe]]\nname = \"kinetic_energy\"\ntype = \"kinetic_energy\"\n"
         "[[probe]]\nname = \"potential_energy\"\ntype = \"potential_energy\"\n";
}

inline Outcome run_text(const std::string& name, const std::string& scene_text, std::vector<std::string> sets,
                        int threads = 0) {
  auto dir = scratch("stability_" + name);
  write_text(dir / "scene.toml", scene_text);
  RunOptions opt;
  opt.scene = (dir / "scene.toml").string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  opt.threads = threads;
  opt.sets = std::move(sets);
  Outcome o;
  o.code = run_scene(opt);
  o.out = dir / "out";
  o.summary = read_text(o.out / "summary.json");
  return o;
}

// A shipped scene with energy probes, run with overrides.
inline Outcome run_shipped(const std::string& name, const std::string& scene_file,
                           std::vector<std::string> sets) {
  return run_text(name, with_energy_probes(read_text(scene_path(scene_file))), std::move(sets));
}

// Exit 0. The message is read before the assertion: a REQUIRE inside a failing assertion's
// message runs under doctest's reporter lock and deadlocks.
inline void require_completed(const Outcome& o) {
  const std::string message = o.code == kExitDone ? "" : json_raw(o.summary, "message");
  REQUIRE_MESSAGE(o.code == kExitDone, message);
}

// Exit 3 with "step N ...", the particle's id and the system that last wrote the bad column (or
// the system that threw), and every frame on disk (the last included) opens with finite
// positions of the particles it holds.
inline void check_clean_failure(const Outcome& o, const std::string& label) {
  INFO(label);
  CHECK(o.code == kExitNumericalFailure);
  CHECK(json_raw(o.summary, "status") == "failed");
  const auto message = json_raw(o.summary, "message");
  INFO(message);
  CHECK(message.rfind("step ", 0) == 0);
  CHECK(message.find("system '") != std::string::npos);
  // A particle-level failure names the particle; a solver failure names the solve instead.
  CHECK((message.find("particle id ") != std::string::npos ||
         message.find("linear_solve") != std::string::npos));
  auto x = read_dataset(last_frame(o.out), "position");
  REQUIRE(x.values.size() > 0);
  for (double v : x.values) CHECK(std::isfinite(v));
}

// Kinetic + potential energy per probe row.
struct EnergySeries {
  std::vector<double> time, total, kinetic;
};
inline EnergySeries energy(const Outcome& o) {
  auto probes = read_csv(o.out / "probes.csv");
  EnergySeries e;
  e.time = probes["time"];
  e.kinetic = probes["kinetic_energy"];
  const auto& potential = probes["potential_energy"];
  for (std::size_t k = 0; k < e.time.size(); ++k) e.total.push_back(e.kinetic[k] + potential[k]);
  return e;
}

}  // namespace ryushi::test
