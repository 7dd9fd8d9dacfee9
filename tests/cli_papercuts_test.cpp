// Papercuts found by trying ryushi as a new user would (issue 51, point 6), each pinned.
#include <doctest/doctest.h>

#include <string>

#include "app/exit_codes.hpp"
#include "test_util.hpp"

using namespace ryushi;

TEST_CASE("cli: a thread count of 0 and an unknown command are one-line errors that say what is wrong") {
  const std::string bin = RYUSHI_BINARY;
  auto zero = test::run_command(bin + " run " + test::scene_path("dam_break_2d.toml") + " --threads 0");
  CHECK(zero.code == kExitBadInput);
  // It printed the double range's 310-digit upper end.
  CHECK_MESSAGE(zero.output.find("not in range 1 to 4096") != std::string::npos, zero.output);
  CHECK(zero.output.size() < 200);
  auto unknown = test::run_command(bin + " frobnicate");
  CHECK(unknown.code == kExitBadInput);
  // It said only that a subcommand is required.
  CHECK_MESSAGE(unknown.output.find("no command 'frobnicate'; the commands are run, resume") != std::string::npos,
                unknown.output);
}

TEST_CASE("cli: the scene reference writes small bounds as numbers, not 0.0000") {
  auto keys = test::run_command(std::string(RYUSHI_BINARY) + " keys --markdown");
  REQUIRE(keys.code == kExitDone);
  const auto cfl = keys.output.find("| `cfl` |");
  REQUIRE(cfl != std::string::npos);
  const auto row = keys.output.substr(cfl, keys.output.find('\n', cfl) - cfl);
  CHECK_MESSAGE(row.find("Allowed: >= 1e-06 <= 1.") != std::string::npos, row);
  CHECK(keys.output.find("0.0000") == std::string::npos);
}

TEST_CASE("cli: `ryushi keys` lists every key on a line for a terminal; --markdown is the reference") {
  auto plain = test::run_command(std::string(RYUSHI_BINARY) + " keys");
  REQUIRE(plain.code == kExitDone);
  // It printed the Markdown tables of docs/scenes.md.
  CHECK(plain.output.find("| key | type |") == std::string::npos);
  CHECK(plain.output.find("\n  time.cfl  number  default (0.2") != std::string::npos);
  CHECK(plain.output.find("\n  method.delta  number") != std::string::npos);  // a method's own key
  CHECK(plain.output.find("\n  health.energy_rise  number  default 0.05\n") != std::string::npos);
  auto markdown = test::run_command(std::string(RYUSHI_BINARY) + " keys --markdown");
  CHECK(markdown.output.find("| key | type |") != std::string::npos);
}

TEST_CASE("cli: a run stopped by time.max_steps says so, not \"completed\"") {
  auto dir = test::unique_scratch("max_steps_status");
  auto r = test::run_command(std::string(RYUSHI_BINARY) + " run " + test::scene_path("hydrostatic_2d.toml") +
                             " --quiet --set time.max_steps=3 --out " + dir.string());
  CHECK(r.code == kExitDone);
  const auto summary = test::read_text(dir / "summary.json");
  CHECK(test::json_raw(summary, "status") == "max_steps");
  CHECK_MESSAGE(summary.find("stopped at time.max_steps = 3, t = ") != std::string::npos, summary);
}
