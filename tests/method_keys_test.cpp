// Methods own their [method] keys (scene/registered_keys.hpp): a key of one method in a scene of
// another is bad input at the key, naming the method that owns it; [method.<name>] tables carry
// another method's settings and are checked against that method's keys.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <string>

#include "scene/registered_keys.hpp"
#include "scene/scene.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

// A shipped scene of each method, with its [method] name line (the line a key is added after).
const std::map<std::string, std::string> kSceneOf = {{"wcsph", "dam_break_2d.toml"},
                                                     {"mps", "dam_break_mps_2d.toml"},
                                                     {"isph", "dam_break_isph_2d.toml"},
                                                     {"swe", "dam_break_ritter_swe.toml"}};

// The scene of `method` with `line` added right after its [method] name; `at` gets the added
// line's number.
std::string with_line(const std::string& method, const std::string& line, int& at,
                      const std::string& scene = "") {
  std::string text = test::read_text(test::scene_path(scene.empty() ? kSceneOf.at(method) : scene));
  const std::string name = "name = \"" + method + "\"";
  const auto pos = text.find(name);
  REQUIRE(pos != std::string::npos);
  const auto end = text.find('\n', pos);
  at = 2 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
  return text.insert(end + 1, line + "\n");
}

// A value of the key's type (the check of ownership comes before the value's).
std::string value_of(const KeySpec& k) {
  if (!k.default_value.empty() && k.default_value.front() != '(') return k.default_value;
  if (!k.choices.empty()) return "\"" + k.choices.front() + "\"";
  return "1";
}

}  // namespace

TEST_CASE("method keys: the issue's two cases are bad input at the key, naming the owner") {
  auto mps =
      test::run_command(std::string(RYUSHI_BINARY) + " check " + test::scene_path("dam_break_mps_2d.toml") +
                        " --set method.ppe_laplacian='\"sph2\"'");
  CHECK(mps.code == 2);
  CHECK_MESSAGE(
      mps.output.find("--set method.ppe_laplacian=\"sph2\": [method] ppe_laplacian is for method isph, "
                      "not for mps") != std::string::npos,
      mps.output);
  CHECK_MESSAGE(mps.output.find("mps's keys: surface_threshold") != std::string::npos, mps.output);
  int at = 0;
  const auto text = with_line("wcsph", "compression_relaxation = 0.5", at);
  const std::string error = test::scene_error(text);
  CHECK_MESSAGE(error.rfind("bad.toml:" + std::to_string(at) +
                                ":1: [method] compression_relaxation is for method "
                                "isph, not for wcsph",
                            0) == 0,
                error);
}

// Every key every method declares, set in a scene of every other method that does not declare it.
TEST_CASE("method keys: each method's keys under the other methods are bad input at the key") {
  int cases = 0;
  for (auto& owner : method_spec_names())
    for (auto& key : find_method_spec(owner)->keys)
      for (auto& [method, scene] : kSceneOf) {
        if (find_key(find_method_spec(method)->keys, key.key)) continue;  // a key both declare
        CAPTURE(owner);
        CAPTURE(key.key);
        CAPTURE(method);
        int at = 0;
        const std::string error = test::scene_error(with_line(method, key.key + " = " + value_of(key), at));
        CHECK(error.rfind("bad.toml:" + std::to_string(at) + ":1: [method] " + key.key + " is for method ",
                          0) == 0);
        CHECK(error.find(owner) != std::string::npos);
        CHECK(error.find("not for " + method) != std::string::npos);
        ++cases;
      }
  // wcsph 13 keys, mps 10, isph 13 (hydrostatic_init and wall_slip shared), under the 3 or 4
  // methods that lack each: the loop ran over every pair.
  CHECK(cases >= 80);
}

TEST_CASE("method keys: [method.<name>] holds another method's settings, checked against its keys") {
  int at = 0;
  // Read under isph only: the tank loads under wcsph, and switching to isph takes them.
  const auto text = with_line("wcsph", "isph = { wall_rows = \"shepard\", ppe_laplacian = \"standard\" }", at,
                              "sloshing_2d.toml");
  auto path = test::unique_scratch("method_tables") / "tank.toml";
  test::write_text(path, text);
  CHECK(load_scene(path.string()).method_params.number("delta") == 0.1);  // wcsph's default
  const Scene isph = load_scene(
      path.string(), {"method.name=isph", "particles.kernel=cubic_spline", "particles.smoothing_ratio=1.2"});
  CHECK(isph.method_params.text("wall_rows") == "shepard");
  CHECK(isph.method_params.given("wall_rows"));
  CHECK(isph.method_params.text("pressure_gradient") == "corrected");  // a default
  CHECK_FALSE(isph.method_params.given("pressure_gradient"));
  // --set reaches into the table; a typo there is caught against isph's keys.
  CHECK(load_scene(path.string(), {"method.isph.wall_rows=adami"}).method == "wcsph");
  CHECK(test::scene_error(text, {"method.isph.wall_row=adami"})
            .find("--set method.isph.wall_row=adami: unknown key 'wall_row' in [method.isph]; did you mean "
                  "'wall_rows'?") != std::string::npos);
  CHECK(test::scene_error(with_line("wcsph", "isph = { delta = 0.1 }", at))
            .rfind("bad.toml:" + std::to_string(at) +
                       ":10: [method.isph] delta is for method wcsph, not for isph",
                   0) == 0);
  CHECK(test::scene_error(with_line("wcsph", "dfsph = { max_error = 0.1 }", at))
            .find("[method.dfsph]: no method is registered as 'dfsph'") != std::string::npos);
  // The same key twice for the scene's method.
  CHECK(test::scene_error(with_line("wcsph", "delta = 0.2\nwcsph = { delta = 0.3 }", at, "sloshing_2d.toml"))
            .find("'delta' is set both in [method] and in [method.wcsph]") != std::string::npos);
}

TEST_CASE("method keys: a section or key another method owns is bad input there") {
  int at = 0;
  CHECK(test::scene_error(with_line("wcsph", "", at) + "\n[splitting]\nenabled = false\n")
            .find("[splitting] is for [method] name = \"swe\"") != std::string::npos);
  CHECK(test::scene_error(with_line("mps", "", at), {"time.step_rule=seed001"})
            .find("--set time.step_rule=seed001: [time] step_rule is for method wcsph") != std::string::npos);
  CHECK(test::scene_error(with_line("mps", "", at) +
                          "\n[[fixed_pressure]]\nmin = [0.0, 0.0]\nmax = [0.1, 0.1]\n"
                          "pressure = 0.0\n")
            .find("[[fixed_pressure]] #0 is for method isph") != std::string::npos);
}

TEST_CASE(
    "method keys: a key or value of [[section]] entries another method owns is bad input at the entry's "
    "key") {
  int at = 0;
  // [[fluid]] depth (a shallow-water depth) in a WCSPH scene: at the key of the entry that has it.
  const std::string fluid_depth = test::scene_error(with_line("wcsph", "", at), {"fluid.0.depth=0.3"});
  INFO(fluid_depth);
  CHECK(fluid_depth.find("--set fluid.0.depth=0.3: [[fluid]] #0 depth is for method swe") !=
        std::string::npos);
  // A probe type only the shallow water samples, under MPS: at the probe's type, naming the owner.
  const std::string text =
      with_line("mps", "", at) + "\n[[probe]]\nname = \"front\"\ntype = \"front_depth\"\n";
  const std::string probe = test::scene_error(text);
  INFO(probe);
  const int line = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  CHECK(probe.find("bad.toml:" + std::to_string(line) + ":") == 0);
  CHECK(probe.find("of type front_depth is for method swe") != std::string::npos);
  // And what the shallow water refuses: a particle method's [[import]] and [[fluid]] pressure.
  const std::string import = test::scene_error(with_line("swe", "", at) + "\n[[import]]\nfile = \"x.h5\"\n");
  INFO(import);
  CHECK(import.find("[[import]] #0 is for the particle methods, not swe") != std::string::npos);
  const std::string pressure = test::scene_error(with_line("swe", "", at), {"fluid.0.pressure=0.0"});
  INFO(pressure);
  CHECK(pressure.find("--set fluid.0.pressure=0.0: [[fluid]] #0: pressure is for the particle methods") !=
        std::string::npos);
}

TEST_CASE("method keys: a key a method removed is bad input at the key, naming what replaced it") {
  // A method registered for this test only, as the One ISPH issue will retire ISPH keys.
  MethodSpec spec;
  spec.doc = "a method with a removed key";
  spec.keys = {{"pressure_gradient", KeyType::String, "", "\"corrected\"", "The gradient."}};
  spec.retired = {{"violent_flow", "use pressure_gradient = \"corrected\" (one set-up for every flow)"}};
  REQUIRE(register_method_spec("retiring_example", spec));
  int at = 0;
  std::string text = with_line("wcsph", "", at, "conduction_2d.toml");  // [method] holds only its name
  text.replace(text.find("name = \"wcsph\""), 14, "name = \"retiring_example\"\nviolent_flow = true");
  const std::string error = test::scene_error(text);
  unregister_method_spec("retiring_example");
  INFO(error);
  CHECK(error.find("bad.toml:" + std::to_string(at) +
                   ":1: [method] violent_flow was removed from method "
                   "retiring_example: use pressure_gradient = \"corrected\"") == 0);
}

// A name the program registers twice (two translation units, an in-tree extension) threw from a
// static initialiser, so every command aborted (exit 134); it is recorded instead, and main()
// prints it on one line with exit 1 before any command (issue 51, point 6).
TEST_CASE("method keys: a name registered twice is recorded, the first registration kept") {
  const std::string doc = find_method_spec("wcsph")->doc;
  MethodSpec spec;
  spec.doc = "an impostor";
  CHECK_FALSE(register_method_spec("wcsph", spec));
  CHECK(find_method_spec("wcsph")->doc == doc);
  const auto& clashes = built_in_registration_clashes();
  CHECK(std::find(clashes.begin(), clashes.end(), "method 'wcsph'") != clashes.end());
}
