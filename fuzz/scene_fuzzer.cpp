// libFuzzer target for the scene loader and the --set overrides (issue 9): an input is a scene
// file's text with optional leading "#set section.key=value" lines (fuzz/scene_input.hpp).
// load_scene must accept it or throw SceneError naming a place; any other exception, a crash,
// a sanitizer report or a hang is a bug. Build and run: fuzz/README.md.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/ryushi_fuzz_" + std::to_string(::getpid()) + ".toml";
  static const bool quiet = [] {
    spdlog::set_level(spdlog::level::off);
    return true;
  }();
  (void)quiet;
  auto outcome = ryushi::fuzz::load(std::string(reinterpret_cast<const char*>(data), size), path);
  if (!outcome.names_a_place) {
    std::fprintf(stderr, "scene error without a place: %s\n", outcome.message.c_str());
    std::abort();
  }
  return 0;
}
