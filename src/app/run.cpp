#include "app/run.hpp"

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
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
#include <set>
#include <sstream>

#include "app/exit_codes.hpp"
#include "app/progress.hpp"
#include "ecs/scheduler.hpp"
#include "io/json.hpp"
#include "app/plugins.hpp"
#include "methods/method.hpp"
#include "metrics/metrics.hpp"
#include "scene/scene.hpp"
#include "systems/io/atomic_file.hpp"
#include "systems/io/checkpoint.hpp"
#include "systems/io/hdf5_frame.hpp"
#include "systems/io/xdmf.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/pressure/pressure_system.hpp"
#include "systems/probes/probes.hpp"

namespace fs = std::filesystem;

namespace ryushi {

namespace {

std::atomic<bool> g_interrupted{false};
extern "C" void on_signal(int) { g_interrupted = true; }

class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The first fluid particle (lowest index) with a non-finite or out-of-domain state, or, with a
// fixed time.dt, one that crossed more than a spacing in the last step (|v| dt > d: CFL above 1;
// a fixed step that is too large otherwise "completes" a tank at rest with particles at 26 m/s,
// MPS at twice its limit). With the adaptive step the control shortens the next step instead: a
// splash particle that jumps to 3x the fastest speed within one step is not a failure (an MPS
// dam break at CFL 0.4 survives one at t = 0.24 s).
template <int D>
struct HealthCheck {
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t index = kNone;
  std::string column, problem;

  bool density_may_vanish = false;

  // dt: the step just taken (0: not checked); spacing: the initial particle spacing d.
  void run(const World<D>& w, const Domain<D>& domain, double dt = 0, double spacing = 0) {
    auto& x = w.column(components::position);
    auto& v = w.column(components::velocity);
    auto& rho = w.column(components::density);
    auto& p = w.column(components::pressure);
    auto& kind = w.column(components::kind);
    auto bad = [&](std::size_t i) -> int {
      if (kind[i] != kFluid && kind[i] != kElastic) return 0;  // walls are placed, not integrated
      if (!x[i].allFinite()) return 1;
      if (!v[i].allFinite()) return 2;
      if (!std::isfinite(rho[i]) || rho[i] < 0 || (rho[i] == 0 && !density_may_vanish)) return 3;
      if (!std::isfinite(p[i])) return 4;
      if (!domain.contains(x[i])) return 5;
      if (dt > 0 && v[i].squaredNorm() * dt * dt > spacing * spacing) return 6;
      return 0;
    };
    index = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, w.size(), 8192), kNone,
        [&](auto r, std::size_t found) {
          for (std::size_t i = r.begin(); i != r.end() && i < found; ++i)
            if (bad(i)) return i;
          return found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
    if (index == kNone) return;
    static const char* columns[] = {"", "position", "velocity", "density", "pressure", "position", "velocity"};
    static const char* problems[] = {"", "non-finite position", "non-finite velocity",
                                     "non-finite or non-positive density", "non-finite pressure",
                                     "left the domain", ""};
    int code = bad(index);
    column = columns[code];
    problem = problems[code];
    if (code == 6) {
      std::ostringstream m;
      m << "crossed " << v[index].norm() * dt / spacing << " spacings in one step (|v| = " << v[index].norm()
        << " m/s, dt = " << dt << " s: CFL above 1; the time step is too large for this flow)";
      problem = m.str();
    }
  }
};

struct Diagnostics {
  std::size_t fluid = 0, walls = 0;
  double fluid_mass = 0, fluid_volume = 0, kinetic_energy = 0, max_speed = 0, max_density_deviation = 0;
  // Total fluid momentum (x, y, z) and sum m |v|, the scale it is judged against: in a closed
  // periodic box a pairwise-antisymmetric method keeps the total to round-off.
  std::array<double, 3> momentum{0, 0, 0};
  double momentum_scale = 0;
};

template <int D>
Diagnostics diagnose(const World<D>& w, double rho0) {
  Diagnostics d;
  auto& kind = w.column(components::kind);
  auto& m = w.column(components::mass);
  auto& v = w.column(components::velocity);
  auto& rho = w.column(components::density);
  auto& id = w.column(components::id);
  // The mass is summed in id order, so reordering particles by cell cannot change the total
  // by round-off: an unchanged set of particles gives a bit-identical mass.
  std::vector<double> mass_by_id, volume_by_id;
  std::vector<Vec<D>> momentum_by_id;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (kind[i] != kFluid) {
      ++d.walls;
      continue;
    }
    ++d.fluid;
    if (mass_by_id.size() <= std::size_t(id[i]))
      mass_by_id.resize(id[i] + 1, 0.0), volume_by_id.resize(id[i] + 1, 0.0),
          momentum_by_id.resize(id[i] + 1, Vec<D>::Zero());
    mass_by_id[id[i]] = m[i];
    momentum_by_id[id[i]] = m[i] * v[i];
    d.momentum_scale += m[i] * v[i].norm();
    volume_by_id[id[i]] = rho[i] > 0 ? m[i] / rho[i] : 0.0;
    d.kinetic_energy += 0.5 * m[i] * v[i].squaredNorm();
    d.max_speed = std::max(d.max_speed, v[i].norm());
    d.max_density_deviation = std::max(d.max_density_deviation, std::abs(rho[i] / rho0 - 1));
  }
  for (double mi : mass_by_id) d.fluid_mass += mi;
  for (double vi : volume_by_id) d.fluid_volume += vi;
  for (auto& p : momentum_by_id)
    for (int a = 0; a < D; ++a) d.momentum[a] += p[a];
  return d;
}

std::vector<std::string> with_end_time(const RunOptions& opt);

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string probes_csv(const std::vector<ProbeSpec>& probes, const std::vector<std::vector<double>>& rows) {
  std::ostringstream out;
  out.precision(10);
  out << "time";
  for (auto& p : probes) out << "," << p.name;
  out << "\n";
  for (auto& r : rows) {
    for (std::size_t k = 0; k < r.size(); ++k) out << (k ? "," : "") << r[k];
    out << "\n";
  }
  return out.str();
}

template <int D>
class Runner {
 public:
  // resume: the checkpoint to continue from (empty: a fresh run).
  Runner(const Scene& scene, const RunOptions& opt, fs::path resume = {})
      : scene_(scene), opt_(opt), profiler_(opt.trace), resume_(std::move(resume)) {
    checkpoint_interval_ = opt.checkpoint_interval ? *opt.checkpoint_interval : scene.checkpoint_interval;
    // The text the run was started from, once: checkpoints record it and resume compares it.
    if (checkpoint_interval_ > 0) scene_text_ = read_file(scene.path);
  }

  // Everything that can reject the input, before any file is written.
  void prepare() {
    PipelineOptions po{opt_.dump_matrix_dir, opt_.dump_step};
    auto method = build_method<D>(scene_, world_, po);
    context_ = method.context;
    search_cell_ = method.search_cell;
    method_parameters_ = method.parameters;
    method_diagnostics_ = method.diagnostics;
    method_summary_ = method.summary;
    density_may_vanish_ = method.density_may_vanish;
    res_.ensure(domain_resource<D>) = context_.domain;
    res_.ensure(resources::time) = 0.0;
    res_.ensure(resources::step) = 0;
    scheduler_ = std::make_unique<Scheduler<D>>(std::move(method.pipeline), world_, res_, profiler_);
    scheduler_->initialise();
    frame_fields_ = scene_.output_fields;
    for (auto& f : method.frame_fields)
      if (std::find(frame_fields_.begin(), frame_fields_.end(), f) == frame_fields_.end()) frame_fields_.push_back(f);
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
  }

  int run() {
    out_ = opt_.out_dir.empty() ? fs::path("out") / scene_.name : fs::path(opt_.out_dir);
    fs::create_directories(out_ / "frames");
    // A fresh run removes a previous run's frames; a resumed one those written after its
    // checkpoint (a killed run may have got further).
    std::set<std::string> kept;
    for (auto& f : frames_) kept.insert(fs::path(f.file).filename().string());
    for (auto& e : fs::directory_iterator(out_ / "frames"))
      if ((e.path().extension() == ".h5" && !kept.count(e.path().filename().string())) || e.path().extension() == ".tmp")
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
    if (!opt_.quiet) {
      const auto& kind = world_.column(components::kind);
      const auto elastic = static_cast<std::size_t>(std::count(kind.begin(), kind.end(), kElastic));
      const std::string solids = elastic > 0 ? " + " + std::to_string(elastic) + " elastic" : "";
      // A resumed run counts the checkpoint's particles (initial_ keeps only the start's mass and volume).
      const auto now = resume_.empty() ? initial_ : diagnose(world_, context_.rho0);
      spdlog::info("{}: {}D {}, {} fluid + {} wall{} particles, {} -> {}", scene_.name, D, scene_.method, now.fluid,
                   now.walls - elastic, solids, method_summary_, out_.string());
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
        if (!scene_.probes.empty()) write_text_atomic(out_ / "probes.csv", probes_csv(scene_.probes, probe_rows_));
        if (!opt_.quiet) spdlog::info("resumed at t = {:.6g} s, step {}, frame {}", time_, step_, frames_.size());
      }
      while (time_ < scene_.end_time * (1 - 1e-12)) {
        if (scene_.max_steps > 0 && step_ >= scene_.max_steps) break;
        if (g_interrupted) {
          status = "interrupted";
          code = kExitInterrupted;
          message = "interrupted by signal at t = " + std::to_string(time_) + " s";
          // A checkpointed run stops where `ryushi resume` can continue it.
          if (checkpoint_interval_ > 0 && step_ > 0) write_checkpoint_now();
          break;
        }
        advance();
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
    if (code == kExitNumericalFailure) std::fprintf(stderr, "ryushi: numerical failure: %s\n", message.c_str());
    if (code == kExitOutputFailed)
      std::fprintf(stderr, "ryushi: %s (frames and the checkpoint written before are whole)\n", message.c_str());
    if (code == kExitInterrupted) std::fprintf(stderr, "ryushi: %s\n", message.c_str());
    return code;
  }

 private:
  void advance() {
    // Also before the first step: the scene's blocks come in lattice order, walls after the
    // fluid, so a wall and the fluid beside it sit a whole block apart in index until the first
    // reorder (which keeps WCSPH's each-pair-once pass from running in parallel blocks). That
    // one sorts by a grid of the neighbour search's cell (or of the kernel's support, two
    // spacings at least, for a method without one), since no search has run yet: in another
    // grid's order every row of the first list comes out of order and is sorted (3D MPS at 1M
    // particles: 3 s of the first step), and so is every row rebuilt until the next reorder.
    // It used to follow the first step, which then ran on the unsorted lattice and rebuilt the
    // neighbour list a second time (an MPS run at 1.36M particles: 1.0 s).
    if (scene_.reorder_interval > 0 && step_ % scene_.reorder_interval == 0) {
      Profiler::Scope t(profiler_, slot_reorder_);
      CellGrid<D> start_grid;
      std::span<const std::uint32_t> order;
      if (!restored_order_.empty()) {
        order = restored_order_;  // the first step after a resume
      } else if (step_ == 0 || !res_.has(cell_grid_resource<D>.name)) {  // (no search: every time)
        start_grid.build(
            context_.domain,
            search_cell_ > 0 ? search_cell_ : std::max(context_.kernel.support(), 2 * context_.spacing),
            world_.column(components::position));
        order = start_grid.sorted();
      } else {
        order = res_.get(cell_grid_resource<D>).sorted();
      }
      if (order.size() == world_.size()) {
        CommandBuffer<D> cb;
        cb.permute({order.begin(), order.end()});
        cb.apply(world_);
      }
    }
    restored_order_.clear();
    double& dt = res_.get(resources::dt);
    if (scene_.fixed_dt > 0) dt = scene_.fixed_dt;
    if (!(dt >= scene_.dt_min))
      throw NumericalFailure("step " + std::to_string(step_) + " (t = " + fmt(time_) + " s): time step " +
                             fmt(dt) + " s fell below time.dt_min = " + fmt(scene_.dt_min) +
                             " s (system 'time_step_control')");
    // Land exactly on the next output time (or time.end) without a sliver of a last step: when
    // less than two steps remain, split the rest evenly. dt_chosen keeps the control's step.
    res_.get(resources::dt_chosen) = dt;
    const double target = std::min(next_output_, scene_.end_time);
    const double rest = target - time_;
    const bool lands = dt * (1 + 1e-9) >= rest;  // a fixed dt that divides the interval lands
    if (lands)
      dt = rest;
    else if (2 * dt > rest)
      dt = 0.5 * rest;
    dt_used_ = dt;
    res_.get(resources::step) = step_;
    auto begin = std::chrono::steady_clock::now();
    try {
      scheduler_->step();
    } catch (const AccessViolation&) {
      throw;
    } catch (const std::exception& e) {
      throw NumericalFailure("step " + std::to_string(step_) + ": " + e.what());
    }
    if (res_.has(structural_changes_resource<D>.name)) {
      auto& changes = res_.get(structural_changes_resource<D>);
      if (!changes.empty()) changes.apply(world_);
    }
    profiler_.add_step_time(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
    time_ = lands ? target : time_ + dt_used_;  // frame times exactly as asked, no round-off
    res_.get(resources::time) = time_;
    ++step_;
    Profiler::Scope t(profiler_, slot_health_);
    if (scene_.outflow_removes) remove_escaped_fluid();
    HealthCheck<D> h;
    h.density_may_vanish = density_may_vanish_;
    h.run(world_, context_.domain, scene_.fixed_dt > 0 ? dt_used_ : 0.0, context_.spacing);
    if (h.index != HealthCheck<D>::kNone) {
      auto& x = world_.column(components::position)[h.index];
      std::ostringstream m;
      m << "step " << step_ << " (t = " << time_ << " s): particle id " << world_.column(components::id)[h.index]
        << " " << h.problem << " at (";
      for (int a = 0; a < D; ++a) m << (a ? ", " : "") << x[a];
      m << ") after system '" << scheduler_->last_writer(h.column) << "'";
      throw NumericalFailure(m.str());
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
      if (kind[i] == kFluid && x[i].allFinite() && !context_.domain.contains(x[i])) gone.push_back(std::uint32_t(i));
    if (gone.empty()) return;
    if (removed_ == 0)
      spdlog::warn("t = {:.6g} s: fluid particle id {} left the domain and is removed ([domain] outflow = \"remove\"); "
                   "the count is in summary.json",
                   time_, world_.column(components::id)[gone.front()]);
    for (auto i : gone) removed_mass_ += m[i];
    removed_ += gone.size();
    CommandBuffer<D> cb;
    cb.erase(std::move(gone));
    cb.apply(world_);
  }

  Checkpoint checkpoint_state() const {
    Checkpoint c;
    auto& k = c.clock;
    k.time = time_, k.step = step_, k.dt = res_.get(resources::dt), k.dt_chosen = res_.get(resources::dt_chosen);
    k.next_output = next_output_, k.next_probe = next_probe_, k.next_checkpoint = next_checkpoint_;
    k.initial_fluid_mass = initial_.fluid_mass, k.initial_fluid_volume = initial_.fluid_volume;
    k.removed = (long long)removed_, k.removed_mass = removed_mass_;
    k.wall_time_s = wall_elapsed(), k.profile_step_total_s = profiler_.step_total_s();
    c.profile = profiler_.entries();
    c.scene.path = fs::absolute(scene_.path).string();
    c.scene.text = scene_text_;
    c.scene.overrides = with_end_time(opt_);
    // The resolved frame and probe intervals: their defaults follow time.end, and a resume with
    // --end-time must keep the run's own.
    char b[80];
    std::snprintf(b, sizeof b, "output.interval=%.17g", scene_.output_interval);
    c.scene.overrides.push_back(b);
    std::snprintf(b, sizeof b, "output.probe_interval=%.17g", scene_.probe_interval);
    c.scene.overrides.push_back(b);
    // And the checkpoint interval, which `run --checkpoint-interval` may have set outside the
    // scene: without it a resumed run wrote no checkpoint, and its next stop lost the segment.
    std::snprintf(b, sizeof b, "output.checkpoint_interval=%.17g", checkpoint_interval_);
    c.scene.overrides.push_back(b);
    c.scene.version = "ryushi 0.1.0";
    c.scene.dimension = D;
    c.frames = frames_;
    c.probe_rows = probe_rows_;
    if (res_.has(cell_grid_resource<D>.name)) {  // a method without a neighbour search has none
      auto order = res_.get(cell_grid_resource<D>).sorted();
      c.cell_order.assign(order.begin(), order.end());
    }
    for (auto& system : scheduler_->pipeline()) c.system_states.push_back({system->name(), system->checkpoint_state(world_, res_)});
    return c;
  }

  // The run's wall time: this segment's plus those before a resume.
  double wall_elapsed() const {
    return wall_before_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
  }

  void write_checkpoint_now() {
    Profiler::Scope t(profiler_, slot_output_);
    next_checkpoint_ = (std::floor(time_ / checkpoint_interval_ + 1e-9) + 1) * checkpoint_interval_;
    write_checkpoint<D>(out_ / "checkpoint.h5", world_, checkpoint_state());
  }

  // The state of the checkpoint replaces the freshly built world and the driver's clock.
  void restore() {
    auto c = read_checkpoint_header(resume_);
    restore_checkpoint_columns<D>(resume_, world_);
    auto& k = c.clock;
    time_ = k.time, step_ = k.step;
    res_.get(resources::dt) = k.dt;
    res_.get(resources::dt_chosen) = k.dt_chosen;
    res_.get(resources::time) = time_;
    res_.get(resources::step) = step_;
    next_output_ = k.next_output, next_probe_ = k.next_probe, next_checkpoint_ = k.next_checkpoint;
    initial_.fluid_mass = k.initial_fluid_mass, initial_.fluid_volume = k.initial_fluid_volume;
    removed_ = std::size_t(k.removed), removed_mass_ = k.removed_mass;
    wall_before_ = k.wall_time_s;
    profiler_.restore(c.profile, k.profile_step_total_s);
    frames_ = c.frames;
    probe_rows_ = c.probe_rows;
    restored_order_ = c.cell_order;
    auto& pipeline = scheduler_->pipeline();
    if (c.system_states.size() != pipeline.size())
      throw SceneError(resume_.string() + ": the checkpoint's pipeline has " + std::to_string(c.system_states.size()) +
                       " systems, this build's " + std::to_string(pipeline.size()));
    for (std::size_t k = 0; k < pipeline.size(); ++k) {
      if (c.system_states[k].first != pipeline[k]->name())
        throw SceneError(resume_.string() + ": system " + std::to_string(k) + " is '" + c.system_states[k].first +
                         "' in the checkpoint, '" + pipeline[k]->name() + "' here");
      pipeline[k]->restore_state(world_, res_, c.system_states[k].second);
    }
  }

  void sample_probes_now() {
    next_probe_ = (std::floor(time_ / scene_.probe_interval + 1e-9) + 1) * scene_.probe_interval;
    if (scene_.probes.empty()) return;
    Profiler::Scope t(profiler_, slot_probes_);
    auto values = sample_probes<D>(scene_.probes, world_, context_);
    values.insert(values.begin(), time_);
    probe_rows_.push_back(std::move(values));
  }

  void write_output() {
    next_output_ = (std::floor(time_ / scene_.output_interval + 1e-9) + 1) * scene_.output_interval;
    Profiler::Scope t(profiler_, slot_output_);
    char name[64];
    std::snprintf(name, sizeof name, "frames/frame_%05zu.h5", frames_.size());
    auto fields = write_frame<D>(out_ / name, world_, frame_fields_, time_, step_);
    frames_.push_back({name, time_, world_.size(), fields});
    write_text_atomic(out_ / "particles.xdmf", xdmf_document(frames_));
    if (!scene_.probes.empty()) write_text_atomic(out_ / "probes.csv", probes_csv(scene_.probes, probe_rows_));
    write_summary("running", "");
  }

  void finish(const std::string& status, const std::string& message) {
    if (!opt_.dump_matrix_dir.empty() && step_ <= opt_.dump_step)
      spdlog::warn("--dump-matrix: the run ended after {} steps, before --dump-step {}; nothing was dumped", step_,
                   opt_.dump_step);
    if (!scene_.probes.empty()) write_text_atomic(out_ / "probes.csv", probes_csv(scene_.probes, probe_rows_));
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

  void write_summary(const std::string& status, const std::string& message) {
    auto now = diagnose(world_, context_.rho0);
    double wall = wall_elapsed();
    // A method without a neighbour search (a plugin's) has no list to report.
    static const NeighbourList empty_list;
    const auto& nl = res_.has(neighbours_resource.name) ? res_.get(neighbours_resource) : empty_list;
    JsonWriter w;
    w.begin_object();
    w.key("scene").value(scene_.name);
    w.key("scene_file").value(scene_.path);
    w.key("method").value(scene_.method);
    w.key("dimension").value(std::int64_t{D});
    w.key("status").value(status);
    w.key("message").value(message);
    w.key("particles").value(static_cast<std::int64_t>(world_.size()));
    w.key("fluid_particles").value(static_cast<std::int64_t>(now.fluid));
    w.key("wall_particles").value(static_cast<std::int64_t>(now.walls));
    w.key("steps").value(static_cast<std::int64_t>(step_));
    w.key("simulated_time").value(time_);
    w.key("end_time").value(scene_.end_time);
    w.key("wall_time_s").value(wall);
    w.key("particle_steps_per_second").value(wall > 0 ? world_.size() * double(step_) / wall : 0.0);
    w.key("frames").value(static_cast<std::int64_t>(frames_.size()));
    // Steps per build tell whether a Verlet skin pays ([particles] neighbour_skin).
    w.key("neighbour_list_builds").value(static_cast<std::int64_t>(nl.builds));
    w.key("bytes_per_particle").begin_object();
    w.key("columns").value(static_cast<std::int64_t>(world_.bytes_per_particle()));
    w.key("neighbour_list").value(world_.size() ? double(nl.bytes()) / world_.size() : 0.0);
    if (res_.has(solve_statistics_resource.name) && world_.size()) {
      // The pressure solve's memory at its largest step, per particle of the world (MPS, ISPH).
      const auto& st = res_.get(solve_statistics_resource);
      const double n = double(world_.size());
      w.key("pressure_matrix").value(st.max_matrix_bytes / n);
      w.key("pressure_preconditioner").value(st.max_preconditioner_bytes / n);
      w.key("pressure_krylov_vectors").value(st.max_krylov_bytes / n);
    }
    w.end_object();
    w.key("parameters").begin_object();
    w.key("spacing").value(scene_.spacing);
    for (auto& [name, value] : method_parameters_) w.key(name).value(value);
    w.key("last_dt").value(dt_used_);
    w.end_object();
    w.key("diagnostics").begin_object();
    w.key("fluid_mass_initial").value(initial_.fluid_mass);
    w.key("fluid_mass").value(now.fluid_mass);
    w.key("fluid_mass_relative_change").value(initial_.fluid_mass > 0 ? (now.fluid_mass - initial_.fluid_mass) / initial_.fluid_mass : 0.0);
    w.key("fluid_volume").value(now.fluid_volume);
    w.key("fluid_volume_relative_change").value(initial_.fluid_volume > 0 ? (now.fluid_volume - initial_.fluid_volume) / initial_.fluid_volume : 0.0);
    if (scene_.outflow_removes) {
      w.key("removed_particles").value(static_cast<std::int64_t>(removed_));
      w.key("removed_mass").value(removed_mass_);
    }
    w.key("kinetic_energy").value(now.kinetic_energy);
    for (int a = 0; a < D; ++a) w.key(std::string("momentum_") + "xyz"[a]).value(now.momentum[a]);
    w.key("momentum_scale").value(now.momentum_scale);
    w.key("max_speed").value(now.max_speed);
    w.key("max_density_deviation").value(now.max_density_deviation);
    if (method_diagnostics_)
      for (auto& [name, value] : method_diagnostics_(world_, res_)) w.key(name).value(value);
    w.end_object();
    w.key("metrics").begin_object();
    for (auto& [name, value] : metrics()) w.key(name).value(value);
    w.end_object();
    if (res_.has(solve_statistics_resource.name)) {
      const auto& st = res_.get(solve_statistics_resource);
      w.key("linear_solver").begin_object();
      w.key("krylov").value(st.krylov.empty() ? scene_.solver.krylov : st.krylov);
      w.key("preconditioner").value(scene_.solver.preconditioner);
      w.key("cycle").value(scene_.solver.cycle);
      w.key("precision").value(scene_.solver.precision);
      w.key("tolerance").value(scene_.solver.tolerance);
      w.key("solves").value(static_cast<std::int64_t>(st.solves));
      w.key("mean_iterations").value(st.solves ? double(st.iterations) / st.solves : 0.0);
      w.key("max_iterations").value(static_cast<std::int64_t>(st.max_iterations));
      w.key("max_relative_residual").value(st.max_relative_residual);
      w.key("max_unknowns").value(static_cast<std::int64_t>(st.max_rows));
      w.key("max_nonzeros").value(static_cast<std::int64_t>(st.max_nonzeros));
      w.end_object();
    }
    w.end_object();
    write_text_atomic(out_ / "summary.json", w.str());
  }

  std::vector<std::pair<std::string, double>> metrics() const {
    const double g = scene_.method == "swe" ? scene_.swe.gravity : scene_.gravity_magnitude();
    return evaluate_metrics<D>(scene_, world_, probe_rows_, context_.rho0, g, time_);
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
  std::vector<std::pair<std::string, double>> method_parameters_;
  std::function<std::vector<std::pair<std::string, double>>(const World<D>&, const Resources&)> method_diagnostics_;
  World<D> world_;
  Resources res_;
  std::unique_ptr<Scheduler<D>> scheduler_;
  std::string method_summary_;
  std::vector<std::string> frame_fields_;  // [output] fields and what the method adds (temperature, ...)
  bool density_may_vanish_ = false;
  fs::path out_;
  std::vector<FrameRecord> frames_;
  std::vector<std::vector<double>> probe_rows_;
  Diagnostics initial_;
  double time_ = 0, dt_used_ = 0, next_output_ = 0, next_probe_ = 0;
  long long step_ = 0;
  std::size_t removed_ = 0;  // fluid particles erased by outflow = "remove"
  double removed_mass_ = 0;
  double search_cell_ = 0;  // MethodSetup::search_cell
  std::size_t slot_output_ = 0, slot_probes_ = 0, slot_reorder_ = 0, slot_health_ = 0;
  fs::path resume_;
  std::vector<std::uint32_t> restored_order_;
  std::string scene_text_;
  double checkpoint_interval_ = 0, next_checkpoint_ = 0;
  std::chrono::steady_clock::time_point wall_start_;
  double wall_before_ = 0;  // the wall time of the segments before a resume (the checkpoint's)
};

std::vector<std::string> with_end_time(const RunOptions& opt) {
  auto sets = opt.sets;
  if (opt.end_time) {
    char value[40];
    std::snprintf(value, sizeof value, "%.17g", *opt.end_time);  // exact round trip
    sets.push_back(std::string("time.end=") + value);
  }
  return sets;
}

template <int D>
int run_dim(const Scene& scene, const RunOptions& opt, const fs::path& resume = {}) {
  Runner<D> runner(scene, opt, resume);
  runner.prepare();
  return runner.run();
}

}  // namespace

namespace {
// Loads the scene and runs it (continuing from the checkpoint `resume` when given) with the
// thread count and signal handlers, mapping failures to the exit codes of app/exit_codes.hpp.
int run_loaded(const RunOptions& opt, const fs::path& resume = {}, int checkpoint_dimension = 0) {
  std::unique_ptr<tbb::global_control> threads;
  if (opt.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, opt.threads);
  g_interrupted = false;
  auto old_int = std::signal(SIGINT, on_signal);
  auto old_term = std::signal(SIGTERM, on_signal);
  int code = kExitInternal;
  try {
    load_plugins(opt.plugins, opt.scene);
    Scene scene = load_scene(opt.scene, with_end_time(opt));
    if (checkpoint_dimension && scene.dimension != checkpoint_dimension)
      throw SceneError(resume.string() + ": the checkpoint is of another dimension");
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

int run_scene(const RunOptions& opt) { return run_loaded(opt); }

int resume_run(const ResumeOptions& ro) {
  const fs::path file = fs::path(ro.out_dir) / "checkpoint.h5";
  Checkpoint c;
  try {
    if (!fs::exists(file))
      throw std::runtime_error(file.string() + ": no checkpoint (run with [output] checkpoint_interval or --checkpoint-interval)");
    c = read_checkpoint_header(file);
    if (!fs::exists(c.scene.path)) throw std::runtime_error(file.string() + ": the scene file " + c.scene.path + " is gone");
    if (read_file(c.scene.path) != c.scene.text)
      throw std::runtime_error(file.string() + ": the scene file " + c.scene.path + " changed since the checkpoint");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ryushi: %s\n", e.what());
    return kExitBadInput;
  }
  RunOptions opt;
  opt.scene = c.scene.path;
  opt.out_dir = ro.out_dir;
  opt.threads = ro.threads;
  opt.quiet = ro.quiet;
  opt.sets = c.scene.overrides;  // the original run's, its end time included
  if (ro.end_time) opt.end_time = ro.end_time;
  if (ro.checkpoint_interval) opt.checkpoint_interval = ro.checkpoint_interval;
  opt.plugins = ro.plugins;
  return run_loaded(opt, file, c.scene.dimension);
}

int check_scene(const std::string& path, const std::vector<std::string>& sets, const std::string& write_initial,
                const std::vector<std::string>& plugins) {
  try {
    load_plugins(plugins, path);
    Scene scene = load_scene(path, sets);
    auto build = [&](auto dim) {
      constexpr int D = decltype(dim)::value;
      World<D> world;
      Resources res;
      Profiler profiler;
      auto method = build_method<D>(scene, world);
      Scheduler<D> s(std::move(method.pipeline), world, res, profiler);
      std::printf("%s: OK (%dD %s, %zu particles, %zu systems in the step graph)\n", path.c_str(), D,
                  scene.method.c_str(), world.size(), s.pipeline().size());
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
