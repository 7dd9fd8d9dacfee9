// Plugins (app/plugins.hpp, docs/extending.md): libraries whose methods and systems register as
// built-in ones do, loaded by --plugin or a scene's [plugins] before its keys are checked; bad
// ones are exit 2 naming the library and why. The example plugin's method, ballistic, integrates
// dv/dt = g - k v exactly, so its run is checked against the closed form to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "app/plugins.hpp"
#include "h5_read.hpp"
#include "scene/registered_keys.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

namespace {

// A block of 0.2 x 0.2 m thrown sideways into a large empty box, with no walls.
std::string ballistic_scene(const std::string& method_lines) {
  return "[scene]\ndimension = 2\n[domain]\nmin = [-10.0, -10.0]\nmax = [10.0, 10.0]\n[particles]\nspacing = "
         "0.05\n"
         "[method]\nname = \"ballistic\"\n" +
         method_lines +
         "[time]\nend = 0.5\ndt = 0.01\n[output]\ninterval = 0.5\n"
         "[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.2, 0.2]\nvelocity = [3.0, 1.0]\n";
}

test::CommandResult ryushi_cli(const std::string& args) {
  return test::run_command(std::string(RYUSHI_BINARY) + " " + args);
}

}  // namespace

TEST_CASE("plugins: bad libraries are exit 2 naming the library and why") {
  const auto dir = test::unique_scratch("bad_plugins");
  fs::create_directories(dir);
  const std::string scene = test::scene_path("dam_break_2d.toml");
  auto check_with = [&](const std::string& library, const std::string& why) {
    CAPTURE(library);
    auto r = ryushi_cli("check " + scene + " --plugin " + library);
    CHECK(r.code == 2);
    CHECK_MESSAGE(r.output.find("ryushi: --plugin: plugin " + library + ": " + why) != std::string::npos,
                  r.output);
  };
  check_with((dir / "missing.so").string(), "no such file");
  test::write_text(dir / "text.so", "not a library\n");
  check_with((dir / "text.so").string(), "not a shared library");
  check_with(RYUSHI_UNMARKED_PLUGIN, "not a ryushi plugin (no RYUSHI_PLUGIN() mark");
  check_with(RYUSHI_OTHER_VERSION_PLUGIN, "built against ryushi 0.0.1, this is ryushi");
  check_with(RYUSHI_NAME_CLASH_PLUGIN, "registers method 'wcsph', a name already registered");
  // In process: after the clash none of the library's names stays registered.
  CHECK_THROWS_WITH_AS(load_plugins({RYUSHI_NAME_CLASH_PLUGIN}), doctest::Contains("method 'wcsph'"),
                       SceneError);
  CHECK(find_system_keys("clash_nothing") == nullptr);
  CHECK(find_method_spec("wcsph")->doc.find("a second") == std::string::npos);
  // From a scene: the place of the entry in [plugins] libraries, the path relative to the scene.
  test::write_text(dir / "scene.toml", test::read_text(scene) + "\n[plugins]\nlibraries = [\"gone.so\"]\n");
  auto r = ryushi_cli("check " + (dir / "scene.toml").string());
  CHECK(r.code == 2);
  CHECK_MESSAGE(r.output.find((dir / "scene.toml").string() + ":") != std::string::npos, r.output);
  CHECK_MESSAGE(
      r.output.find(": plugin " + (dir / "gone.so").string() + ": no such file") != std::string::npos,
      r.output);
}

TEST_CASE("plugins: a plugin's method and system register as built-in ones, keys and docs included") {
  const auto dir = test::unique_scratch("plugin_method");
  fs::create_directories(dir);
  // Without the plugin the method is unknown; with it, in --plugin or in [plugins], it loads.
  test::write_text(dir / "throw.toml", ballistic_scene("drag = 2.0\n"));
  CHECK(
      ryushi_cli("check " + (dir / "throw.toml").string()).output.find("'name' in [method] is 'ballistic'") !=
      std::string::npos);
  auto ok = ryushi_cli("check " + (dir / "throw.toml").string() + " --plugin " RYUSHI_EXAMPLE_PLUGIN);
  CHECK_MESSAGE(ok.code == 0, ok.output);
  test::write_text(dir / "with_section.toml", ballistic_scene("drag = 2.0\n") +
                                                  "[plugins]\nlibraries = [\"" RYUSHI_EXAMPLE_PLUGIN "\"]\n");
  CHECK(ryushi_cli("check " + (dir / "with_section.toml").string()).code == 0);
  // Its key is validated like a built-in method's: range, and ownership under another method.
  auto negative = ryushi_cli("check " + (dir / "throw.toml").string() + " --plugin " RYUSHI_EXAMPLE_PLUGIN +
                             " --set method.drag=-1.0");
  CHECK(negative.code == 2);
  CHECK_MESSAGE(negative.output.find("--set method.drag=-1.0: 'drag' in [method] is -1; it must be > 0") !=
                    std::string::npos,
                negative.output);
  auto foreign = ryushi_cli("check " + test::scene_path("dam_break_2d.toml") +
                            " --plugin " RYUSHI_EXAMPLE_PLUGIN + " --set method.drag=1.0");
  CHECK(foreign.code == 2);
  CHECK_MESSAGE(
      foreign.output.find("[method] drag is for method ballistic, not for wcsph") != std::string::npos,
      foreign.output);
  // `keys --plugin` documents both.
  auto keys = ryushi_cli("keys --markdown --plugin " RYUSHI_EXAMPLE_PLUGIN);
  CHECK(keys.output.find("### `name = \"ballistic\"`") != std::string::npos);
  CHECK(keys.output.find("### `passive_scalar_diffusion`") != std::string::npos);
  CHECK(ryushi_cli("keys --markdown").output.find("ballistic") == std::string::npos);

  // The run: every particle follows v(t) = v_inf + (v0 - v_inf) e^(-k t), v_inf = g / k.
  auto run = ryushi_cli("run " + (dir / "throw.toml").string() + " --quiet --plugin " RYUSHI_EXAMPLE_PLUGIN +
                        " --out " + (dir / "out").string());
  REQUIRE_MESSAGE(run.code == 0, run.output);
  const auto v = test::read_dataset(test::last_frame(dir / "out"), "velocity").values;  // N x 3
  const double k = 2.0, t = 0.5, decay = std::exp(-k * t), g = -9.81;
  const double vx = 3.0 * decay, vy = g / k + (1.0 - g / k) * decay;
  double worst = 0;
  for (std::size_t i = 0; i < v.size() / 3; ++i)
    worst = std::max({worst, std::abs(v[3 * i] - vx), std::abs(v[3 * i + 1] - vy)});
  MESSAGE("largest velocity error ", worst, " m/s against (", vx, ", ", vy, ")");
  CHECK(v.size() == 3 * 16);
  CHECK(worst < 1e-12);  // the exact step: 50 of them, round-off only
}
