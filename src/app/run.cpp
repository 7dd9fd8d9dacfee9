#include "app/run.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "app/memory_estimate.hpp"
#include "app/plugins.hpp"
#include "app/runner.hpp"

namespace ryushi {

namespace {

extern "C" void on_signal(int) {
  g_interrupted = true;
}

template <int D>
int run_dim(const Scene& scene, const RunOptions& opt, const fs::path& resume = {}) {
  Runner<D> runner(scene, opt, resume);
  runner.prepare();
  return runner.run();
}

}  // namespace

std::vector<std::string> with_end_time(const RunOptions& opt) {
  auto sets = opt.sets;
  if (opt.end_time) {
    char value[40];
    std::snprintf(value, sizeof value, "%.17g", *opt.end_time);  // exact round trip
    sets.push_back(std::string("time.end=") + value);
  }
  return sets;
}

namespace {
// Loads the scene and runs it (continuing from the checkpoint `resume` when given) with the
// thread count and signal handlers, mapping failures to the exit codes of app/exit_codes.hpp.
int run_loaded(const RunOptions& opt, const fs::path& resume = {}, int checkpoint_dimension = 0) {
  std::unique_ptr<tbb::global_control> threads;
  if (opt.threads > 0)
    threads =
        std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, opt.threads);
  g_interrupted = false;
  auto old_int = std::signal(SIGINT, on_signal);
  auto old_term = std::signal(SIGTERM, on_signal);
  int code = kExitInternal;
  try {
    load_plugins(opt.plugins, opt.scene);
    Scene scene =
        load_scene(opt.scene, with_end_time(opt), opt.scene_text.empty() ? nullptr : &opt.scene_text);
    if (checkpoint_dimension && scene.dimension != checkpoint_dimension)
      throw SceneError(resume.string() + ": the checkpoint is of another dimension");
    guard_memory(scene, estimate_memory(scene));
    code = scene.dimension == 2 ? run_dim<2>(scene, opt, resume) : run_dim<3>(scene, opt, resume);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "ryushi: %s\n", e.what());
    code = kExitBadInput;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "ryushi: could not write the output: %s\n", e.what());
    code = kExitOutputFailed;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "ryushi: could not write the output: %s\n", e.what());
    code = kExitOutputFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ryushi: internal error: %s\n", e.what());
    code = kExitInternal;
  }
  std::signal(SIGINT, old_int);
  std::signal(SIGTERM, old_term);
  return code;
}
}  // namespace

int run_scene(const RunOptions& opt) {
  return run_loaded(opt);
}

const std::vector<std::string>& resumable_keys() {
  static const std::vector<std::string> keys{"time.end",
                                             "time.cfl",
                                             "time.dt",
                                             "time.dt_min",
                                             "time.max_steps",
                                             "output.interval",
                                             "output.probe_interval",
                                             "output.checkpoint_interval"};
  return keys;
}

int resume_run(const ResumeOptions& ro) {
  const fs::path file = fs::path(ro.out_dir) / "checkpoint.h5";
  Checkpoint c;
  try {
    if (!fs::exists(file))
      throw std::runtime_error(
          file.string() + ": no checkpoint (run with [output] checkpoint_interval or --checkpoint-interval)");
    c = read_checkpoint_header(file);
    // The checkpoint holds the scene's text: the file may have changed or gone since.
    for (auto& set : ro.sets) {
      const auto key = set.substr(0, set.find('='));
      const auto& allowed = resumable_keys();
      if (set.find('=') == std::string::npos ||
          std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        std::string list;
        for (auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
        throw std::runtime_error("--set " + set +
                                 ": not a key a resumed run can change (its state was built with "
                                 "the rest); these can: " +
                                 list);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ryushi: %s\n", e.what());
    return kExitBadInput;
  }
  RunOptions opt;
  opt.scene = c.scene.path;
  opt.out_dir = ro.out_dir;
  opt.threads = ro.threads;
  opt.quiet = ro.quiet;
  opt.sets = c.scene.overrides;  // the original run's, its end time included, then the new ones
  opt.sets.insert(opt.sets.end(), ro.sets.begin(), ro.sets.end());
  opt.scene_text = c.scene.text;
  if (ro.end_time) opt.end_time = ro.end_time;
  if (ro.checkpoint_interval) opt.checkpoint_interval = ro.checkpoint_interval;
  opt.plugins = ro.plugins;
  return run_loaded(opt, file, c.scene.dimension);
}

int check_scene(const std::string& path, const std::vector<std::string>& sets,
                const std::string& write_initial, const std::vector<std::string>& plugins) {
  try {
    load_plugins(plugins, path);
    Scene scene = load_scene(path, sets);
    const MemoryEstimate memory = estimate_memory(scene);
    guard_memory(scene, memory);
    auto build = [&](auto dim) {
      constexpr int D = decltype(dim)::value;
      World<D> world;
      Resources res;
      Profiler profiler;
      auto method = build_method<D>(scene, world);
      probes_of(scene, world, method.context);  // a wall sensor off any wall, or facing into it
      Scheduler<D> s(std::move(method.pipeline), world, res, profiler);
      std::printf(
          "%s: OK (%dD %s, %zu particles, %zu systems in the step graph; memory about %s of %s "
          "available)\n",
          path.c_str(), D, scene.method.c_str(), world.size(), s.pipeline().size(),
          format_bytes(memory.bytes).c_str(), format_bytes(available_memory().bytes).c_str());
      if (write_initial.empty()) return;
      // Every column the method made at set-up (wall normals, layers, areas, ...), not only
      // the run's output fields: this frame is for inspecting the geometry.
      std::vector<std::string> fields;
      const auto defaults = default_frame_fields();
      for (auto& name : world.column_names())
        if (std::find(defaults.begin(), defaults.end(), name) == defaults.end()) fields.push_back(name);
      const fs::path dir(write_initial);
      fs::create_directories(dir / "frames");
      const std::string name = "frames/frame_00000.h5";
      auto written = write_frame<D>(dir / name, world, fields, 0.0, 0);
      write_text_atomic(dir / "particles.xdmf", xdmf_document({{name, 0.0, world.size(), written}}));
      std::printf("initial particles: %s (open in ParaView)\n", (dir / "particles.xdmf").string().c_str());
    };
    if (scene.dimension == 2)
      build(std::integral_constant<int, 2>{});
    else
      build(std::integral_constant<int, 3>{});
    return kExitDone;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "ryushi: %s\n", e.what());
    return kExitBadInput;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "ryushi: %s\n", e.what());
    return kExitOutputFailed;
  } catch (const fs::filesystem_error& e) {
    std::fprintf(stderr, "ryushi: %s\n", e.what());
    return kExitOutputFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ryushi: internal error: %s\n", e.what());
    return kExitInternal;
  }
}

}  // namespace ryushi
