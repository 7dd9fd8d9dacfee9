#include <doctest/doctest.h>

#include "app/exit_codes.hpp"
#include "app/plugins.hpp"
#include "app/run.hpp"
#include "scene/scene.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

const char* kValid = R"([scene]
dimension = 2
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[particles]
spacing = 0.05
[time]
end = 0.1
[[fluid]]
min = [0.0, 0.0]
max = [0.4, 0.4]
[[wall]]
min = [0.0, 0.0]
max = [0.5, 0.8]
)";

// Loads `text` (after replacing `from` with `to`) and returns the error message, or "" if it loaded.
std::string error_of(std::string text, const std::string& from = "", const std::string& to = "",
                     const std::vector<std::string>& sets = {}) {
  if (!from.empty()) {
    auto pos = text.find(from);
    REQUIRE(pos != std::string::npos);
    text.replace(pos, from.size(), to);
  }
  return test::scene_error(text, sets);
}

std::string valid_with_domain_min() {
  std::string t = kValid;
  return t.replace(t.find("min = [0.0, 0.0]\nmax = [1.0, 1.0]"), 33, "min = [-0.2, -0.2]\nmax = [1.0, 1.0]");
}

}  // namespace

TEST_CASE("scene: a valid file loads with documented defaults filled in") {
  auto path = test::scratch("scene_ok") / "ok.toml";
  test::write_text(path, valid_with_domain_min());
  Scene s = load_scene(path.string());
  CHECK(s.dimension == 2);
  CHECK(s.name == "ok");
  CHECK(s.smoothing_ratio == 1.5);
  CHECK(s.kernel == "wendland_c2");
  CHECK(s.cfl == 0.2);
  CHECK(s.method_params.number("delta") == 0.1);
  CHECK(s.gravity[1] == doctest::Approx(-9.81));
  CHECK(s.output_interval == doctest::Approx(0.1 / 20));
  CHECK(s.walls.at(0).layers == 3);
  CHECK(s.fluid.size() == 1);
  CHECK(s.resolved_sound_speed() == doctest::Approx(10 * std::sqrt(2 * 9.81 * 0.4)));
}

TEST_CASE("scene: unknown keys and sections name the place and the closest valid name") {
  std::string base = valid_with_domain_min();
  CHECK(error_of(base, "spacing = 0.05", "spacnig = 0.05") ==
        "bad.toml:7:1: unknown key 'spacnig' in [particles]; did you mean 'spacing'?");
  CHECK(error_of(base + "[meshod]\nname = \"wcsph\"\n") ==
        "bad.toml:16:2: unknown section 'meshod'; did you mean 'method'?");
  CHECK(error_of(base + "[method]\nname = \"wcspj\"\n") ==
        "bad.toml:17:8: 'name' in [method] is 'wcspj'; allowed: isph, mph, mps, swe, wcsph (did you mean "
        "'wcsph'?)");
  load_plugins({RYUSHI_EXAMPLE_PLUGIN});  // the example's passive_scalar_diffusion (docs/extending.md)
  CHECK(error_of(base + "[[systems]]\nname = \"pasive_scalar_diffusion\"\n") ==
        "bad.toml:17:8: no system registered as 'pasive_scalar_diffusion'; did you mean 'passive_scalar_diffusion'?");
  CHECK(error_of(base + "[[systems]]\nname = \"passive_scalar_diffusion\"\ndifusivity = 1.0\n") ==
        "bad.toml:18:1: unknown key 'difusivity' in [[systems]] #0 (passive_scalar_diffusion); did you mean 'diffusivity'?");
}

TEST_CASE("scene: wrong types, out-of-range and inconsistent values") {
  std::string base = valid_with_domain_min();
  CHECK(error_of(base, "spacing = 0.05", "spacing = \"fine\"") == "bad.toml:7:11: 'spacing' in [particles] must be number");
  CHECK(error_of(base, "spacing = 0.05", "spacing = 0.0") == "bad.toml:7:11: 'spacing' in [particles] is 0; it must be > 0");
  CHECK(error_of(base, "spacing = 0.05", "spacing = -1") == "bad.toml:7:11: 'spacing' in [particles] is -1; it must be > 0");
  CHECK(error_of(base, "dimension = 2", "dimension = 4") == "bad.toml:2:13: 'dimension' in [scene] is 4; it must be >= 2 and <= 3");
  CHECK(error_of(base, "end = 0.1", "end = nan") == "bad.toml:9:7: 'end' in [time] must be finite");
  CHECK(error_of(base, "max = [0.4, 0.4]", "max = [0.4]") == "bad.toml:12:7: 'max' in [[fluid]] #0 has 1 values; the scene is 2D");
  CHECK(error_of(base, "max = [0.4, 0.4]", "max = [1.4, 0.4]") == "bad.toml:11:7: [[fluid]] #0 lies (partly) outside the domain");
  CHECK(error_of(base, "max = [0.4, 0.4]", "max = [0.4, 0.01]") == "bad.toml:12:7: [[fluid]] #0 is empty: thinner than one particle spacing on axis 1");
  CHECK(error_of(base, "max = [0.4, 0.4]", "max = [0.4, -0.1]") == "bad.toml:12:7: [[fluid]] #0 is empty: thinner than one particle spacing on axis 1");
  CHECK(error_of(kValid) == "bad.toml:14:7: [[wall]] #0 with its 3 layers lies outside the domain");
  CHECK(error_of(base + "", "max = [0.5, 0.8]", "max = [0.5, 0.8]\nlayers = 2") ==
        "bad.toml:16:10: [[wall]] #0: 2 layers (0.1 m) do not cover the support radius 0.15 m; use layers >= 3");
  CHECK(error_of(base, "[time]", "[tiem]") == "bad.toml:8:2: unknown section 'tiem'; did you mean 'time'?");
  CHECK(error_of(base, "end = 0.1\n", "cfl = 0.3\n") == "bad.toml:8:1: [time] is missing required key 'end'");
  CHECK(error_of(base, "[time]\nend = 0.1\n", "") == "bad.toml: missing required section [time]");
  CHECK(error_of(base + "[output]\nfields = [1, 2]\n") == "bad.toml:17:10: 'fields' in [output] must be array of strings");
  CHECK(error_of(base, "spacing = 0.05", "spacing = 0.05 x") .find("bad.toml:7:16:") == 0);  // TOML syntax
  CHECK(error_of(base + "[shifting]\nmodel = \"density\"\n") ==
        "bad.toml:17:9: [shifting] model = \"density\" is ISPH's (its beta, eqs. 19-25); wcsph takes none, fickian, optimised or xsph");
  CHECK(error_of(base + "[method]\nname = \"mps\"\n[shifting]\nmodel = \"fickian\"\n") ==
        "bad.toml:19:9: method mps has no particle shifting; leave [shifting] out");
  CHECK(error_of(base + "[method]\ndissipation = \"riemann\"\nartificial_viscosity = 0.1\n") ==
        "bad.toml:18:24: artificial_viscosity is read by dissipation = \"artificial_viscosity\" only; "
        "\"riemann\" "
        "takes its dissipation from the pair's Riemann problem (its one parameter is riemann_limiter)");
}

TEST_CASE("scene: --set overrides scalar keys and reports its own errors") {
  auto path = test::scratch("scene_set") / "set.toml";
  test::write_text(path, valid_with_domain_min());
  Scene s = load_scene(path.string(), {"particles.spacing=0.025", "time.end=0.5", "method.name=wcsph",
                                       "fluid.0.max=[0.2, 0.2]", "material.viscosity=1e-3"});
  CHECK(s.spacing == 0.025);
  CHECK(s.end_time == 0.5);
  CHECK(s.fluid[0].max[0] == 0.2);
  CHECK(s.viscosity == 1e-3);
  std::string base = valid_with_domain_min();
  CHECK(error_of(base, "", "", {"particles.spacing=-2"}) == "--set particles.spacing=-2: 'spacing' in [particles] is -2; it must be > 0");
  CHECK(error_of(base, "", "", {"particles.spasing=1"}) ==
        "--set particles.spasing=1: unknown key 'spasing' in [particles]; did you mean 'spacing'?");
  CHECK(error_of(base, "", "", {"partcles.spacing=1"}) == "--set partcles.spacing=1: unknown section 'partcles'; did you mean 'particles'?");
  CHECK(error_of(base, "", "", {"fluid.3.max=[1, 1]"}) == "--set fluid.3.max=[1, 1]: the scene has no [[fluid]] entry 3");
  CHECK(error_of(base, "", "", {"spacing"}) == "--set spacing: expected section.key=value");
}

TEST_CASE("scene: unreadable files") {
  try {
    load_scene("/nonexistent/scene.toml");
    FAIL("loaded a missing file");
  } catch (const SceneError& e) {
    CHECK(std::string(e.what()) == "/nonexistent/scene.toml: cannot read the scene file (no such file)");
  }
}

TEST_CASE("run: bad input exits with code 2, says where, and creates no output directory") {
  auto dir = test::scratch("bad_run");
  auto scene = dir.string() + "_scene.toml";
  const std::string bin = RYUSHI_BINARY, out = (dir / "out").string();
  auto run = [&](const std::string& extra) { return test::run_command(bin + " run " + scene + " --out " + out + " --quiet" + extra); };
  test::write_text(scene, kValid);  // its wall's layers stick out of the domain (min 0)
  auto r = run("");
  CHECK(r.code == kExitBadInput);
  CHECK(r.output.find("_scene.toml:14:7: [[wall]] #0 with its 3 layers lies outside the domain") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out"));
  r = run(" --set particles.spacing=abc");
  CHECK(r.code == kExitBadInput);
  CHECK(r.output.find("--set particles.spacing=abc") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out"));
  test::write_text(scene, valid_with_domain_min());
  r = run(" --set 'output.fields=[\"temperature\"]'");
  CHECK(r.code == kExitBadInput);  // a field no system provides
  CHECK(r.output.find("no per-particle field 'temperature'") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out"));
}

// WCSPH's integrator: the leapfrog unless the scene names one; a scene with heat conduction or
// elastic bodies that names none takes the midpoint (the leapfrog does not move solids and halves
// the conduction step); other methods refuse the key.
TEST_CASE("scene: the integrator defaults to the leapfrog, to the midpoint with heat or elastic bodies") {
  auto path = test::scratch("scene_integrator") / "integrator.toml";
  test::write_text(path, valid_with_domain_min());
  CHECK(load_scene(path.string()).method_params.text("integrator") == "leapfrog");
  CHECK(load_scene(path.string(), {"method.integrator=midpoint"}).method_params.text("integrator") == "midpoint");
  CHECK(load_scene(path.string(), {"material.conductivity=0.6", "material.temperature=300.0"}).method_params.text("integrator") ==
        "midpoint");
  CHECK(load_scene(path.string(),
                   {"material.conductivity=0.6", "material.temperature=300.0", "method.integrator=leapfrog"})
            .method_params.text("integrator") == "leapfrog");
  auto elastic = test::scratch("scene_integrator") / "elastic.toml";
  test::write_text(elastic, test::read_text(test::scene_path("elastic_plate_2d.toml")));
  CHECK(load_scene(elastic.string()).method_params.text("integrator") == "midpoint");
  CHECK(error_of(valid_with_domain_min(), "", "", {"method.name=mps", "method.integrator=leapfrog"})
            .find("[method] integrator is for method wcsph") != std::string::npos);
}
