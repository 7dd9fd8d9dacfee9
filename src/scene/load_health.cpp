// [health] and the check-time refusal of a kernel support too small for the lattice
// (load_parts.hpp).
#include <cmath>
#include <sstream>

#include "kernels/lattice_kernel_sum.hpp"
#include "scene/load_parts.hpp"
#include "scene/registered_keys.hpp"
#include "scene/scene.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

template <int D>
double gradient_moment(KernelType type, double ratio) {
  return lattice_gradient_moment<D>(Kernel<D>(type, ratio), 1.0);
}

}  // namespace

void check_kernel_support(const toml::table& root, Validator& val, const Scene& sc) {
  // The weights of mps and spiky (the shallow water's) are not SPH gradients; their methods set
  // their own radii.
  const KernelType type = kernel_from_name(sc.kernel);
  if (type == KernelType::Mps || type == KernelType::Spiky) return;
  auto moment = [&](double ratio) {
    return sc.dimension == 2 ? gradient_moment<2>(type, ratio) : gradient_moment<3>(type, ratio);
  };
  // The discrete gradient of a linear field on the scene's own lattice: off by more than 10%,
  // the operators no longer approximate anything (at smoothing_ratio 0.5 with wendland_c2 no
  // neighbour lies inside the support: the dam break's column stood as a rigid block).
  const double m = moment(sc.smoothing_ratio);
  if (std::abs(m - 1) <= 0.1) return;
  double enough = sc.smoothing_ratio;
  while (std::abs(moment(enough) - 1) > 0.1 && enough < 4) enough += 0.05;
  std::ostringstream msg;
  msg.precision(3);
  msg << "smoothing_ratio " << sc.smoothing_ratio << " with kernel " << sc.kernel << ": the support reaches "
      << sc.smoothing_ratio * Kernel<2>(type, 1.0).support_factor()
      << " spacings and the lattice's gradient of a linear field is off by " << 100 * std::abs(m - 1)
      << "% (more than 10%); use at least " << enough;
  const toml::node* at = root["particles"]["smoothing_ratio"].node();
  val.fail(at ? at : root["particles"]["kernel"].node(), "particles.smoothing_ratio", msg.str());
}

void load_health(const toml::table& root, Scene& sc) {
  const MethodHooks& hooks = find_method_spec(sc.method)->hooks;
  auto& h = sc.health;
  h.warn = root["health"]["action"].value_or(std::string("stop")) == "warn";
  h.density_deviation = root["health"]["density_deviation"].value_or(
      hooks.health_density_deviation ? hooks.health_density_deviation(sc) : 0.0);
  if (h.density_deviation > 0) h.sound_speed = sc.resolved_sound_speed();
  h.energy_rise = root["health"]["energy_rise"].value_or(0.05);
  h.pressure_factor = root["health"]["pressure_factor"].value_or(0.0);
  h.wall_penetration = root["health"]["wall_penetration"].value_or(true);
  if (!hooks.health_fluid_checks) h.energy_rise = h.pressure_factor = 0, h.wall_penetration = false;
}

}  // namespace ryushi
