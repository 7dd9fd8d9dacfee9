#pragma once
// Checkpoints (`[output] checkpoint_interval`, `ryushi resume`): the complete state of a run in
// one HDF5 file, written to NAME.tmp and renamed, so the file on disk is always a whole one.
// Holds every column at full precision (vectors N x D, tensors N x D x D: no padding), the id
// counter, the driver's clock (time, step, dt, the next output and probe times, the frames and
// probe rows written so far, the initial fluid mass and volume, removed particles, the wall time
// and the profile so far) and what is
// needed to rebuild the pipeline: the scene file's path and text and the --set overrides, and
// the ryushi version. Resources that systems rebuild every step (neighbour lists, cell grids,
// matrices, multigrid hierarchies) are not stored; a Verlet list is rebuilt on the first step
// after a resume and gives the same pairs in the same order, so the continued run is the run.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ecs/profiler.hpp"
#include "ecs/world.hpp"
#include "systems/io/xdmf.hpp"

namespace ryushi {

struct CheckpointClock {
  double time = 0, dt = 0, dt_chosen = 0, next_output = 0, next_probe = 0, next_checkpoint = 0;
  long long step = 0;
  double initial_fluid_mass = 0, initial_fluid_volume = 0;
  long long removed = 0;
  double removed_mass = 0;
  // The run's wall time and the profiler's step total so far, over every segment: a resumed
  // run's summary and profile.json cover the whole run (0 in checkpoints written before them).
  double wall_time_s = 0, profile_step_total_s = 0;
};

struct CheckpointScene {
  std::string path, text, version;
  std::vector<std::string> overrides;
  int dimension = 2;
  std::uint64_t run_id = 0;  // the run's, also in each of its frames (0: a checkpoint from before)
};

struct Checkpoint {
  CheckpointClock clock;
  CheckpointScene scene;
  std::vector<FrameRecord> frames;
  std::vector<std::vector<double>> probe_rows;
  // The particle order by cell of the search's last grid: the driver reorders with it at the
  // start of a step, so the first step after a resume needs it.
  std::vector<std::uint32_t> cell_order;
  // Each system's own state (System::checkpoint_state), by pipeline position and name.
  std::vector<std::pair<std::string, std::vector<double>>> system_states;
  // The profiler's entries so far (calls and seconds per system and driver task).
  std::vector<Profiler::Entry> profile;
  // The driver's health monitor (its energy's start, scales and timers; empty in checkpoints
  // written before 2026-11-29, whose resumes count from the resumed state).
  std::vector<double> monitor_state;
};

template <int D>
void write_checkpoint(const std::filesystem::path& path, const World<D>& world, const Checkpoint& c);

// Reads everything but the columns (to rebuild the scene and pipeline first). Throws
// std::runtime_error naming the file when it is not a ryushi checkpoint.
Checkpoint read_checkpoint_header(const std::filesystem::path& path);

// Replaces the world's particles and columns with the checkpoint's. Columns the pipeline did not
// allocate are created; the world's own columns missing from the file are an error.
template <int D>
void restore_checkpoint_columns(const std::filesystem::path& path, World<D>& world);

}  // namespace ryushi
