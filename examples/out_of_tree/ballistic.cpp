// A small method registered from a plugin: "ballistic", particles that fly under gravity with a
// linear drag and feel nothing else (no pressure, no neighbours): dv/dt = g - k v. Each step
// integrates it exactly,
//   v(t + dt) = v_inf + (v - v_inf) e^(-k dt),  v_inf = g / k (the terminal velocity),
//   x(t + dt) = x + v_inf dt + (v - v_inf) (1 - e^(-k dt)) / k,
// so a run is exact to round-off at any step: the plugin's test checks that. Its own [method]
// key, drag, is validated by ryushi like a built-in method's; it needs a fixed [time] dt.
#include <cmath>

#include "ecs/io.hpp"
#include "methods/plugin.hpp"
#include "methods/scene_particles.hpp"
#include "scene/validator.hpp"

namespace ryushi::example {

template <int D>
class BallisticDrag final : public System<D> {
 public:
  BallisticDrag(const Vec<D>& gravity, double drag) : gravity_(gravity), drag_(drag) {}
  std::string name() const override { return "ballistic_drag"; }
  static constexpr auto io =
      Io{reads(components::kind, resources::dt), writes(components::position, components::velocity)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [kind, dt, x, v] = io.fetch(ctx);
    const Vec<D> terminal = gravity_ / drag_;
    const double decay = std::exp(-drag_ * dt), reach = (1 - decay) / drag_;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (kind[i] != kFluid) continue;
      const Vec<D> excess = v[i] - terminal;
      x[i] += terminal * dt + excess * reach;
      v[i] = terminal + excess * decay;
    }
  }

 private:
  Vec<D> gravity_;
  double drag_;
};

template <int D>
MethodSetup<D> build_ballistic(const Scene& s, World<D>& world, const PipelineOptions& options) {
  refuse_matrix_dump(s, options);
  const double drag = s.method_params.number("drag");
  append_scene_particles<D>(
      s, s.density, world,
      [&](double, double) {
        return std::pair{s.density, 0.0};
      },
      [](int) { return kWall; });
  MethodSetup<D> m;
  m.context = method_context<D>(s, Kernel<D>(kernel_from_name(s.kernel), s.smoothing_length()));
  m.pipeline.push_back(std::make_shared<BallisticDrag<D>>(m.context.gravity, drag));
  m.first_dt = s.fixed_dt;
  m.summary = "drag " + std::to_string(drag) + " 1/s";
  m.parameters = {{"drag", drag}};
  return m;
}

MethodSpec ballistic_spec() {
  MethodSpec spec;
  spec.doc = "particles under gravity and a linear drag, nothing else (the out-of-tree example plugin)";
  spec.keys = {keyspec::positive("drag", "1/s", "1.0", "k of the drag force per unit mass -k v.")};
  spec.hooks.validate = [](const Scene& sc, const toml::table& root, Validator& val) {
    if (sc.fixed_dt <= 0)
      val.fail(root["time"].node(), "time.dt",
               "method ballistic integrates with a fixed step: set [time] dt");
  };
  return spec;
}

RYUSHI_REGISTER_METHOD("ballistic", ballistic_spec(), build_ballistic);

}  // namespace ryushi::example
