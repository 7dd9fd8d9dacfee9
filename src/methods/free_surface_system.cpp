// Free-surface detection (systems/free_surface/) as a registered system, here with the registry
// (systems know no method layer); scenes add it with
//   [[systems]]
//   name = "free_surface_detection"
//   rule = "isph2"        # marrone | isph2 | mps
// and get the per-particle columns `free_surface` (1 on the surface) and `surface_normal`;
// with `moment_matrix = true` also the tensor `moment_matrix` (M_i, the inverse of L_i).
#include "ecs/io.hpp"
#include "methods/system_registry.hpp"
#include "systems/free_surface/free_surface_detection.hpp"
#include "systems/loops/for_each_particle.hpp"

namespace ryushi {

inline constexpr Component<Tensor> moment_matrix_component{"moment_matrix"};

template <int D>
class FreeSurfaceDetection final : public System<D> {
 public:
  FreeSurfaceDetection(const toml::table& params, const MethodContext<D>& context)
      : context_(context), rule_(free_surface_rule(*params["rule"].value<std::string>())) {
    p_.beta = *params["beta"].value<double>();
    write_moments_ = *params["moment_matrix"].value<bool>();
    if (rule_ == FreeSurfaceRule::Mps) n0_ = mps_reference<D>(context_.kernel, context_.spacing).n0;
  }
  std::string name() const override { return "free_surface_detection"; }
  auto io() const {
    return Io{reads(components::position, components::mass, components::density, components::kind,
                    neighbours_resource),
              writes(components::free_surface, components::surface_normal),
              optional(write_moments_, writes(moment_matrix_component))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, m, rho, kind, nl, flag, normal, moments] = io().fetch(ctx);
    particle_volumes(m, rho, volume_);
    ParticleView<D> view{x, volume_, nl, context_.kernel, context_.domain};
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      auto r = detect_free_surface(view, i, rule_, p_, n0_);
      flag[i] = r.surface;
      normal[i] = r.normal;
    });
    if (write_moments_)
      for_each_of_kind(kind, kFluid, [&](std::size_t i) { moments[i] = moment_matrix(view, i); });
  }

 private:
  MethodContext<D> context_;
  FreeSurfaceRule rule_;
  FreeSurfaceParameters p_;
  double n0_ = 0;
  bool write_moments_ = false;
  std::vector<double> volume_;
};

namespace {
KeySpec rule_key() {
  KeySpec k{"rule", KeyType::String, "", "\"isph2\"",
            "marrone (eigenvalue + scan region), isph2 (marrone + det(M) < 0.6) or mps (n < beta n0)."};
  k.choices = {"marrone", "isph2", "mps"};
  return k;
}
KeySpec beta_key() {
  KeySpec k{"beta", KeyType::Float, "", "0.85", "Threshold of the mps rule."};
  k.min = 0.0;
  k.max = 1.0;
  k.min_exclusive = true;
  return k;
}
KeySpec moments_key() {
  return {"moment_matrix", KeyType::Bool, "", "false",
          "Also write the moment matrix M_i (the inverse of the correction matrix L_i) as the tensor "
          "`moment_matrix`."};
}
}  // namespace

RYUSHI_REGISTER_SYSTEM(FreeSurfaceDetection, "free_surface_detection",
                       "Flags free-surface fluid particles (`free_surface` = 1) and writes their outward "
                       "unit normal (`surface_normal`).",
                       {rule_key(), beta_key(), moments_key()});

}  // namespace ryushi
