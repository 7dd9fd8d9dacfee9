// Settling before t = 0 (app/settle.hpp; ISPH's implicit density formulation, [method]
// settle_steps, docs/isph.md "Settling before t = 0"): a resting tank is moved into the discrete
// equilibrium near its lattice, a dam-break column and a fluid given a velocity start as the scene
// made them, and summary.json's settle block says which.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "h5_read.hpp"
#include "shipped_scene_run.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

const std::string kImplicit = "method.formulation=\"implicit_density\"";

// summary.json's settle block (its keys are not unique in the whole summary: "steps").
std::string settle_block(const std::filesystem::path& out) {
  const auto summary = test::read_text(out / "summary.json");
  const auto at = summary.find("\"settle\"");
  REQUIRE_MESSAGE(at != std::string::npos, "no settle block in " << out / "summary.json");
  return summary.substr(at, summary.find('}', at) - at);
}

// Frame 0's fluid positions by particle id (2D; the frame stores three components).
std::map<double, std::pair<double, double>> start_positions(const std::filesystem::path& out) {
  const auto frame = out / "frames" / "frame_00000.h5";
  auto id = test::read_dataset(frame, "id").values, kind = test::read_dataset(frame, "kind").values;
  auto x = test::read_dataset(frame, "position").values;
  std::map<double, std::pair<double, double>> by_id;
  for (std::size_t i = 0; i < id.size(); ++i)
    if (kind[i] == 0) by_id[id[i]] = {x[3 * i], x[3 * i + 1]};
  return by_id;
}

// The largest distance between two runs' starts, particle by particle.
double largest_difference(const std::map<double, std::pair<double, double>>& a,
                          const std::map<double, std::pair<double, double>>& b) {
  REQUIRE(a.size() == b.size());
  double largest = 0;
  for (auto& [id, p] : a) {
    auto q = b.at(id);
    largest = std::max(largest, std::hypot(p.first - q.first, p.second - q.second));
  }
  return largest;
}

// A scene run for one short step with the settle (the default) and without it: the two outputs.
struct SettledAndNot {
  std::filesystem::path settled, lattice;
};
SettledAndNot run_with_and_without_settle(const std::string& label, const std::string& scene) {
  const std::vector<std::string> sets{kImplicit, "time.end=0.01", "output.interval=0.01"};
  auto without = sets;
  without.push_back("method.settle_steps=0");
  return {test::run_shipped_scene(label, scene, "", sets),
          test::run_shipped_scene(label + "_off", scene, "", without)};
}

}  // namespace

// Measured 2026-11-29: 1,000 steps (2 s of wall time on one thread), the corner particles where
// the surface meets the walls moved 0.086 d, everything else far less. The bounds: settled, the
// start moved by at least a hundredth of a spacing somewhere (a settle that did nothing fails) and
// by less than the half spacing that would have refused it.
TEST_CASE("settle: a resting tank settles into the discrete equilibrium near its lattice") {
  const double d = 0.0125;
  const auto [settled, lattice] = run_with_and_without_settle("settle_tank", "hydrostatic_isph_2d.toml");
  const auto block = settle_block(settled);
  MESSAGE("resting tank: ", block);
  CHECK(test::json_raw(block, "at_rest") == "true");
  CHECK(test::json_number(block, "steps") == 1000);
  const double moved = largest_difference(start_positions(settled), start_positions(lattice)) / d;
  MESSAGE("resting tank: the settled start lies up to ", moved, " spacings from the lattice");
  CHECK(moved == doctest::Approx(test::json_number(block, "largest_displacement")).epsilon(1e-6));
  CHECK(moved > 0.01);
  CHECK(moved < 0.5);
  // Without settle_steps the run has no settle block.
  CHECK(test::read_text(lattice / "summary.json").find("\"settle\"") == std::string::npos);
}

// Measured 2026-11-29: the a/d = 20 column's front moved half a spacing in 20 steps.
TEST_CASE("settle: a dam-break column is not at rest and starts from the scene's lattice") {
  const auto [tried, lattice] = run_with_and_without_settle("settle_column", "dam_break_isph_2d.toml");
  const auto block = settle_block(tried);
  MESSAGE("dam-break column: ", block);
  CHECK(test::json_raw(block, "at_rest") == "false");
  CHECK(test::json_number(block, "largest_displacement") > 0.5);
  CHECK(test::json_number(block, "steps") < 100);
  CHECK(test::json_raw(block, "refused").find("not at rest") != std::string::npos);
  // Restored exactly: the same start as without settling.
  CHECK(largest_difference(start_positions(tried), start_positions(lattice)) == 0.0);
  const auto v = test::read_dataset(tried / "frames" / "frame_00000.h5", "velocity").values;
  CHECK(*std::max_element(v.begin(), v.end()) == 0.0);
  CHECK(*std::min_element(v.begin(), v.end()) == 0.0);
}

TEST_CASE("settle: a fluid given a velocity is not settled") {
  const auto out = test::run_shipped_scene("settle_square", "rotating_square_isph_2d.toml", "",
                                           {kImplicit, "time.end=0.01", "output.interval=0.01"});
  const auto block = settle_block(out);
  CHECK(test::json_raw(block, "at_rest") == "false");
  CHECK(test::json_number(block, "steps") == 0);
  CHECK(test::json_raw(block, "refused") == "the fluid starts moving");
}
