// The `ryushi` command line: run, check and keys. Exit codes: app/exit_codes.hpp.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "scene/schema.hpp"

int main(int argc, char** argv) {
  using namespace ryushi;
  CLI::App app{"ryushi: particle methods for fluid mechanics (WCSPH, ISPH, MPS, shallow-water MPS)"};
  app.set_version_flag("--version", "ryushi 0.1.0");
  app.require_subcommand(1);

  RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run a scene file headless.");
  run_cmd->add_option("scene", run.scene, "Scene file (TOML)")->required();
  run_cmd->add_option("--out", run.out_dir, "Output directory (default out/<scene name>)");
  run_cmd->add_option("--threads", run.threads, "Worker threads (default: all cores)")->check(CLI::PositiveNumber);
  run_cmd->add_option("--end-time", run.end_time, "Override time.end (s)");
  run_cmd->add_option("--set", run.sets, "Override a scene key: section.key=value (repeatable)");
  run_cmd->add_flag("--trace", run.trace, "Write trace.json (Chrome trace events, opens in Perfetto)");
  run_cmd->add_flag("--quiet", run.quiet, "No progress output and no profile table");

  std::string check_path;
  std::vector<std::string> check_sets;
  auto* check_cmd = app.add_subcommand("check", "Validate a scene file without running it.");
  check_cmd->add_option("scene", check_path, "Scene file (TOML)")->required();
  check_cmd->add_option("--set", check_sets, "Override a scene key: section.key=value (repeatable)");

  bool markdown = false;
  auto* keys_cmd = app.add_subcommand("keys", "Print the scene-file reference (every section and key).");
  keys_cmd->add_flag("--markdown", markdown, "Markdown (docs/scenes.md is this output)");

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
  if (*check_cmd) return check_scene(check_path, check_sets);
  if (*keys_cmd) {
    std::printf("%s", schema_markdown().c_str());
    return kExitDone;
  }
  return kExitBadInput;
}
