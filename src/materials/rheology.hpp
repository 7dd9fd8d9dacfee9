#pragma once
// Apparent viscosity mu(gamma_dot, T) of the fluid's rheology model (seed 001 eqs. 3-8 set the
// frame: the stress is eta(D) D with D = grad v + grad v^T; the models are the usual ones):
//   newtonian          mu
//   power_law          K gamma_dot^(n-1)
//   cross              mu_inf + (mu_0 - mu_inf) / (1 + (lambda gamma_dot)^n)
//   bingham            mu_p + tau_0 (1 - exp(-m gamma_dot)) / gamma_dot        (Papanastasiou 1987)
//   herschel_bulkley   K gamma_dot^(n-1) + tau_0 (1 - exp(-m gamma_dot)) / gamma_dot
// times the Arrhenius factor exp(E/R (1/T - 1/T_ref)) when an activation energy is given (the
// whole apparent viscosity, the yield stress with it), then capped at max_viscosity (a power law
// with n < 1 has no finite viscosity at rest). gamma_dot = sqrt(D:D / 2) (simple shear du/dy:
// gamma_dot = |du/dy|); seed 001 eq. 5 writes |trace D| / sqrt 2, which vanishes in any
// incompressible flow, so the second invariant is taken, as its reference [3] does.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ryushi {

inline constexpr double kGasConstant = 8.314462618;  // J/(mol K)

struct Rheology {
  enum class Model { Newtonian, PowerLaw, Cross, Bingham, HerschelBulkley };
  Model model = Model::Newtonian;
  double viscosity = 0;             // mu (newtonian), mu_p (bingham), mu_inf (cross); Pa s
  double consistency = 0;           // K, Pa s^n (power_law, herschel_bulkley)
  double power_index = 1;           // n (power_law, herschel_bulkley, cross)
  double yield_stress = 0;          // tau_0, Pa (bingham, herschel_bulkley)
  double regularisation = 0;        // m, s (bingham, herschel_bulkley)
  double zero_shear_viscosity = 0;  // mu_0, Pa s (cross)
  double time_constant = 0;         // lambda, s (cross)
  double activation_energy = 0;     // E, J/mol (0: no temperature dependence)
  double reference_temperature = std::numeric_limits<double>::quiet_NaN();  // T_ref, K
  double max_viscosity = std::numeric_limits<double>::infinity();           // Pa s

  bool temperature_dependent() const { return activation_energy != 0; }
  bool shear_dependent() const { return model != Model::Newtonian; }

  double arrhenius(double T) const {
    return temperature_dependent()
               ? std::exp(activation_energy / kGasConstant * (1.0 / T - 1.0 / reference_temperature))
               : 1.0;
  }
  // (1 - exp(-m g)) / g, m at g = 0 (its limit), without cancellation at small m g.
  double regularised_yield(double g) const {
    return g > 0 ? -std::expm1(-regularisation * g) / g : regularisation;
  }
  double power(double g) const {
    if (g > 0) return consistency * std::pow(g, power_index - 1.0);
    return power_index < 1 ? std::numeric_limits<double>::infinity() : power_index > 1 ? 0.0 : consistency;
  }
  double at_temperature_free(double g) const {
    switch (model) {
      case Model::Newtonian:
        return viscosity;
      case Model::PowerLaw:
        return power(g);
      case Model::Cross:
        return viscosity +
               (zero_shear_viscosity - viscosity) / (1.0 + std::pow(time_constant * g, power_index));
      case Model::Bingham:
        return viscosity + yield_stress * regularised_yield(g);
      case Model::HerschelBulkley:
        return power(g) + yield_stress * regularised_yield(g);
    }
    return viscosity;
  }
  // The apparent viscosity at shear rate g (1/s) and temperature T (K; ignored without E).
  double apparent(double g, double T) const {
    return std::min(max_viscosity, at_temperature_free(g) * arrhenius(T));
  }
};

inline const char* rheology_names_doc() {
  return "newtonian, power_law, cross, bingham, herschel_bulkley";
}

inline Rheology::Model rheology_model_from_name(const std::string& name) {
  if (name == "power_law") return Rheology::Model::PowerLaw;
  if (name == "cross") return Rheology::Model::Cross;
  if (name == "bingham") return Rheology::Model::Bingham;
  if (name == "herschel_bulkley") return Rheology::Model::HerschelBulkley;
  return Rheology::Model::Newtonian;
}

}  // namespace ryushi
