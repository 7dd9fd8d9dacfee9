// The `ryushi` command line: run, check, keys, render, solve and the verification commands. Exit codes: app/exit_codes.hpp.
#include <malloc.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/exit_codes.hpp"
#include "app/plugins.hpp"
#include "app/render.hpp"
#include "app/run.hpp"
#include "app/solve.hpp"
#include "app/sweep.hpp"
#include "ryushi_version.hpp"
#include "scene/registered_keys.hpp"
#include "scene/schema.hpp"
#include "verification/free_surface_check.hpp"
#include "verification/patch_test.hpp"

int main(int argc, char** argv) {
  // A name registered twice in this build: one line, not an abort in a static initialiser.
  if (const auto& clashes = ryushi::built_in_registration_clashes(); !clashes.empty()) {
    std::string names;
    for (auto& c : clashes) names += (names.empty() ? "" : ", ") + c;
    std::fprintf(stderr,
                 "ryushi: internal error: %s registered twice in this build (two registrations take one "
                 "name; rename one)\n",
                 names.c_str());
    return ryushi::kExitInternal;
  }
  using namespace ryushi;
  // Every step frees and reallocates large buffers (neighbour list, pressure matrix, multigrid
  // hierarchy). glibc serves blocks above its dynamic mmap threshold with fresh, zero-filled
  // pages each time: measured on the 80,000-particle MPS dam break, the float hierarchy's setup
  // took 23.8 ms per step instead of 14.5, the whole step 5-7% longer. Blocks up to 32 MiB (the
  // glibc maximum) now come from the heap and are reused, and freed memory is kept.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  CLI::App app{"ryushi: particle methods for fluid mechanics (WCSPH, ISPH, MPS, shallow-water MPS)"};
  app.set_version_flag("--version", "ryushi " RYUSHI_VERSION);
  app.require_subcommand(1);
  // A count of threads or jobs: CLI::PositiveNumber's message printed the double range's
  // 310-digit upper end for --threads 0 (issue 51).
  const CLI::Range kCount(1, 4096, "a count from 1 to 4096");

  RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run a scene file headless.");
  run_cmd->add_option("scene", run.scene, "Scene file (TOML)")->required();
  run_cmd->add_option("--out", run.out_dir, "Output directory (default out/<scene name>)");
  run_cmd->add_option("--threads", run.threads, "Worker threads (default: all cores)")->check(kCount);
  run_cmd->add_option("--end-time", run.end_time, "Override time.end (s)");
  run_cmd->add_option("--set", run.sets, "Override a scene key: section.key=value (repeatable)");
  run_cmd->add_flag("--trace", run.trace, "Write trace.json (Chrome trace events, opens in Perfetto)");
  run_cmd->add_flag("--quiet", run.quiet, "No progress output and no profile table");
  run_cmd->add_flag(
      "--overwrite", run.overwrite,
      "Replace another run's files in the output directory (without it such a directory is refused)");
  run_cmd->add_option("--plugin", run.plugins, "Load a plugin library first (repeatable; docs/extending.md)");
  run_cmd->add_option("--dump-matrix", run.dump_matrix_dir,
                      "Write the pressure system of one step to DIR: A.mtx, b.txt, x.txt (coordinates), p.txt (solution)");
  run_cmd->add_option("--dump-step", run.dump_step, "Step (from 0) whose system --dump-matrix writes (default 0)")
      ->check(CLI::NonNegativeNumber);

  run_cmd->add_option("--checkpoint-interval", run.checkpoint_interval,
                      "Write OUT/checkpoint.h5 every T of simulated time (overrides [output] checkpoint_interval)")
      ->check(CLI::NonNegativeNumber);

  ResumeOptions resume;
  auto* resume_cmd = app.add_subcommand("resume", "Continue a run from OUT/checkpoint.h5 (same scene, same result).");
  resume_cmd->add_option("out", resume.out_dir, "The run's output directory")->required();
  resume_cmd->add_option("--end-time", resume.end_time, "Run on to this time instead (s)");
  resume_cmd->add_option(
      "--set", resume.sets,
      "Change a key that is safe mid-run: time.end, time.cfl, time.dt, time.dt_min, time.max_steps, "
      "output.interval, output.probe_interval, output.checkpoint_interval (repeatable)");
  resume_cmd->add_option("--threads", resume.threads, "Worker threads (default: all cores)")->check(kCount);
  resume_cmd->add_flag("--quiet", resume.quiet, "No progress output and no profile table");
  resume_cmd->add_option("--plugin", resume.plugins, "The plugin libraries the run was started with (repeatable)");
  resume_cmd->add_option("--checkpoint-interval", resume.checkpoint_interval,
                         "Write OUT/checkpoint.h5 every T of simulated time (default: the run's own interval)")
      ->check(CLI::NonNegativeNumber);

  SweepOptions sweep;
  auto* sweep_cmd = app.add_subcommand(
      "sweep", "Run the cartesian product of --vary overrides into DIR/<run>/, collect DIR/sweep.csv and draw DIR/sweep.png.");
  sweep_cmd->add_option("scene", sweep.scene, "Scene file (TOML)")->required();
  sweep_cmd->add_option("--vary", sweep.vary, "section.key=v1,v2,... (repeatable; the product of all)")->required();
  sweep_cmd->add_option("--out", sweep.out_dir, "Output directory (resumable: completed runs are kept)")->required();
  sweep_cmd->add_option("--set", sweep.sets, "A fixed override for every run (repeatable)");
  sweep_cmd->add_option("--jobs", sweep.jobs, "Runs at a time (default 1)")->check(kCount);
  sweep_cmd->add_option("--threads", sweep.threads, "Threads per run (default 1)")->check(kCount);
  sweep_cmd->add_option("--error", sweep.error, "summary.json diagnostics key sweep.png plots (default: the first *_error)");
  sweep_cmd->add_flag("--quiet", sweep.quiet, "No log lines");
  sweep_cmd->add_option("--plugin", sweep.plugins, "Load a plugin library in every run (repeatable)");

  std::string check_path;
  std::vector<std::string> check_sets;
  auto* check_cmd = app.add_subcommand("check", "Validate a scene file without running it.");
  check_cmd->add_option("scene", check_path, "Scene file (TOML)")->required();
  check_cmd->add_option("--set", check_sets, "Override a scene key: section.key=value (repeatable)");
  std::string check_write_initial;
  std::vector<std::string> check_plugins;
  check_cmd->add_option("--plugin", check_plugins, "Load a plugin library first (repeatable)");
  check_cmd->add_option("--write-initial", check_write_initial,
                        "Also write the particles the scene makes (every column) to DIR/particles.xdmf + DIR/frames/");

  bool markdown = false;
  auto* keys_cmd = app.add_subcommand("keys", "Print the scene-file reference (every section and key).");
  keys_cmd->add_flag("--markdown", markdown, "Markdown (docs/scenes.md is this output)");
  std::vector<std::string> keys_plugins;
  keys_cmd->add_option("--plugin", keys_plugins, "Include a plugin library's methods and systems (repeatable)");

  PatchTestOptions patch;
  auto* patch_cmd = app.add_subcommand("patch-test", "Operator accuracy on the Franke function (V&V paper section 3).");
  patch_cmd->add_option("--dim", patch.dimension, "2 or 3")->check(CLI::IsMember({2, 3}));
  patch_cmd->add_option("--operator", patch.op, "Operator name")->check(CLI::IsMember(patch_test_operators()));
  patch_cmd->add_option("--disorder", patch.disorder, "Random displacement up to this fraction of the spacing")
      ->check(CLI::Range(0.0, 0.49));
  patch_cmd->add_option("--kernel", patch.kernel, "Kernel (as in scenes)");
  patch_cmd->add_option("--smoothing-ratio", patch.smoothing_ratio, "h / d")->check(CLI::Range(0.5, 4.0));
  patch_cmd->add_option("--spacings", patch.spacings, "Spacings (default 1/20..1/160 in 2D; 1/20, 1/30, 1/40 in 3D)");
  patch_cmd->add_option("--seed", patch.seed, "Seed of the disorder");

  std::string fs_rule = "isph2";
  double fs_disorder = 0.0;
  unsigned fs_seed = 1;
  double fs_beta = 0.85;
  auto* fs_cmd = app.add_subcommand("free-surface-test", "Free-surface detection on known shapes: recall and precision.");
  fs_cmd->add_option("--rule", fs_rule, "marrone, isph2 or mps")->check(CLI::IsMember({"marrone", "isph2", "mps"}));
  fs_cmd->add_option("--disorder", fs_disorder, "Random displacement up to this fraction of the spacing")->check(CLI::Range(0.0, 0.49));
  fs_cmd->add_option("--seed", fs_seed, "Seed of the disorder");
  fs_cmd->add_option("--beta", fs_beta, "MPS threshold n < beta n0")->check(CLI::Range(0.1, 1.0));

  SolveCommandOptions solve;
  auto* solve_cmd = app.add_subcommand("solve", "Solve an exported linear system (Matrix Market) and time it.");
  solve_cmd->add_option("matrix", solve.matrix, "A.mtx")->required();
  solve_cmd->add_option("--rhs", solve.rhs, "b.txt, one value per line")->required();
  solve_cmd->add_option("--coords", solve.coords, "x.txt, D values per line (needed by multigrid)");
  solve_cmd->add_option("--krylov", solve.krylov, "cg or bicgstab")->check(CLI::IsMember({"cg", "bicgstab"}));
  solve_cmd->add_option("--preconditioner", solve.preconditioner, "none, jacobi or multigrid")
      ->check(CLI::IsMember({"none", "jacobi", "multigrid"}));
  solve_cmd->add_option("--cycle", solve.cycle, "v, w or sw (scale-corrected W)")->check(CLI::IsMember({"v", "w", "sw"}));
  solve_cmd->add_option("--precision", solve.precision, "double or mixed (float preconditioner)")
      ->check(CLI::IsMember({"double", "mixed"}));
  solve_cmd->add_option("--tol", solve.tolerance, "Relative residual |b - Ax|/|b|")->check(CLI::PositiveNumber);
  solve_cmd->add_option("--max-iterations", solve.max_iterations, "Iteration cap")->check(CLI::PositiveNumber);
  solve_cmd->add_option("--bucket-width", solve.bucket_width, "Level-1 bucket width (default: longest coupling)");
  solve_cmd->add_option("--pre-smoothing", solve.pre_smoothing, "Jacobi sweeps before restriction")
      ->check(CLI::Range(0, 16));
  solve_cmd->add_option("--post-smoothing", solve.post_smoothing, "Jacobi sweeps after prolongation")
      ->check(CLI::Range(0, 16));
  solve_cmd->add_option("--bottom-smoothing", solve.bottom_smoothing, "Jacobi sweeps on the coarsest level")
      ->check(CLI::Range(1, 64));
  solve_cmd
      ->add_option("--bottom-size", solve.bottom_size, "A level with at most this many rows is the coarsest")
      ->check(CLI::PositiveNumber);
  solve_cmd
      ->add_option(
          "--jacobi-weight", solve.jacobi_weight,
          "Weight of the multigrid's Jacobi sweeps (default: 1 with cg, 2/3 with bicgstab, as in scenes)")
      ->check(CLI::Range(1e-3, 1.5));
  solve_cmd
      ->add_option("--block-size", solve.block_size,
                   "Unknowns per particle (MPH-I: the dimension); --coords has one line per block")
      ->check(CLI::Range(1, 3));
  solve_cmd->add_flag("--bound-jacobi-weight", solve.bound_jacobi_weight,
                      "Each level's Jacobi weight at most 4 / (3 max eig(D^-1 A)) (MPH-I's matrices)");
  solve_cmd->add_option("--threads", solve.threads, "Worker threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);

  RenderOptions render;
  auto* render_cmd = app.add_subcommand("render", "PNG pictures and an MP4 of a run's frames (tools/render.py).");
  render_cmd->add_option("out", render.out_dir, "Output directory of a run")->required();
  render_cmd->add_option("--field", render.field, "Field to colour by (default pressure; vectors by magnitude)");
  render_cmd->add_option("--frames", render.frames, "all, last or frame numbers 0,10,20 (default all)");
  render_cmd->add_flag("--movie", render.movie, "Also write FIELD.mp4 of every frame (ffmpeg)");
  render_cmd->add_option("--slice", render.slice, "3D: keep particles within a spacing of AXIS=VALUE (default: projection)");
  render_cmd->add_option("--range", render.range, "Colour range LO,HI (default: 1st-99th percentile)");
  render_cmd->add_option("--dest", render.dest, "Where the pictures go (default OUT/render)");

  // A first word that is no command (`ryushi frobnicate`): CLI11 only says a subcommand is required.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    std::string known;
    bool found = false;
    for (auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
      known += (known.empty() ? "" : ", ") + sub->get_name();
      found |= sub->get_name() == word;
    }
    if (!found) {
      std::fprintf(stderr, "ryushi: command line: no command '%s'; the commands are %s (see ryushi --help)\n",
                   word.c_str(), known.c_str());
      return kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ryushi: command line: %s (see ryushi --help)\n", e.what());
    return kExitBadInput;
  }

  spdlog::set_pattern("[%H:%M:%S] %v");
  if (*run_cmd) return run_scene(run);
  if (*resume_cmd) return resume_run(resume);
  if (*sweep_cmd) return run_sweep(sweep);
  if (*check_cmd) return check_scene(check_path, check_sets, check_write_initial, check_plugins);
  if (*patch_cmd) {
    try {
      auto r = run_patch_test(patch);
      std::printf("# %s, %dD, disorder %.2f, kernel %s, h/d %.2f\n", patch.op.c_str(), patch.dimension,
                  patch.disorder, patch.kernel.c_str(), patch.smoothing_ratio);
      std::printf("%10s %10s %10s %14s %14s %10s\n", "spacing", "interior", "boundary", "rmse_interior",
                  "rmse_boundary", "seconds");
      for (auto& row : r.rows)
        std::printf("%10.6f %10zu %10zu %14.6e %14.6e %10.4f\n", row.spacing, row.interior, row.boundary,
                    row.rmse_interior, row.rmse_boundary, row.seconds);
      std::printf("order_interior=%.3f order_boundary=%.3f\n", r.order_interior, r.order_boundary);
      return kExitDone;
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "ryushi: patch-test: %s\n", e.what());
      return kExitBadInput;
    }
  }
  if (*fs_cmd) {
    std::printf("# rule %s, disorder %.2f (outer layer = truth)\n%-18s %8s %8s %10s %10s %9s %9s\n", fs_rule.c_str(),
                fs_disorder, "shape", "outer", "interior", "outer_hit", "interior_hit", "recall", "precision");
    for (auto& shape : free_surface_shapes()) {
      auto s = score_free_surface(shape, fs_rule, fs_disorder, fs_seed, 0.02, fs_beta);
      std::printf("%-18s %8zu %8zu %10zu %10zu %9.4f %9.4f\n", shape.c_str(), s.outer, s.interior, s.outer_flagged,
                  s.interior_flagged, s.recall(), s.precision());
    }
    return kExitDone;
  }
  if (*solve_cmd) return solve_command(solve);
  if (*render_cmd) return render_command(render);
  if (*keys_cmd) {
    try {
      load_plugins(keys_plugins);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ryushi: %s\n", e.what());
      return kExitBadInput;
    }
    std::printf("%s", markdown ? schema_markdown().c_str() : schema_text().c_str());
    return kExitDone;
  }
  return kExitBadInput;
}
