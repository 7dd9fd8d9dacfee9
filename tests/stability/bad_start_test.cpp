// Starts that are not a flow (issue 9): an empty fluid block, fluid placed inside a wall's
// particle layers or on top of other fluid are refused at load (exit 2, the key's place, no
// output written); particles leaving the domain fail cleanly or are removed and counted, under
// every method.
#include <doctest/doctest.h>

#include "stability_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

namespace {

// A 0.2 m x 0.2 m block in a 0.4 m box at d = 0.02 (isph gets one wall layer, the others the
// layers their support needs).
std::string tank(const std::string& fluid) {
  return "[scene]\ndimension = 2\n[domain]\nmin = [-0.2, -0.2]\nmax = [0.6, 0.8]\n[particles]\nspacing = "
         "0.02\n"
         "[time]\nend = 0.05\n" +
         fluid + "[[wall]]\nmin = [0.0, 0.0]\nmax = [0.4, 0.4]\n";
}

void check_refused(const std::string& name, const std::string& scene, const std::string& method,
                   const std::string& place, const std::string& message) {
  auto dir = test::scratch("stability_" + name + "_" + method);
  test::write_text(dir / "scene.toml", scene);
  auto r = test::run_command(std::string(RYUSHI_BINARY) + " run " + (dir / "scene.toml").string() +
                             " --out " + (dir / "out").string() + " --quiet --set method.name=" + method);
  INFO(name << " under " << method << ": " << r.output);
  CHECK(r.code == kExitBadInput);
  CHECK(r.output.find((dir / "scene.toml").string() + ":" + place + ": " + message) != std::string::npos);
  CHECK(!fs::exists(dir / "out" / "summary.json"));
}

}  // namespace

TEST_CASE(
    "stability: an empty fluid block, fluid inside a wall's layers and fluid on fluid are refused at load") {
  for (const char* method : {"wcsph", "mps", "isph"}) {
    check_refused("empty", tank("[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.0, 0.2]\n"), method, "12:7",
                  "[[fluid]] #0 is empty: thinner than one particle spacing on axis 0");
    // Three spacings into the left wall: its particles would sit on the wall's.
    check_refused("in_wall", tank("[[fluid]]\nmin = [-0.06, 0.0]\nmax = [0.2, 0.2]\n"), method, "11:7",
                  "[[fluid]] #0 reaches into the");
    check_refused(
        "on_fluid",
        tank(
            "[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.2, 0.2]\n[[fluid]]\nmin = [0.1, 0.1]\nmax = [0.3, 0.3]\n"),
        method, "14:7", "[[fluid]] #1 overlaps [[fluid]] #0");
  }
  // Blocks that only touch the wall's box or each other are a tank, not an overlap.
  auto ok = test::run_text(
      "touching",
      tank("[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.2, 0.2]\n[[fluid]]\nmin = [0.2, 0.0]\nmax = [0.4, 0.2]\n"),
      {});
  CHECK(ok.code == kExitDone);
}

TEST_CASE(
    "stability: a block falling out of a wall-less domain fails cleanly, or is removed and counted, under "
    "every method") {
  // No walls: free fall from the block's lowest row at y = 0.075 m crosses y = 0 after 0.124 s;
  // by t = 0.2 s the three lowest of the five rows (24 particles) have left.
  const std::string scene =
      "[scene]\ndimension = 2\n[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[particles]\nspacing = 0.05\n"
      "[time]\nend = 0.2\n[output]\ninterval = 0.05\n[[fluid]]\nmin = [0.3, 0.05]\nmax = [0.7, 0.30]\n";
  for (const char* method : {"wcsph", "mps", "isph"}) {
    auto failed =
        test::run_text(std::string("falling_") + method, scene, {std::string("method.name=") + method});
    test::check_clean_failure(failed, method);
    CHECK(test::json_raw(failed.summary, "message").find("left the domain") != std::string::npos);
    auto removed = test::run_text(std::string("falling_removed_") + method, scene,
                                  {std::string("method.name=") + method, "domain.outflow=remove"});
    INFO(method);
    REQUIRE(removed.code == kExitDone);
    CHECK(test::json_number(removed.summary, "removed_particles") == 24);
    CHECK(test::json_number(removed.summary, "fluid_particles") == 16);
  }
}
