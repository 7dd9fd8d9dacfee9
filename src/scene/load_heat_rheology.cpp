#include "scene/load_heat_rheology.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "scene/registered_keys.hpp"

namespace ryushi {

namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Each model's own keys besides `viscosity`, so that a key the chosen model ignores is an error,
// not a surprise.
struct ModelKeys {
  const char* name;
  std::vector<std::string> required;
  bool uses_viscosity;
};
const std::vector<ModelKeys>& model_keys() {
  static const std::vector<ModelKeys> keys{
      {"newtonian", {}, true},
      {"power_law", {"consistency", "power_index"}, false},
      {"cross", {"zero_shear_viscosity", "time_constant", "power_index"}, true},
      {"bingham", {"yield_stress", "regularisation"}, true},
      {"herschel_bulkley", {"consistency", "power_index", "yield_stress", "regularisation"}, false}};
  return keys;
}

}  // namespace

void load_heat_and_rheology(toml::table& root, const Validator& val, Scene& sc) {
  auto material = [&](const char* key) { return root["material"][key]; };
  auto given = [&](const char* key) { return material(key).node() != nullptr; };
  auto fail = [&](const char* key, const std::string& msg) {
    val.fail(material(key).node(), std::string("material.") + key, msg);
  };
  // The methods that model a rheology and heat (their hooks say so; today wcsph).
  const bool wcsph = find_method_spec(sc.method)->hooks.multiphysics;
  std::string modelling;
  for (auto& name : method_spec_names())
    if (find_method_spec(name)->hooks.multiphysics) modelling += (modelling.empty() ? "" : ", ") + name;

  // Rheology.
  const std::string model = *material("rheology").value<std::string>();
  Rheology& r = sc.rheology;
  r.model = rheology_model_from_name(model);
  if (model != "newtonian" && !wcsph)
    fail("rheology", "[material] rheology = \"" + model + "\" is for method " + modelling);
  const ModelKeys* mine = &model_keys().front();
  for (auto& k : model_keys())
    if (model == k.name) mine = &k;
  auto uses = [&](const std::string& key) {
    return std::find(mine->required.begin(), mine->required.end(), key) != mine->required.end();
  };
  for (const char* key : {"consistency", "power_index", "yield_stress", "regularisation",
                          "zero_shear_viscosity", "time_constant"})
    if (given(key) && !uses(key))
      fail(key, std::string("'") + key + "' is not a parameter of rheology \"" + model + "\"");
  for (auto& key : mine->required)
    if (!given(key.c_str()))
      val.fail(root["material"].node(), "material." + key,
               "[material] rheology = \"" + model + "\" needs '" + key + "'");
  if (!mine->uses_viscosity && sc.viscosity != 0)
    fail("viscosity", "'viscosity' is not a parameter of rheology \"" + model +
                          "\" (its viscosity is consistency * shear rate^(power_index - 1))");
  r.viscosity = sc.viscosity;
  r.consistency = material("consistency").value_or(0.0);
  r.power_index = material("power_index").value_or(1.0);
  r.yield_stress = material("yield_stress").value_or(0.0);
  r.regularisation = material("regularisation").value_or(0.0);
  r.zero_shear_viscosity = material("zero_shear_viscosity").value_or(0.0);
  r.time_constant = material("time_constant").value_or(0.0);
  r.activation_energy = material("activation_energy").value_or(0.0);
  if (given("max_viscosity")) r.max_viscosity = *material("max_viscosity").value<double>();
  const bool unbounded_at_rest =
      (r.model == Rheology::Model::PowerLaw || r.model == Rheology::Model::HerschelBulkley) &&
      r.power_index < 1;
  if (unbounded_at_rest && !given("max_viscosity"))
    fail("power_index", "rheology \"" + model + "\" with power_index " + number(r.power_index) +
                            " < 1 has infinite viscosity at rest: set [material] max_viscosity (Pa s)");
  if (r.activation_energy != 0) {
    if (!wcsph)
      fail("activation_energy",
           "'activation_energy' (a temperature-dependent viscosity) is for method " + modelling);
    if (!given("reference_temperature"))
      fail("activation_energy",
           "'activation_energy' needs reference_temperature (K): the temperature at which the model's "
           "parameters hold");
    if (!given("max_viscosity"))
      fail("activation_energy",
           "'activation_energy' needs max_viscosity (Pa s): the Arrhenius factor grows without bound as the "
           "fluid cools");
    r.reference_temperature = *material("reference_temperature").value<double>();
  } else if (given("reference_temperature")) {
    fail("reference_temperature",
         "'reference_temperature' is for the Arrhenius factor: set activation_energy too");
  }

  // Heat.
  sc.conductivity = *material("conductivity").value<double>();
  sc.heat_capacity = *material("heat_capacity").value<double>();
  if (sc.conductivity > 0 && !wcsph)
    fail("conductivity", "heat conduction ([material] conductivity > 0) is for method " + modelling);
  if (given("temperature")) {
    if (!sc.models_heat())
      fail("temperature",
           "[material] temperature needs heat: conductivity > 0 or a temperature-dependent viscosity "
           "(activation_energy)");
    sc.temperature = *material("temperature").value<double>();
  }
  if (auto* arr = root["fluid"].as_array())
    for (std::size_t i = 0; i < arr->size(); ++i) {
      auto node = root["fluid"][i]["temperature"];
      const std::string path = "fluid." + std::to_string(i) + ".temperature";
      if (node) {
        if (!sc.models_heat())
          val.fail(node.node(), path,
                   "[[fluid]] #" + std::to_string(i) +
                       " temperature needs heat: [material] conductivity > 0 or activation_energy");
        sc.fluid[i].temperature = *node.value<double>();
      } else if (sc.models_heat() && std::isnan(sc.temperature)) {
        val.fail(&(*arr)[i], path,
                 "[[fluid]] #" + std::to_string(i) +
                     " needs a temperature (K): give it one or set [material] temperature");
      }
    }
  if (sc.models_heat() && !sc.imports.empty() && std::isnan(sc.temperature))
    val.fail(root["import"].node(), "material.temperature",
             "[[import]] particles start at [material] temperature: set it (K)");

  auto thermal = [&](const char* section, std::size_t i, ThermalCondition& c) {
    auto t = root[section][i]["temperature"], q = root[section][i]["heat_flux"];
    const std::string label = std::string("[[") + section + "]] #" + std::to_string(i);
    const std::string prefix = std::string(section) + "." + std::to_string(i) + ".";
    if (!t && !q) return;
    auto* node = t ? t.node() : q.node();
    const std::string path = prefix + (t ? "temperature" : "heat_flux");
    if (sc.conductivity <= 0)
      val.fail(node, path,
               label + " " + (t ? "temperature" : "heat_flux") +
                   " needs heat conduction: set [material] conductivity > 0");
    if (t && q)
      val.fail(q.node(), prefix + "heat_flux",
               label + " has both temperature (Dirichlet) and heat_flux (Neumann); give one");
    if (t) c.temperature = *t.value<double>();
    if (q) c.heat_flux = *q.value<double>();
  };
  for (std::size_t i = 0; i < sc.walls.size(); ++i) thermal("wall", i, sc.walls[i].thermal);
  for (std::size_t i = 0; i < sc.solids.size(); ++i) thermal("solid", i, sc.solids[i].thermal);

  // A fixed step must meet conduction's limit (an explicit diffusion beyond it blows up).
  if (sc.conductivity > 0 && sc.fixed_dt > 0) {
    const double h = sc.smoothing_length();
    const double limit = 0.125 * h * h * sc.density * sc.heat_capacity / sc.conductivity;
    if (sc.fixed_dt > limit)
      val.fail(root["time"]["dt"].node(), "time.dt",
               "[time] dt = " + number(sc.fixed_dt) +
                   " s exceeds heat conduction's stable step 0.125 h^2 rho0 c / k = " + number(limit) + " s");
  }
}

}  // namespace ryushi
