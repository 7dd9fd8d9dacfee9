#pragma once
// `ryushi run` and `ryushi check` as library calls (the CLI and the tests share them).
#include <optional>
#include <string>
#include <vector>

namespace ryushi {

struct RunOptions {
  std::string scene;
  std::string out_dir;  // default out/<scene name>
  // A directory that holds another run's files is refused (exit 2) unless overwrite, which
  // removes those files first (app/run_files.hpp).
  bool overwrite = false;
  int threads = 0;      // 0: all cores
  std::optional<double> end_time;
  std::vector<std::string> sets;
  bool trace = false;
  bool quiet = false;
  std::string dump_matrix_dir;  // write the pressure system of step dump_step here (implicit methods)
  long long dump_step = 0;
  std::optional<double> checkpoint_interval;  // overrides [output] checkpoint_interval
  std::vector<std::string> plugins;           // --plugin libraries (app/plugins.hpp)
  std::string scene_text;                     // the scene's text in place of the file's (a resume)
};

// `ryushi resume OUT`: continues the run whose checkpoint is OUT/checkpoint.h5, with the scene
// text and overrides the checkpoint holds (the scene file may have changed or gone); end_time
// extends it, and sets may change what is safe to change mid-run (resumable_keys()).
struct ResumeOptions {
  std::string out_dir;
  std::vector<std::string> sets;
  int threads = 0;
  std::optional<double> end_time;
  std::optional<double> checkpoint_interval;  // default: the run's own (the checkpoint's)
  bool quiet = false;
  std::vector<std::string> plugins;  // the --plugin libraries the run was started with
};

// Runs a scene; returns the exit code (app/exit_codes.hpp). Messages go to stderr/stdout.
int run_scene(const RunOptions& options);
int resume_run(const ResumeOptions& options);
// The keys `ryushi resume --set` may change: the step's controls, the output's cadence, the end.
const std::vector<std::string>& resumable_keys();
// Validates a scene (and builds its pipeline without running it); returns the exit code.
// Loads the scene and builds its method; with write_initial, also writes the particles it made
// (fluid, walls, with normals and kinds) as frame 0 of DIR/particles.xdmf, to look at in ParaView.
int check_scene(const std::string& scene, const std::vector<std::string>& sets, const std::string& write_initial = "",
                const std::vector<std::string>& plugins = {});

}  // namespace ryushi
