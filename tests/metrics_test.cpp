// [[metric]] entries (issue 9): each value in summary.json equals the same error computed here
// from the run's own output, and bad references or missing probes are exit code 2 naming a place.
#include <doctest/doctest.h>

#include <cmath>

#include "app/exit_codes.hpp"
#include "front_criterion.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

namespace {
std::string bin() { return RYUSHI_BINARY; }
}  // namespace

TEST_CASE("metrics: dam_break_front is the time-origin criterion of the tests, computed by the run") {
  auto dir = test::scratch("metric_front");
  auto r = test::run_command(bin() + " run " + test::scene_path("dam_break_2d.toml") + " --out " + dir.string() +
                             " --quiet --set particles.spacing=0.025 --end-time 0.3");
  REQUIRE(r.code == kExitDone);
  auto summary = test::read_text(dir / "summary.json");
  const double a = 0.25, g = 9.81;
  auto fit = test::fit_time_origin(test::front_of(test::read_csv(dir / "probes.csv"), a, std::sqrt(a / (2 * g))));
  CHECK(test::json_number(summary, "front_error") == doctest::Approx(fit.error).epsilon(1e-9));
  CHECK(test::json_number(summary, "front_error_shift") == doctest::Approx(fit.shift).epsilon(1e-9));
  CHECK(test::json_number(summary, "front_error_unshifted") > fit.error);
}

TEST_CASE("metrics: hydrostatic_pressure and probe_csv equal their definitions on the run's own output") {
  auto dir = test::scratch("metric_hydro");
  auto r = test::run_command(bin() + " run " + test::scene_path("hydrostatic_2d.toml") + " --out " + dir.string() +
                             " --quiet --end-time 0.05");
  REQUIRE(r.code == kExitDone);
  auto summary = test::read_text(dir / "summary.json");
  // From the last frame: fluid particles below the block's top (0.5 m in this scene).
  fs::path last;
  for (auto& e : fs::directory_iterator(dir / "frames")) last = std::max(last, e.path());
  auto x = test::read_dataset(last, "position").values, p = test::read_dataset(last, "pressure").values,
       kind = test::read_dataset(last, "kind").values;
  double num = 0, den = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (kind[i] != 0 || x[3 * i + 1] > 0.5) continue;
    const double ref = 1000.0 * 9.81 * (0.5 - x[3 * i + 1]);
    num += (p[i] - ref) * (p[i] - ref), den += ref * ref;
  }
  CHECK(test::json_number(summary, "pressure_error") == doctest::Approx(std::sqrt(num / den)).epsilon(1e-6));
  CHECK(test::json_number(summary, "pressure_error") < 0.05);

  // probe_csv against the run's own pressure probe: 0; against 1.1 times it: 0.1 / 1.1.
  auto probes = test::read_csv(dir / "probes.csv");
  std::string ref = "time,value\n", scaled = "time,value\n";
  const auto& t = probes["time"];
  const auto& column = probes["p_depth_0.40"];
  for (std::size_t k = 0; k < t.size(); ++k) {
    char line[96];
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", t[k], column[k]);
    ref += line;
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", t[k], 1.1 * column[k]);
    scaled += line;
  }
  test::write_text(dir / "ref.csv", ref);
  test::write_text(dir / "scaled.csv", scaled);
  const std::string probe = "p_depth_0.40";
  auto scene = dir / "scene.toml";
  test::write_text(scene, test::read_text(test::scene_path("hydrostatic_2d.toml")) +
                              "\n[[metric]]\nname = \"same\"\ntype = \"probe_csv\"\nprobe = \"" + probe +
                              "\"\nreference = \"ref.csv\"\n[[metric]]\nname = \"scaled\"\ntype = \"probe_csv\"\nprobe = \"" +
                              probe + "\"\nreference = \"scaled.csv\"\n");
  auto again = test::run_command(bin() + " run " + scene.string() + " --out " + (dir / "again").string() +
                                 " --quiet --end-time 0.05");
  REQUIRE(again.code == kExitDone);
  auto s2 = test::read_text(dir / "again" / "summary.json");
  CHECK(test::json_number(s2, "same") < 1e-9);
  CHECK(test::json_number(s2, "scaled") == doctest::Approx(0.1 / 1.1).epsilon(1e-6));
}

TEST_CASE("metrics: a bad reference table or a missing probe is exit code 2 with the place") {
  auto dir = test::scratch("metric_bad");
  auto check_scene = [&](const std::string& extra, const std::string& expect) {
    auto scene = dir / "scene.toml";
    test::write_text(scene, test::block_scene("[0.2, 0.0]", "[0.4, 0.2]", 0.01, extra));
    auto r = test::run_command(bin() + " check " + scene.string());
    CHECK(r.code == kExitBadInput);
    CHECK_MESSAGE(r.output.find(expect) != std::string::npos, r.output);
  };
  test::write_text(dir / "bad.csv", "# a comment\ntime,value\n0.0,1.0\n0.1,x\n");
  check_scene("[[probe]]\nname = \"ke\"\ntype = \"kinetic_energy\"\n[[metric]]\nname = \"m\"\ntype = \"probe_csv\"\nprobe = \"ke\"\nreference = \"bad.csv\"\n",
              "bad.csv:4: expected two numbers");
  check_scene("[[metric]]\nname = \"m\"\ntype = \"dam_break_front\"\n", "needs a [[probe]] of type surge_front");
  check_scene("[[probe]]\nname = \"ke\"\ntype = \"kinetic_energy\"\n[[metric]]\nname = \"m\"\ntype = \"probe_csv\"\nprobe = \"ke\"\n",
              "needs a reference CSV");
}
