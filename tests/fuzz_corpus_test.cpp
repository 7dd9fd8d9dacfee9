// Replays the scene fuzzer's corpus (fuzz/corpus/, and fuzz/crashes/ for inputs that once
// crashed and were fixed) through the loader: no crash, no exception but SceneError, and every
// rejection names a place (file:line:column or the --set override).
#include <doctest/doctest.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "../fuzz/scene_input.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

TEST_CASE("fuzz: the scene fuzzer's corpus loads or is rejected with a message that names a place") {
  auto dir = test::unique_scratch("fuzz_replay");
  fs::create_directories(dir);
  const std::string path = (dir / "input.toml").string();
  std::vector<fs::path> inputs;
  for (const char* sub : {"corpus", "crashes"}) {
    auto d = test::source_dir() / "fuzz" / sub;
    if (!fs::exists(d)) continue;
    for (auto& e : fs::directory_iterator(d))
      if (e.is_regular_file() && e.path().filename() != "README.md") inputs.push_back(e.path());
  }
  std::sort(inputs.begin(), inputs.end());
  REQUIRE(inputs.size() > 20);
  auto level = spdlog::get_level();
  spdlog::set_level(spdlog::level::off);
  std::size_t accepted = 0;
  for (auto& input : inputs) {
    fuzz::Outcome o;
    try {
      o = fuzz::load(test::read_text(input), path);
    } catch (const std::exception& e) {
      FAIL_CHECK(input.filename().string() << ": " << e.what());
      continue;
    }
    accepted += o.accepted;
    CHECK_MESSAGE(o.names_a_place, input.filename().string() << ": " << o.message);
  }
  spdlog::set_level(level);
  MESSAGE(inputs.size() << " inputs, " << accepted << " accepted");
  CHECK(accepted > 0);
}

// 300 seeded mutations of the shipped scenes through `ryushi check` (tools/fuzz_check.py: extreme
// and non-numbers, wrong strings and arrays, lines deleted, repeated or swapped, schema keys with
// values of the wrong kind, [health] tables, --set overrides): each exits 0, or 2 with one line
// naming the place; no crash, no other exit code, no hang (issue 51). Measured 2026-11-29: 48
// accepted, 252 refused, 13 s.
TEST_CASE("fuzz: 300 scene mutations through ryushi check give exit 0 or 2 with a place, no crash or hang") {
#if defined(__SANITIZE_ADDRESS__)
  const std::string limit = " --no-ulimit";
#else
  const std::string limit;
#endif
  auto r = test::run_command("/usr/bin/python3 " + (test::source_dir() / "tools" / "fuzz_check.py").string() +
                             " " + RYUSHI_BINARY + " --count 300 --seed 1" + limit);
  CHECK_MESSAGE(r.code == 0, r.output);
  CHECK(r.output.find("300 mutations of ") != std::string::npos);
}
