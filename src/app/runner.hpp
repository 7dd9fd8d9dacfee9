#pragma once
// Runner<D>: one run's time loop (app/run.cpp builds it): the scene's method and its step graph,
// steps shortened to land on frame and probe times, the health check after every step,
// reordering, outflow, frames, probes, checkpoints and their restore, the summary
// (app/run_summary.hpp) and the profile.
#include <spdlog/spdlog.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "app/exit_codes.hpp"
#include "app/health_check.hpp"
#include "app/health_monitor.hpp"
#include "app/memory_estimate.hpp"
#include "app/progress.hpp"
#include "app/run.hpp"
#include "app/run_files.hpp"
#include "app/run_probes.hpp"
#include "app/settle.hpp"
#include "app/steady_stop.hpp"
#include "ecs/scheduler.hpp"
#include "io/atomic_file.hpp"
#include "io/json.hpp"
#include "methods/method.hpp"
#include "metrics/metrics.hpp"
#include "scene/scene.hpp"
#include "systems/io/checkpoint.hpp"
#include "systems/io/hdf5_frame.hpp"
#include "systems/io/xdmf.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/pressure/pressure_system.hpp"
#include "systems/probes/vorticity_field.hpp"

namespace ryushi {

namespace fs = std::filesystem;

// Set by SIGINT and SIGTERM (run.cpp installs the handler); the loop stops cleanly at the next step.
inline std::atomic<bool> g_interrupted{false};

// The scene's overrides with --end-time as time.end (a run and its checkpoint keep both).
std::vector<std::string> with_end_time(const RunOptions& opt);

template <int D>
class Runner {
 public:
  // resume: the checkpoint to continue from (empty: a fresh run).
  Runner(const Scene& scene, const RunOptions& opt, fs::path resume = {})
      : scene_(scene), opt_(opt), profiler_(opt.trace), resume_(std::move(resume)) {
    checkpoint_interval_ = opt.checkpoint_interval ? *opt.checkpoint_interval : scene.checkpoint_interval;
    // The text the run was started from, once: checkpoints record it and resume compares it.
    if (checkpoint_interval_ > 0) scene_text_ = scene.text;
  }

  // Everything that can reject the input, before any file is written.
  void prepare() {
    PipelineOptions po{opt_.dump_matrix_dir, opt_.dump_step};
    auto method = build_method<D>(scene_, world_, po);
    context_ = method.context;
    probes_ = probes_of(scene_, world_, context_);
    search_cell_ = method.search_cell;
    method_parameters_ = method.parameters;
    method_diagnostics_ = method.diagnostics;
    method_summary_ = method.summary;
    density_may_vanish_ = method.density_may_vanish;
    settled_.requested = method.settle_steps;
    res_.ensure(domain_resource<D>) = context_.domain;
    res_.ensure(resources::time) = 0.0;
    res_.ensure(resources::step) = 0;
    scheduler_ = std::make_unique<Scheduler<D>>(std::move(method.pipeline), world_, res_, profiler_);
    scheduler_->initialise();
    frame_fields_ = scene_.output_fields;
    for (auto& f : method.frame_fields)
      if (std::find(frame_fields_.begin(), frame_fields_.end(), f) == frame_fields_.end())
        frame_fields_.push_back(f);
    // A field computed when a frame is written (systems/probes/vorticity_field.hpp).
    if (std::count(frame_fields_.begin(), frame_fields_.end(), "vorticity")) vorticity_column(world_);
    for (auto& f : scene_.output_fields)
      if (!world_.has(f)) {
        std::string list;
        for (auto& n : world_.column_names()) list += (list.empty() ? "" : ", ") + n;
        throw SceneError(scene_.path + ": [output] fields: no per-particle field '" + f +
                         "' in this pipeline; available: " + list);
      }
    res_.ensure(resources::dt) = scene_.fixed_dt > 0 ? scene_.fixed_dt : method.first_dt;
    res_.ensure(resources::dt_chosen) = res_.get(resources::dt);
    if (!resume_.empty()) restore();
    HealthCheck<D> h;
    h.density_may_vanish = density_may_vanish_;
    h.run(world_, context_.domain);
    if (h.index != HealthCheck<D>::kNone)
      throw SceneError(scene_.path + ": the initial state is invalid: particle id " +
                       std::to_string(world_.column(components::id)[h.index]) + " " + h.problem);
    // A fresh run into a directory that holds another run's files: that run's checkpoint would
    // later resume into this run's frames (issue 51: frames of two scenes, a particles.xdmf
    // pointing at missing files).
    out_ = opt_.out_dir.empty() ? fs::path("out") / scene_.name : fs::path(opt_.out_dir);
    if (resume_.empty() && !opt_.overwrite)
      if (auto found = run_files_in(out_); !found.empty())
        throw SceneError(out_.string() + ": holds another run's files (" + found +
                         "): pass --overwrite to replace them, or continue that run with `ryushi resume " +
                         out_.string() + "`");
    if (resume_.empty()) settle_start();  // app/run_settle.hpp
    // After a resume: the scales, the energy's start and the density's timer are the original
    // run's, as the checkpoint holds them (older checkpoints: the restored state's).
    health_.prepare(scene_, world_, context_);
    if (!restored_monitor_.empty()) health_.restore(restored_monitor_);
  }

  int run() {
    if (resume_.empty() && opt_.overwrite) remove_run_files(out_);
    fs::create_directories(out_ / "frames");
    // A resumed run removes the frames written after its checkpoint (a killed run may have got
    // further); a fresh one finds none (refused or cleared in prepare()).
    std::set<std::string> kept;
    for (auto& f : frames_) kept.insert(fs::path(f.file).filename().string());
    for (auto& e : fs::directory_iterator(out_ / "frames"))
      if ((e.path().extension() == ".h5" && !kept.count(e.path().filename().string())) ||
          e.path().extension() == ".tmp")
        fs::remove(e.path());
    fs::remove(out_ / "trace.json");
    wall_start_ = std::chrono::steady_clock::now();
    if (resume_.empty()) {
      initial_ = diagnose(world_, context_.rho0);
      next_checkpoint_ = checkpoint_interval_;
    }
    slot_output_ = profiler_.slot("output");
    slot_probes_ = profiler_.slot("probes");
    slot_reorder_ = profiler_.slot("reorder_by_cell");
    slot_health_ = profiler_.slot("health_check");
    slot_monitor_ = profiler_.slot("health_monitor");
    if (!opt_.quiet) {
      const auto& kind = world_.column(components::kind);
      const auto elastic = static_cast<std::size_t>(std::count(kind.begin(), kind.end(), kElastic));
      const std::string solids = elastic > 0 ? " + " + std::to_string(elastic) + " elastic" : "";
      // A resumed run counts the checkpoint's particles (initial_ keeps only the start's mass and volume).
      const auto now = resume_.empty() ? initial_ : diagnose(world_, context_.rho0);
      spdlog::info("{}: {}D {}, {} fluid + {} wall{} particles, {} -> {}", scene_.name, D, scene_.method,
                   now.fluid, now.walls - elastic, solids, method_summary_, out_.string());
    }

    std::string status = "completed", message;
    int code = kExitDone;
    Progress progress(time_, step_, scene_.end_time, opt_.quiet);
    try {
      if (resume_.empty()) {
        sample_probes_now();
        write_output();
      } else {
        write_text_atomic(out_ / "particles.xdmf", xdmf_document(frames_));
        if (!scene_.probes.empty())
          write_text_atomic(out_ / "probes.csv", probes_csv(scene_.probes, probe_rows_));
        if (!opt_.quiet)
          spdlog::info("resumed at t = {:.6g} s, step {}, frame {}", time_, step_, frames_.size());
      }
      while (time_ < scene_.end_time * (1 - 1e-12)) {
        if (scene_.max_steps > 0 && step_ >= scene_.max_steps) {
          // Not "completed": the end time was not reached (it said so).
          status = "max_steps";
          message = "stopped at time.max_steps = " + std::to_string(scene_.max_steps) +
                    ", t = " + std::to_string(time_) + " s of " + std::to_string(scene_.end_time) + " s";
          break;
        }
        if (g_interrupted) {
          status = "interrupted";
          code = kExitInterrupted;
          message = "interrupted by signal at t = " + std::to_string(time_) + " s";
          // A checkpointed run stops where `ryushi resume` can continue it.
          if (checkpoint_interval_ > 0 && step_ > 0) write_checkpoint_now();
          break;
        }
        advance();
        if (steady_.enabled() && steady_.reached(time_, fluid_kinetic_energy(world_))) {
          status = "steady";  // exit 0: the run ended as asked ([time] steady_tolerance)
          message = steady_.message;
          break;
        }
        if (time_ >= next_probe_ * (1 - 1e-12)) sample_probes_now();
        if (time_ >= next_output_ * (1 - 1e-12)) write_output();
        if (checkpoint_interval_ > 0 && time_ >= next_checkpoint_ * (1 - 1e-12)) write_checkpoint_now();
        progress.update(time_, step_);
      }
      if (frames_.empty() || frames_.back().time < time_) write_output();
    } catch (const NumericalFailure& e) {
      status = "failed";
      code = kExitNumericalFailure;
      message = e.what();
    } catch (const OutputError& e) {
      status = "failed";
      code = kExitOutputFailed;
      message = std::string("could not write the output: ") + e.what();
    } catch (const std::exception& e) {
      // An internal error: still leave a summary that says what happened, then report it.
      progress.finish();
      finish("error", e.what());
      throw;
    }
    progress.finish();
    try {
      finish(status, message);
    } catch (const OutputError& e) {  // the disk is still full: the message goes to stderr only
      std::fprintf(stderr, "ryushi: %s\n", e.what());
    }
    if (code == kExitNumericalFailure)
      std::fprintf(stderr, "ryushi: numerical failure: %s\n", message.c_str());
    if (code == kExitOutputFailed)
      std::fprintf(stderr, "ryushi: %s (frames and the checkpoint written before are whole)\n",
                   message.c_str());
    if (code == kExitInterrupted) std::fprintf(stderr, "ryushi: %s\n", message.c_str());
    return code;
  }

 private:
  // One step: the reorder, the step length landing on the next frame, the step graph, the
  // world's deferred changes, the checks after it (app/run_advance.hpp).
  void advance();

  // After every step: a particle that is not a number or left the box (health_check.hpp); with
  // outflow = "remove" the fluid that left is erased first.
  void check_state() {
    Profiler::Scope t(profiler_, slot_health_);
    if (scene_.outflow_removes) remove_escaped_fluid();
    HealthCheck<D> h;
    h.density_may_vanish = density_may_vanish_;
    h.run(world_, context_.domain, scene_.fixed_dt > 0 ? dt_used_ : 0.0, context_.spacing);
    if (h.index != HealthCheck<D>::kNone) {
      auto& x = world_.column(components::position)[h.index];
      std::ostringstream m;
      m << "step " << step_ << " (t = " << time_ << " s): particle id "
        << world_.column(components::id)[h.index] << " " << h.problem << " at (";
      for (int a = 0; a < D; ++a) m << (a ? ", " : "") << x[a];
      m << ") after system '" << scheduler_->last_writer(h.column) << "'";
      throw NumericalFailure(m.str());
    }
  }

  // [health]: the physical checks (health_monitor.hpp), timed on their own.
  void check_health() {
    Profiler::Scope t(profiler_, slot_monitor_);
    if (auto finding = health_.check(world_, time_)) {
      std::ostringstream m;
      m << "step " << step_ << " (t = " << time_ << " s): health check '" << finding->check
        << "': " << finding->message << " after system '" << scheduler_->last_writer(finding->column)
        << "' (likely: " << finding->cause << ")";
      if (!scene_.health.warn) throw NumericalFailure(m.str());
      if (health_warned_.insert(finding->check).second) {  // [health] action = "warn": once per check
        spdlog::warn("{}", m.str());
        health_warnings_.push_back(m.str());
      }
    }
  }

  // [domain] outflow = "remove": fluid particles that left the box (finite positions: a
  // non-finite one is still a failure) are erased between steps and counted; the first is logged.
  void remove_escaped_fluid() {
    auto& x = world_.column(components::position);
    auto& kind = world_.column(components::kind);
    auto& m = world_.column(components::mass);
    std::vector<std::uint32_t> gone;
    for (std::size_t i = 0; i < world_.size(); ++i)
      if (kind[i] == kFluid && x[i].allFinite() && !context_.domain.contains(x[i]))
        gone.push_back(std::uint32_t(i));
    if (gone.empty()) return;
    if (removed_ == 0)
      spdlog::warn(
          "t = {:.6g} s: fluid particle id {} left the domain and is removed ([domain] outflow = "
          "\"remove\"); "
          "the count is in summary.json",
          time_, world_.column(components::id)[gone.front()]);
    for (auto i : gone) removed_mass_ += m[i];
    removed_ += gone.size();
    CommandBuffer<D> cb;
    cb.erase(std::move(gone));
    cb.apply(world_);
  }

  // app/run_checkpoint.hpp: the whole state as a checkpoint, its writing, and the restore.
  Checkpoint checkpoint_state() const;
  double wall_elapsed() const {
    return wall_before_ +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
  }

  void write_checkpoint_now();
  void restore();
  void sample_probes_now() {
    next_probe_ = (std::floor(time_ / scene_.probe_interval + 1e-9) + 1) * scene_.probe_interval;
    if (scene_.probes.empty()) return;
    Profiler::Scope t(profiler_, slot_probes_);
    auto values = sample_probes<D>(probes_, world_, context_);
    values.insert(values.begin(), time_);
    probe_rows_.push_back(std::move(values));
  }

  void write_output() {
    next_output_ = (std::floor(time_ / scene_.output_interval + 1e-9) + 1) * scene_.output_interval;
    Profiler::Scope t(profiler_, slot_output_);
    char name[64];
    std::snprintf(name, sizeof name, "frames/frame_%05zu.h5", frames_.size());
    if (world_.has("vorticity")) compute_vorticity(world_, context_);
    auto fields = write_frame<D>(out_ / name, world_, frame_fields_, time_, step_, run_id_);
    frames_.push_back({name, time_, world_.size(), fields});
    write_text_atomic(out_ / "particles.xdmf", xdmf_document(frames_));
    if (!scene_.probes.empty())
      write_text_atomic(out_ / "probes.csv", probes_csv(scene_.probes, probe_rows_));
    write_summary("running", "");
  }

  void finish(const std::string& status, const std::string& message) {
    if (!opt_.dump_matrix_dir.empty() && step_ <= opt_.dump_step)
      spdlog::warn("--dump-matrix: the run ended after {} steps, before --dump-step {}; nothing was dumped",
                   step_, opt_.dump_step);
    if (!scene_.probes.empty())
      write_text_atomic(out_ / "probes.csv", probes_csv(scene_.probes, probe_rows_));
    write_summary(status, message);
    write_text_atomic(out_ / "profile.json", profiler_.json());
    if (opt_.trace) write_text_atomic(out_ / "trace.json", profiler_.trace_json());
    if (!opt_.quiet) {
      double wall = wall_elapsed();
      std::printf("%s", profiler_.table().c_str());
      for (auto& [name, value] : metrics()) std::printf("metric %s = %.6g\n", name.c_str(), value);
      std::printf("%s: %s, %lld steps, t = %.6g s, wall %.2f s, %.3g particle-steps/s\n", scene_.name.c_str(),
                  status.c_str(), step_, time_, wall, wall > 0 ? world_.size() * double(step_) / wall : 0.0);
    }
  }

  void write_summary(const std::string& status, const std::string& message);  // run_summary.hpp
  void settle_start();                                                        // run_settle.hpp

  std::vector<std::pair<std::string, double>> metrics() const {
    return evaluate_metrics<D>(scene_, world_, probe_rows_, context_.rho0, context_.gravity_magnitude, time_);
  }

  static std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
  }

  const Scene& scene_;
  const RunOptions& opt_;
  Profiler profiler_;
  MethodContext<D> context_;
  std::vector<Probe> probes_;  // the scene's [[probe]] entries, as the probes sample them
  std::vector<std::pair<std::string, double>> method_parameters_;
  std::function<std::vector<std::pair<std::string, double>>(const World<D>&, const Resources&)>
      method_diagnostics_;
  std::map<std::string, std::pair<double, double>>
      diagnostic_range_;  // each one's least, largest at a summary
  World<D> world_;
  Resources res_;
  std::unique_ptr<Scheduler<D>> scheduler_;
  std::string method_summary_;
  std::vector<std::string> frame_fields_;  // [output] fields and what the method adds (temperature, ...)
  bool density_may_vanish_ = false;
  HealthMonitor<D> health_;
  const double estimated_bytes_ = estimate_memory(scene_).bytes;  // the guard's, for summary.json
  std::vector<double> restored_monitor_;      // the checkpoint's health monitor state
  std::set<std::string> health_warned_;       // the checks that warned (action = "warn")
  std::vector<std::string> health_warnings_;  // their messages, for summary.json
  fs::path out_;
  std::vector<FrameRecord> frames_;
  std::vector<std::vector<double>> probe_rows_;
  Diagnostics initial_;
  SettleReport settled_;  // the start's settling (app/settle.hpp), before t = 0
  SteadyStop steady_{scene_.steady_tolerance, scene_.steady_window};
  double time_ = 0, dt_used_ = 0, next_output_ = 0, next_probe_ = 0;
  long long step_ = 0;
  std::size_t removed_ = 0;  // fluid particles erased by outflow = "remove"
  double removed_mass_ = 0;
  double search_cell_ = 0;  // MethodSetup::search_cell
  std::size_t slot_output_ = 0, slot_probes_ = 0, slot_reorder_ = 0, slot_health_ = 0, slot_monitor_ = 0;
  fs::path resume_;
  std::vector<std::uint32_t> restored_order_;
  std::string scene_text_;
  std::uint64_t run_id_ = new_run_id();  // in every frame, the checkpoint and summary.json
  double checkpoint_interval_ = 0, next_checkpoint_ = 0;
  std::chrono::steady_clock::time_point wall_start_;
  double wall_before_ = 0;  // the wall time of the segments before a resume (the checkpoint's)
};

}  // namespace ryushi

#include "app/run_advance.hpp"
#include "app/run_checkpoint.hpp"
#include "app/run_settle.hpp"
#include "app/run_summary.hpp"
