// Never lose a run (issue 9): a run killed with SIGKILL at random moments and resumed from its
// checkpoint, again and again, ends bit-identical to a run that was never stopped (same thread
// count), and every frame on disk opens. Resume refuses a missing checkpoint, keys that built the
// state, and frames of another run; a run refuses a folder of another run's files.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <thread>

#include "app/exit_codes.hpp"
#include "app/progress.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

extern char** environ;

using namespace ryushi;
namespace fs = std::filesystem;

namespace {

// Starts `args` (argv[0] the binary) with output to /dev/null; returns the pid.
pid_t spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  REQUIRE(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits up to `seconds` for pid; kills it with SIGKILL if still running. Returns the exit code,
// or -1 when it was killed.
int wait_or_kill(pid_t pid, double seconds) {
  auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -2;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return -1;
}

// `ryushi run` of the 2D dam break under a file-size limit of `kib` KiB (ulimit -f; ryushi ignores
// SIGXFSZ, so a write past it fails with EFBIG, as on a full disk).
test::CommandResult run_with_file_limit(int kib, const fs::path& out, const std::string& args) {
  return test::run_command("bash -c 'ulimit -f " + std::to_string(kib) + "; exec " + std::string(RYUSHI_BINARY) +
                           " run " + test::scene_path("dam_break_2d.toml") + " --out " + out.string() +
                           " --quiet " + args + "'");
}

std::vector<fs::path> frames_of(const fs::path& out) {
  std::vector<fs::path> f;
  for (auto& e : fs::directory_iterator(out / "frames")) f.push_back(e.path());
  std::sort(f.begin(), f.end());
  return f;
}

}  // namespace

TEST_CASE("checkpoint: a run killed at random moments and resumed ends bit-identical to an unstopped run") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("checkpoint_kill");
  const std::vector<std::string> common{"--set", "particles.spacing=0.01", "--end-time", "0.3", "--threads", "2",
                                        "--quiet", "--checkpoint-interval", "0.02"};
  auto run_args = [&](const fs::path& out) {
    std::vector<std::string> a{bin, "run", test::scene_path("dam_break_2d.toml"), "--out", out.string()};
    a.insert(a.end(), common.begin(), common.end());
    return a;
  };
  const fs::path full = dir / "full", part = dir / "part";
  REQUIRE(wait_or_kill(spawn(run_args(full)), 120) == kExitDone);

  // Each kill comes at a random moment after the run has written its first checkpoint (before
  // it there is nothing to resume: a user would start the run again).
  std::mt19937 random(20261123);
  std::uniform_real_distribution<double> moment(0.05, 1.0);
  auto until_checkpoint = [&](pid_t pid) {
    for (int k = 0; k < 6000 && !fs::exists(part / "checkpoint.h5"); ++k) {
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -2;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return -3;  // still running
  };
  pid_t pid = spawn(run_args(part));
  int code = until_checkpoint(pid);
  REQUIRE(code == -3);
  code = wait_or_kill(pid, moment(random));
  int kills = code == -1;
  for (int attempt = 0; code != kExitDone && attempt < 20; ++attempt) {
    // After three kills, let it finish.
    const double budget = kills < 3 ? moment(random) : 120.0;
    code = wait_or_kill(spawn({bin, "resume", part.string(), "--threads", "2", "--quiet"}), budget);
    kills += code == -1;
    REQUIRE((code == -1 || code == kExitDone));
  }
  MESSAGE(kills << " kills");
  CHECK(kills >= 2);
  REQUIRE(code == kExitDone);

  auto a = frames_of(full), b = frames_of(part);
  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() == 16);
  for (std::size_t k = 0; k < a.size(); ++k)
    for (const char* name : {"position", "velocity", "pressure", "density", "id", "kind"}) {
      auto x = test::read_dataset(a[k], name).values, y = test::read_dataset(b[k], name).values;
      REQUIRE_MESSAGE(x == y, b[k] << ": " << name << " differs from the unstopped run");
    }
  auto sa = test::read_text(full / "summary.json"), sb = test::read_text(part / "summary.json");
  CHECK(test::json_number(sa, "steps") == test::json_number(sb, "steps"));
  // The summary's baseline survives the resume: the volume change (not the mass, a constant
  // column) is counted from the original start, the same printed value as the unstopped run's.
  CHECK(test::json_number(sb, "fluid_volume_relative_change") ==
        test::json_number(sa, "fluid_volume_relative_change"));
  // The probes and the XDMF collection cover the whole run, without a gap or a repeated row.
  CHECK(test::read_text(full / "probes.csv") == test::read_text(part / "probes.csv"));
  CHECK(test::read_text(full / "particles.xdmf") == test::read_text(part / "particles.xdmf"));
}

TEST_CASE(
    "checkpoint: resume refuses a missing checkpoint, runs from its own copy of the scene, and takes --set "
    "only "
    "for keys that can change mid-run") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("checkpoint_refusals");
  auto r = test::run_command(bin + " resume " + (dir / "nothing").string());
  CHECK(r.code == kExitBadInput);
  CHECK_MESSAGE(r.output.find("no checkpoint") != std::string::npos, r.output);

  auto scene = dir / "scene.toml";
  test::write_text(scene, test::block_scene("[0.3, 0.3]", "[0.5, 0.5]", 0.02,
                                            "[[wall]]\nmin = [0.3, 0.3]\nmax = [0.7, 0.7]\n[output]\ncheckpoint_interval = 0.01\n"));
  auto out = (dir / "out").string();
  REQUIRE(test::run_command(bin + " run " + scene.string() + " --out " + out + " --quiet").code == kExitDone);
  REQUIRE(fs::exists(dir / "out" / "checkpoint.h5"));
  // Extending a finished run with --end-time continues it.
  auto more = test::run_command(bin + " resume " + out + " --end-time 0.03 --quiet");
  CHECK(more.code == kExitDone);
  CHECK(test::json_number(test::read_text(dir / "out" / "summary.json"), "simulated_time") == doctest::Approx(0.03));
  // The checkpoint holds the scene's text: a scene file edited, or gone, does not matter (issue 51:
  // resume needed the file at its absolute path, byte-identical).
  test::write_text(scene, "this is not a scene any more\n");
  auto edited = test::run_command(bin + " resume " + out + " --end-time 0.04 --quiet");
  CHECK_MESSAGE(edited.code == kExitDone, edited.output);
  fs::remove(scene);
  // A key that is safe mid-run: a smaller CFL for the rest, recorded for the next resume.
  auto gone = test::run_command(bin + " resume " + out + " --end-time 0.05 --set time.cfl=0.1 --quiet");
  CHECK_MESSAGE(gone.code == kExitDone, gone.output);
  auto summary = test::read_text(dir / "out" / "summary.json");
  CHECK(test::json_number(summary, "simulated_time") == doctest::Approx(0.05));
  // One that built the state is refused, naming the ones that can change.
  auto refused = test::run_command(bin + " resume " + out + " --end-time 0.06 --set particles.spacing=0.01");
  CHECK(refused.code == kExitBadInput);
  CHECK_MESSAGE(refused.output.find("--set particles.spacing=0.01: not a key a resumed run can change") !=
                    std::string::npos,
                refused.output);
  CHECK(refused.output.find("time.cfl") != std::string::npos);
  CHECK(test::read_text(dir / "out" / "summary.json") == summary);  // nothing written
}

TEST_CASE(
    "checkpoint: a run refuses a folder with another run's files unless --overwrite, and resume refuses "
    "frames of another run") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("checkpoint_folders");
  auto scene = dir / "scene.toml";
  test::write_text(
      scene, test::block_scene(
                 "[0.3, 0.3]", "[0.5, 0.5]", 0.02,
                 "[[wall]]\nmin = [0.3, 0.3]\nmax = [0.7, 0.7]\n[output]\ncheckpoint_interval = 0.01\n"));
  const auto out = dir / "out";
  REQUIRE(test::run_command(bin + " run " + scene.string() + " --out " + out.string() + " --quiet").code ==
          kExitDone);
  const auto first = test::read_text(out / "summary.json");
  const auto first_id = test::json_raw(first, "run_id");
  // The case: a fresh run into the folder of an earlier one left its checkpoint, which a
  // later resume mixed with the new run's frames. Now refused, and nothing is written.
  auto again = test::run_command(bin + " run " + scene.string() + " --out " + out.string() + " --quiet");
  CHECK(again.code == kExitBadInput);
  CHECK_MESSAGE(again.output.find("holds another run's files (summary.json") != std::string::npos,
                again.output);
  CHECK(again.output.find("--overwrite") != std::string::npos);
  CHECK(again.output.find("ryushi resume") != std::string::npos);
  CHECK(test::read_text(out / "summary.json") == first);
  // A user's own file in the folder is kept by --overwrite; the run's files are replaced.
  test::write_text(out / "notes.txt", "mine\n");
  auto replaced = test::run_command(bin + " run " + scene.string() + " --out " + out.string() +
                                    " --quiet --overwrite --set output.checkpoint_interval=0");
  CHECK(replaced.code == kExitDone);
  CHECK(fs::exists(out / "notes.txt"));
  CHECK_FALSE(fs::exists(out / "checkpoint.h5"));  // the earlier run's is gone with it
  CHECK(test::json_raw(test::read_text(out / "summary.json"), "run_id") != first_id);
  CHECK(test::run_command(bin + " resume " + out.string()).code == kExitBadInput);  // no checkpoint to mix
  // A checkpointed run whose frame 1 is replaced by another run's: resume names it and stops.
  const auto other = dir / "other";
  REQUIRE(test::run_command(bin + " run " + scene.string() + " --out " + other.string() + " --quiet").code ==
          kExitDone);
  REQUIRE(
      test::run_command(bin + " run " + scene.string() + " --out " + out.string() + " --quiet --overwrite")
          .code == kExitDone);
  fs::copy_file(other / "frames" / "frame_00001.h5", out / "frames" / "frame_00001.h5",
                fs::copy_options::overwrite_existing);
  auto mixed = test::run_command(bin + " resume " + out.string() + " --end-time 0.03");
  CHECK(mixed.code == kExitBadInput);
  CHECK_MESSAGE(mixed.output.find("frame_00001.h5 belongs to another run") != std::string::npos,
                mixed.output);
}

TEST_CASE("checkpoint: a full disk stops the run with exit code 4 and a clear message, the frames so far whole") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("output_full");
  auto out = dir / "out";
  // A 160 KiB file-size limit (ulimit -f; ryushi ignores SIGXFSZ, so writes fail with EFBIG):
  // this scene's frames (99 KB) fit, its checkpoint (every column, 256 KB) does not.
  auto r = run_with_file_limit(160, out, "--set particles.spacing=0.02 --end-time 0.05 --checkpoint-interval 0.02");
  CHECK(r.code == kExitOutputFailed);
  CHECK_MESSAGE(r.output.find("could not write the output") != std::string::npos, r.output);
  CHECK_MESSAGE(r.output.find("checkpoint.h5.tmp: write failed: File too large") != std::string::npos, r.output);
  CHECK(!fs::exists(out / "checkpoint.h5.tmp"));
  auto frames = frames_of(out);
  REQUIRE(frames.size() >= 2);  // t = 0, 0.0025, ... up to the first checkpoint
  for (auto& f : frames) {
    CHECK(f.extension() == ".h5");
    CHECK(!test::read_dataset(f, "position").values.empty());
  }
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "failed");

  // An output directory that cannot be made: exit 4 before any step.
  test::write_text(dir / "blocked" / "frames", "a file where the frames directory should be");
  auto blocked = test::run_command(bin + " run " + test::scene_path("dam_break_2d.toml") + " --out " +
                                   (dir / "blocked").string() + " --quiet --end-time 0.01");
  CHECK(blocked.code == kExitOutputFailed);
  CHECK_MESSAGE(blocked.output.find("could not write the output") != std::string::npos, blocked.output);
}

TEST_CASE("checkpoint: SIGINT stops a checkpointed run with a checkpoint where it stopped, and resume finishes it") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("checkpoint_sigint");
  const fs::path full = dir / "full", part = dir / "part";
  auto args = [&](const fs::path& out) {
    return std::vector<std::string>{bin, "run", test::scene_path("dam_break_2d.toml"), "--out", out.string(),
                                    "--set", "particles.spacing=0.01", "--end-time", "0.3", "--threads", "2",
                                    "--quiet", "--checkpoint-interval", "0.1"};
  };
  REQUIRE(wait_or_kill(spawn(args(full)), 120) == kExitDone);
  pid_t pid = spawn(args(part));
  for (int k = 0; k < 6000 && !fs::exists(part / "frames" / "frame_00002.h5"); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == kExitInterrupted);
  // The checkpoint is where the run stopped (after frame 2, t = 0.03 s), not at a multiple of 0.1.
  const double stopped = test::json_number(test::read_text(part / "summary.json"), "simulated_time");
  CHECK(stopped < 0.3);
  CHECK(stopped >= 0.03);
  CHECK(test::read_dataset(part / "checkpoint.h5", "clock").values.at(0) == doctest::Approx(stopped).epsilon(1e-9));
  const double wall_before = test::json_number(test::read_text(part / "summary.json"), "wall_time_s");
  REQUIRE(wait_or_kill(spawn({bin, "resume", part.string(), "--threads", "2", "--quiet"}), 120) == kExitDone);
  auto a = frames_of(full), b = frames_of(part);
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
    REQUIRE(test::read_dataset(a[k], "position").values == test::read_dataset(b[k], "position").values);
  // The resumed run's summary and profile are the whole run's, not its last segment's: the
  // first system's calls (one per step) are the unstopped run's, the wall time includes the
  // part before the stop.
  auto summary = test::read_text(part / "summary.json"), profile = test::read_text(part / "profile.json");
  const double steps = test::json_number(summary, "steps");
  CHECK(steps == test::json_number(test::read_text(full / "summary.json"), "steps"));
  CHECK(test::json_number(profile, "calls") == steps);
  CHECK(test::json_number(summary, "wall_time_s") > wall_before);
  // The resumed run goes on checkpointing at the interval the first was given on the command
  // line (it wrote none before: a second stop lost the resumed segment).
  CHECK(test::read_dataset(part / "checkpoint.h5", "clock").values.at(0) > stopped);
}

TEST_CASE("checkpoint: a disk that fills after a checkpoint leaves that checkpoint whole, and resume continues from it") {
  const std::string bin = RYUSHI_BINARY;
  auto dir = test::scratch("checkpoint_later_full");
  auto out = dir / "out";
  // A 320 KiB file-size limit: the first checkpoints fit, but with a probe sample at every step
  // the checkpoint (which carries the probe rows, for resume) and probes.csv grow past it after
  // some thousand steps: the write that fails is a later checkpoint's (or probes.csv's).
  auto r = run_with_file_limit(320, out,
                               "--set particles.spacing=0.02 --set output.probe_interval=1e-7"
                               " --end-time 2.0 --checkpoint-interval 0.02");
  REQUIRE(r.code == kExitOutputFailed);
  CHECK_MESSAGE(r.output.find(".tmp: write failed: File too large") != std::string::npos, r.output);
  CHECK(!fs::exists(out / "probes.csv.tmp"));
  CHECK(!fs::exists(out / "checkpoint.h5.tmp"));
  // The latest checkpoint is whole and behind where the run stopped.
  const double stopped = test::json_number(test::read_text(out / "summary.json"), "simulated_time");
  const double saved = test::read_dataset(out / "checkpoint.h5", "clock").values.at(0);
  CHECK(saved >= 0.02);
  CHECK(saved <= stopped);
  // With the disk free again the run resumes from it and finishes (a short end: the point is
  // that the checkpoint opens and carries on, not the remaining seconds).
  auto resumed = test::run_command(bin + " resume " + out.string() + " --end-time " + std::to_string(saved + 0.01));
  CHECK_MESSAGE(resumed.code == kExitDone, resumed.output);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "completed");
  // Its first line counts the checkpoint's particles (it said 0 fluid + 0 wall before).
  const auto fluid = static_cast<long long>(test::json_number(summary, "fluid_particles"));
  CHECK(fluid > 0);
  CHECK_MESSAGE(resumed.output.find(", " + std::to_string(fluid) + " fluid + ") != std::string::npos, resumed.output);
}

// The progress line's rate and ETA count from where this process started. A run resumed at
// t = 0.5 s, step 1000 (of a run to 1 s) that stands at t = 0.6 s, step 1100 after 10 s did 10
// steps/s and needs 40 s more; counted from t = 0 it would claim 110 steps/s and 6.7 s (the
// 255k benchmark's resumed segments printed "140 steps/s, ETA 117 s" for hours of work left).
TEST_CASE("checkpoint: a resumed run's progress rate and ETA count from the resume") {
  const auto resumed = progress_rate(0.5, 1000, 0.6, 1100, 10.0, 1.0);
  CHECK(resumed.steps_per_second == doctest::Approx(10.0));
  CHECK(resumed.eta_s == doctest::Approx(40.0));
  const auto fresh = progress_rate(0.0, 0, 0.25, 50, 5.0, 1.0);
  CHECK(fresh.steps_per_second == doctest::Approx(10.0));
  CHECK(fresh.eta_s == doctest::Approx(15.0));
  // Nothing advanced yet, or past the end: no division by zero, no negative time left.
  CHECK(progress_rate(0.5, 1000, 0.5, 1000, 0.0, 1.0).eta_s == 0.0);
  CHECK(progress_rate(0.0, 0, 1.2, 10, 1.0, 1.0).eta_s == 0.0);
}
