// Wall pressure sensors and the force on a body read one surface pressure (issue 57,
// src/systems/probes/wall_sensor.hpp, solid_surface_force.hpp): a plate holding back a resting
// tank, for every method, and a dam break pushing on an obstacle.
#include "systems/probes/wall_sensor.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

// Sensors 1 mm wide in front of each of the plate's 28 left-face particles (z = 0.0125 + k d).
std::string face_sensors() {
  std::string text;
  for (int k = 0; k < 28; ++k)
    text += "[[probe]]\nname = \"face_" + std::to_string(k) +
            "\"\ntype = \"wall_pressure\"\nposition = [0.5, " + std::to_string(0.0125 + 0.025 * k) +
            "]\nnormal = [-1.0, 0.0]\ndiameter = 0.001\n";
  return text;
}

// Water 0.5 m deep between the tank's left wall and a plate (a [[solid]] box standing on the
// floor at x = 0.5 m), H / d = 20, to t = 2 s; the plate's force and three sensors on its face:
// 0.25 m deep, on its foot beside the floor, and above the water.
std::string plate_tank(const std::string& method) {
  return R"([scene]
dimension = 2
[domain]
min = [-0.1, -0.1]
max = [0.8, 0.8]
[particles]
spacing = 0.025
[material]
density = 1000.0
viscosity = 1.0e-3
[method]
name = ")" +
         method +
         R"("
[method.wcsph]
artificial_viscosity = 1.0          # the resting tank's (scenes/hydrostatic_2d.toml)
artificial_viscosity_quadratic = 1.0
[time]
end = 2.0
[output]
interval = 1.0
probe_interval = 0.01
[[fluid]]
min = [0.0, 0.0]
max = [0.5, 0.5]
[[wall]]
min = [0.0, 0.0]
max = [0.7, 0.7]
[[solid]]
name = "plate"
shape = "box"
min = [0.5, 0.0]
max = [0.6, 0.7]
[[probe]]
name = "fx"
type = "force"
solid = "plate"
axis = 0
[[probe]]
name = "mid"
type = "wall_pressure"
position = [0.5, 0.25]
normal = [-1.0, 0.0]
diameter = 0.005
[[probe]]
name = "foot"
type = "wall_pressure"
position = [0.5, 0.01]
normal = [-1.0, 0.0]
diameter = 0.005
[[probe]]
name = "dry"
type = "wall_pressure"
position = [0.5, 0.6]
normal = [-1.0, 0.0]
diameter = 0.005
)" + face_sensors();
}

}  // namespace

// The hydrostatic thrust rho g H^2 / 2 = 1226.25 N/m. Measured (t = 1-2 s): WCSPH +0.65% (its
// pressure is 0.5% over rho g depth at rest, as its probes in the water), ISPH -0.01%, MPS -1.3% on
// the mean, single samples -15% .. +8% (its pressure noise; tests/mps_test.cpp). Before the force
// probe read the surface pressure (2026-11-29): WCSPH's pair reaction -2.5%, MPS's wall layer +2.1%.
TEST_CASE(
    "wall sensors: a plate holding a resting tank feels the hydrostatic thrust, and its sensors agree") {
  const double rho_g = 1000 * 9.81, H = 0.5, thrust = rho_g * H * H / 2;
  for (std::string method : {"wcsph", "isph", "mps"}) {
    CAPTURE(method);
    auto dir = test::unique_scratch("plate_" + method);
    test::write_text(dir / "plate.toml", plate_tank(method));
    RunOptions opt;
    opt.scene = (dir / "plate.toml").string();
    opt.out_dir = (dir / "out").string();
    opt.quiet = true;
    REQUIRE(run_scene(opt) == kExitDone);
    auto probes = test::read_csv(dir / "out" / "probes.csv");
    double force = 0, mid = 0, foot = 0, worst_sum = 0;
    int samples = 0;
    for (std::size_t k = 0; k < probes["time"].size(); ++k) {
      if (probes["time"][k] < 1.0) continue;
      force += probes["fx"][k], mid += probes["mid"][k], foot += probes["foot"][k], ++samples;
      // One field: the force's pressure is the sensors' in front of each face particle times its
      // share of the face (the top of the plate and its right face are dry).
      double sum = 0;
      for (int f = 0; f < 28; ++f) sum += probes["face_" + std::to_string(f)][k] * 0.025;
      worst_sum = std::max(worst_sum, std::abs(sum / probes["fx"][k] - 1));
      // Above the water line the sensor reads the air's 0, not the hydrostatic line continued.
      CHECK(probes["dry"][k] == 0.0);
      if (method != "mps")  // every sample: the issue's 1%
        CHECK_MESSAGE(std::abs(probes["fx"][k] / thrust - 1) < 0.01, "t = " << probes["time"][k]);
    }
    REQUIRE(samples >= 100);
    force /= samples, mid /= samples, foot /= samples;
    MESSAGE(method, ": force / thrust - 1 = ", force / thrust - 1, ", mid sensor ", mid / (rho_g * 0.25) - 1,
            ", foot ", foot / (rho_g * 0.49) - 1);
    CHECK(std::abs(force / thrust - 1) < (method == "mps" ? 0.03 : 0.01));
    // The sensors' sum against the force: the same numbers but for the wall shear, none in a fluid
    // at rest; MPS's water moves (0.07 m/s, its noise) and its viscous reaction adds 0.13%.
    // Measured: 1.7e-8 (WCSPH), 5.4e-10 (ISPH), 1.3e-3 (MPS).
    MESSAGE(method, ": largest |sum of the face sensors / force - 1| ", worst_sum);
    CHECK(worst_sum < (method == "mps" ? 5e-3 : 1e-6));
    // The mid-depth sensor and the foot's beside the floor read rho g depth (MPS: its noise and
    // its pressure's bias, -2.2% mid-depth and +3.0% at the foot).
    CHECK(std::abs(mid / (rho_g * 0.25) - 1) < (method == "mps" ? 0.03 : 0.01));
    CHECK(std::abs(foot / (rho_g * 0.49) - 1) < (method == "mps" ? 0.04 : 0.01));
  }
}

TEST_CASE("solid: a dam break pushes on an obstacle from when its front arrives") {
  auto dir = test::unique_scratch("dam_break_obstacle");
  auto r = test::run_command(std::string(RYUSHI_BINARY) + " run " +
                             test::scene_path("dam_break_obstacle_2d.toml") + " --quiet --out " +
                             dir.string() + " --set time.end=0.4");
  REQUIRE_MESSAGE(r.code == 0, r.output);
  auto csv = test::read_csv(dir / "probes.csv");
  const auto& t = csv["time"];
  const auto& front = csv["surge_front"];
  const auto& fx = csv["block_fx"];
  const double support = 2 * 1.5 * 0.0125, block = 0.5;
  std::size_t peak = 0, contact = t.size();
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (std::abs(fx[k]) > std::abs(fx[peak])) peak = k;
    if (contact == t.size() && fx[k] != 0) contact = k;
    // No fluid particle within the kernel support of the block: no force at all.
    if (front[k] < block - support) CHECK(fx[k] == 0.0);
  }
  REQUIRE(contact < t.size());
  CHECK(front[contact] >= block - support);  // the first push comes with the front at the block
  CHECK(fx[peak] > 0);                       // pushed downstream
  // The impact: within 0.03 s of the first contact the force reaches half its largest value of
  // the run. (Its samples swing by +-1 kN/m with WCSPH's acoustic noise, so which sample is the
  // largest is chance: 0.186 s with the pair reaction, 0.246 s with the surface pressure.)
  double impact = 0, mean = 0;
  int after = 0;
  for (std::size_t k = contact; k < t.size(); ++k) {
    if (t[k] <= t[contact] + 0.03) impact = std::max(impact, fx[k]);
    if (t[k] >= 0.18 && t[k] <= 0.4) mean += fx[k], ++after;
  }
  MESSAGE("first contact at t = ", t[contact], " s; largest force ", fx[peak], " N/m at t = ", t[peak],
          " s, within 0.03 s of the contact ", impact, ", mean over 0.18-0.4 s ", mean / after);
  CHECK(impact >= 0.5 * fx[peak]);
  CHECK(mean / after > 0);  // the water running over the block pushes it downstream
  // Water over and around the block, not through it: in no frame a fluid particle's centre past
  // the block's first wall layer (d/2 inside its faces; a centre grazing the upstream top corner
  // comes within 0.07 d of it with either integrator), every particle still there.
  const double d = 0.0125;
  int k = 0;
  for (;; ++k) {
    const auto frame = test::frame_path(dir, k);
    if (!std::filesystem::exists(frame)) break;
    auto kind = test::read_dataset(frame, "kind").values, x = test::read_dataset(frame, "position").values;
    std::size_t fluid = 0, inside = 0;
    for (std::size_t i = 0; i < kind.size(); ++i) {
      if (kind[i] != 0) continue;
      ++fluid;
      inside += x[3 * i] > 0.5 + d / 2 && x[3 * i] < 0.6 - d / 2 && x[3 * i + 1] < 0.1 - d / 2;
    }
    CAPTURE(k);
    CHECK(fluid == 20 * 40);
    CHECK(inside == 0);
  }
  REQUIRE_MESSAGE(k == 21, k << " frames checked");  // t = 0 to 0.4 s every 0.02 s: none skipped
}

// MPS's density column is its Poisson source density rho0 n* / n0, which is 0 for a lone
// particle with no neighbour (a splash): its volume m / rho was infinite and the sensor read
// inf / inf = NaN (a 3D dam break onto a column under MPS: 45 NaN samples of the force). Such a
// particle has no volume to weigh: the sensor reads what the other particles give.
TEST_CASE("wall sensor: a particle without density (MPS's lone splash) does not make the reading NaN") {
  const double d = 0.01, rho0 = 1000;
  World<2> world;
  auto add = [&](Vec<2> x, std::int32_t kind, double rho, double p) {
    const std::size_t k = world.append(1, kind);
    world.ensure(components::position)[k] = x;
    world.ensure(components::density)[k] = rho;
    world.ensure(components::mass)[k] = rho0 * d * d;
    world.ensure(components::pressure)[k] = p;
  };
  for (int i = -3; i < 4; ++i)
    for (int layer = 0; layer < 3; ++layer) add(Vec<2>((i + 0.5) * d, -(layer + 0.5) * d), kWall, rho0, 0);
  for (int i = -3; i < 4; ++i)
    for (int row = 0; row < 3; ++row) add(Vec<2>((i + 0.5) * d, (row + 0.5) * d), kFluid, rho0, 100.0);
  Domain<2> domain;
  domain.min = Vec<2>(-0.1, -0.1);
  domain.max = Vec<2>(0.1, 0.1);
  const Kernel<2> kernel = sensor_kernel<2>(d);
  const Vec<2> at(0, 0), felt = Vec<2>::Zero();
  const double dry_of_it = surface_pressure_at<2>(at, world, SensorCells<2>(world, domain, kernel.support()),
                                                  domain, kernel, rho0, felt);
  CHECK(dry_of_it == doctest::Approx(100.0));   // a uniform 100 Pa without gravity
  add(Vec<2>(0.002, 0.004), kFluid, 0.0, 0.0);  // the lone particle, inside the sensor's support
  const double with_it = surface_pressure_at<2>(at, world, SensorCells<2>(world, domain, kernel.support()),
                                                domain, kernel, rho0, felt);
  CHECK(std::isfinite(with_it));
  CHECK(with_it == doctest::Approx(100.0));
}
