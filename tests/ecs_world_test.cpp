#include <doctest/doctest.h>

#include "app/plugins.hpp"
#include "ecs/world.hpp"
#include "methods/method.hpp"
#include "ecs/scheduler.hpp"
#include "test_util.hpp"

using namespace ryushi;

TEST_CASE("world: columns exist only once asked for, and are typed") {
  World<2> w;
  CHECK(w.has("id"));
  CHECK(w.has("kind"));
  CHECK_FALSE(w.has("temperature"));
  w.append(3, kFluid);
  auto& t = w.ensure(Component<Scalar>{"temperature"});
  CHECK(t.size() == 3);
  CHECK(t[2] == 0.0);
  CHECK(w.has("temperature"));
  CHECK_THROWS_AS(w.column(Component<Vector>{"temperature"}), std::logic_error);
  CHECK_THROWS_AS(w.column(Component<Scalar>{"salinity"}), std::logic_error);
  auto& v = w.ensure(components::velocity);
  CHECK(v.size() == 3);
  CHECK(w.bytes_per_particle() == 4 + 4 + 8 + 16);
}

TEST_CASE("world: permute and erase keep every column aligned and ids stable") {
  World<2> w;
  auto& x = w.ensure(components::position);
  (void)x;
  w.append(5, kFluid);
  auto& pos = w.column(components::position);
  auto& p = w.ensure(components::pressure);
  for (int i = 0; i < 5; ++i) {
    pos[i] = Vec<2>(i, 10 * i);
    p[i] = 100.0 * i;
  }
  CommandBuffer<2> cb;
  cb.permute({4, 3, 2, 1, 0});
  cb.erase({0, 2});  // indices after the permutation: ids 4 and 2
  CHECK(w.size() == 5);  // deferred: nothing changes until applied
  cb.apply(w);
  REQUIRE(w.size() == 3);
  auto& ids = w.column(components::id);
  CHECK(ids[0] == 3);
  CHECK(ids[1] == 1);
  CHECK(ids[2] == 0);
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(w.column(components::position)[k][0] == doctest::Approx(ids[k]));
    CHECK(w.column(components::pressure)[k] == doctest::Approx(100.0 * ids[k]));
  }
  // New particles get fresh ids, never reused.
  std::size_t first = w.append(2, kWall);
  CHECK(w.column(components::id)[first] == 5);
  CHECK(w.column(components::kind)[first + 1] == kWall);
}

namespace {
template <int D>
std::vector<std::string> columns_of(const std::string& scene_text) {
  auto path = test::scratch("columns") / "scene.toml";
  test::write_text(path, scene_text);
  Scene s = load_scene(path.string());
  World<D> world;
  Resources res;
  Profiler prof;
  auto method = build_method<D>(s, world);
  Scheduler<D> sched(std::move(method.pipeline), world, res, prof);
  sched.initialise();
  return world.column_names();
}
const std::string kSceneBase = test::block_scene("[0.2, 0.2]", "[0.6, 0.6]", 0.1);
bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}
}  // namespace

TEST_CASE("world: a scene pays only for what it models") {
  auto plain = columns_of<2>(kSceneBase);
  CHECK_FALSE(contains(plain, "viscosity"));      // no viscous material
  CHECK_FALSE(contains(plain, "wall_velocity"));  // no walls, no viscosity
  CHECK_FALSE(contains(plain, "scalar"));         // no passive scalar system
  CHECK(contains(plain, "density"));

  auto viscous = columns_of<2>(kSceneBase + "[material]\nviscosity = 1e-3\n");
  CHECK(contains(viscous, "viscosity"));
  CHECK_FALSE(contains(viscous, "scalar"));

  load_plugins({RYUSHI_EXAMPLE_PLUGIN});  // the example's passive_scalar_diffusion (docs/extending.md)
  auto scalar = columns_of<2>(kSceneBase +
                              "[[systems]]\nname = \"passive_scalar_diffusion\"\ndiffusivity = 1e-3\n");
  CHECK(contains(scalar, "scalar"));
  CHECK_FALSE(contains(scalar, "viscosity"));

  auto no_delta = columns_of<2>(kSceneBase + "[method]\ndelta = 0.0\n");
  CHECK_FALSE(contains(no_delta, "density_gradient"));

  // Each method allocates its own columns only.
  CHECK_FALSE(contains(plain, "number_density"));
  CHECK_FALSE(contains(plain, "pressure_role"));
  auto mps = columns_of<2>(kSceneBase + "[method]\nname = \"mps\"\n");
  CHECK(contains(mps, "number_density"));
  CHECK(contains(mps, "pressure_gradient"));
  CHECK_FALSE(contains(mps, "density_rate"));
  CHECK_FALSE(contains(mps, "position_start"));
  CHECK_FALSE(contains(mps, "density_gradient"));
}
