// The worked example of docs/extending.md (examples/out_of_tree/passive_scalar_diffusion.cpp), a
// plugin's system added to a scene by name. Physics: a Gaussian bump of variance s0^2 per axis
// diffusing with kappa keeps its shape with s^2(t) = s0^2 + 2 kappa t; the total sum m_i phi_i is
// conserved exactly by the antisymmetric pair form. Run twice: with the example built in tree
// (ryushi_example_plugin), and built out of tree, as a user would, against a staged install of
// this build (cmake --install), loaded by the staged ryushi with --plugin.
#include <doctest/doctest.h>

#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

namespace {

struct Moments {
  double total, variance;
};

Moments moments(const fs::path& frame, double cx, double cy) {
  auto x = test::read_dataset(frame, "position").values;  // N x 3, z = 0 in 2D
  auto phi = test::read_dataset(frame, "scalar").values;
  auto m = test::read_dataset(frame, "mass").values;
  double total = 0, second = 0;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    double dx = x[3 * i] - cx, dy = x[3 * i + 1] - cy;
    total += m[i] * phi[i];
    second += m[i] * phi[i] * (dx * dx + dy * dy);
  }
  return {total, second / total / 2.0};  // per-axis variance
}

// The same registered system under two methods: it sees the method-neutral context (kernel,
// spacing, domain; MPS gives its weight function as the kernel). WCSPH fills a periodic box;
// MPS, whose pressure equation needs a free surface, holds a block at rest in open space
// (no gravity), the bump 6.7 widths from the block's edges.
void check_variance_law(const std::string& ryushi, const std::string& plugin, const std::string& label) {
  for (std::string method : {"wcsph", "mps"}) {
    CAPTURE(method);
    auto dir = test::scratch(label + "_" + method);
    auto scene = dir / "scalar.toml";
    const double kappa = 2e-3, s0 = 0.06, t_end = 0.5;
    const bool mps = method == "mps";
    test::write_text(scene, std::string(R"([scene]
dimension = 2
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
)") + (mps ? "" : "periodic = [true, true]\n") + R"([particles]
spacing = 0.02
[material]
sound_speed = 5.0
[method]
name = ")" + method + R"("
[physics]
gravity = [0.0, 0.0]
[time]
end = 0.5
[output]
interval = 0.25
fields = ["scalar", "mass"]
[[fluid]]
)" + (mps ? "min = [0.1, 0.1]\nmax = [0.9, 0.9]\n" : "min = [0.0, 0.0]\nmax = [1.0, 1.0]\n") + R"([[systems]]
name = "passive_scalar_diffusion"
diffusivity = 2e-3
centre = [0.5, 0.5]
width = 0.06
)");
    auto run = test::run_command(ryushi + " run " + scene.string() + " --quiet --plugin " + plugin + " --out " +
                                 (dir / "out").string());
    REQUIRE_MESSAGE(run.code == 0, run.output);
    auto start = moments(dir / "out" / "frames" / "frame_00000.h5", 0.5, 0.5);
    auto end = moments(dir / "out" / "frames" / "frame_00002.h5", 0.5, 0.5);
    CHECK(std::abs(start.variance / (s0 * s0) - 1) < 0.02);  // the lattice samples the bump
    double growth = end.variance - start.variance, exact = 2 * kappa * t_end;
    MESSAGE(method, ": variance growth ", growth, " vs 2 kappa t = ", exact);
    CHECK(std::abs(growth / exact - 1) < 0.05);  // relative: doctest's Approx adds 1 to its scale
    CHECK(std::abs(end.total - start.total) <= 1e-12 * start.total);
  }
}

}  // namespace

TEST_CASE("extension: passive scalar system spreads as 2 kappa t and conserves its total, under WCSPH and MPS") {
  check_variance_law(RYUSHI_BINARY, RYUSHI_EXAMPLE_PLUGIN, "extension");
}

// The issue's acceptance: the example project builds against a staged install (headers,
// libryushi.so, the CMake package) with its own CMakeLists.txt, and the staged ryushi loads it.
TEST_CASE("extension: the out-of-tree example builds against an installed ryushi and runs as a plugin") {
  const auto dir = test::unique_scratch("out_of_tree");
  const std::string stage = (dir / "stage").string(), build = (dir / "build").string();
  auto install = test::run_command("cmake --install " RYUSHI_BUILD_DIR " --prefix " + stage);
  REQUIRE_MESSAGE(install.code == 0, install.output);
  auto configure = test::run_command("cmake -S " RYUSHI_SOURCE_DIR "/examples/out_of_tree -B " + build +
                                     " -DCMAKE_PREFIX_PATH=" + stage);
  REQUIRE_MESSAGE(configure.code == 0, configure.output);
  auto compile = test::run_command("cmake --build " + build);
  REQUIRE_MESSAGE(compile.code == 0, compile.output);
  check_variance_law(stage + "/bin/ryushi", build + "/ryushi_example.so", "out_of_tree");
}
