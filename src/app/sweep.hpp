#pragma once
// `ryushi sweep SCENE --vary key=v1,v2,... [--vary ...] --out DIR [--jobs N] [--threads N]`: the
// cartesian product of overrides, each run in its own sub-directory of DIR (resumable: a run
// whose summary.json says completed is kept, the others run again), collected into
// DIR/sweep.csv (the varied values, status, wall time, steps, particles, particle-steps/s, every
// number under "metrics" and "diagnostics" in summary.json, each system's share of the step from
// profile.json) and drawn into DIR/sweep.png by tools/plot_sweep.py (error against wall time,
// the Pareto front marked). docs/tradeoffs.md.
#include <string>
#include <vector>

namespace ryushi {

struct SweepOptions {
  std::string scene, out_dir;
  std::vector<std::string> vary;  // "section.key=v1,v2,..." (commas inside [...] belong to a value)
  std::vector<std::string> sets;  // fixed overrides for every run
  int jobs = 1, threads = 1;
  std::string error;  // the sweep.csv column sweep.png plots against wall time ("": the first *_error)
  bool quiet = false;
  std::vector<std::string> plugins;  // --plugin libraries, for the check and every run
};

int run_sweep(const SweepOptions& options);

// "key=v1,[1, 2],v3" -> key and its values; throws std::invalid_argument naming the problem.
std::pair<std::string, std::vector<std::string>> parse_vary(const std::string& vary);

}  // namespace ryushi
