#include "scene/load_elastic.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace ryushi {

namespace {

std::vector<double> numbers(const toml::node& n) {
  std::vector<double> v;
  for (auto& e : *n.as_array()) v.push_back(*e.value<double>());
  return v;
}

}  // namespace

void load_elastic(toml::table& root, const Validator& val, Scene& sc) {
  auto* arr = root["elastic"].as_array();
  if (!arr) return;
  const int D = sc.dimension;
  const double d = sc.spacing;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    auto t = root["elastic"][i];
    const std::string label = "[[elastic]] #" + std::to_string(i),
                      prefix = "elastic." + std::to_string(i) + ".";
    auto fail = [&](const char* key, const std::string& msg) {
      val.fail(t[key].node() ? t[key].node() : &(*arr)[i], prefix + key, label + " " + msg);
    };
    ElasticSpec e;
    e.name = t["name"].value_or(label);
    e.min = numbers(*t["min"].node());
    e.max = numbers(*t["max"].node());
    for (int a = 0; a < D; ++a) {
      const double cells = (e.max[a] - e.min[a]) / d;
      if (cells < 1 - 1e-9) fail("max", "is thinner than one particle spacing on axis " + std::to_string(a));
      if (std::abs(cells - std::round(cells)) > 1e-6)
        fail("max", "is " + std::to_string(cells) + " spacings wide on axis " + std::to_string(a) +
                        ": a body takes whole spacings (particles at min + (k + 1/2) d)");
      if (e.min[a] < sc.domain_min[a] || e.max[a] > sc.domain_max[a])
        fail("min", "lies (partly) outside the domain");
    }
    e.density = *t["density"].value<double>();
    const bool kg = t["bulk_modulus"] || t["shear_modulus"], enu = t["youngs_modulus"] || t["poisson_ratio"];
    if (kg && enu)
      fail("youngs_modulus", "has both bulk/shear moduli and youngs_modulus/poisson_ratio; give one pair");
    if (kg) {
      if (!t["bulk_modulus"] || !t["shear_modulus"])
        fail(t["bulk_modulus"] ? "bulk_modulus" : "shear_modulus",
             "needs both bulk_modulus and shear_modulus");
      e.bulk_modulus = *t["bulk_modulus"].value<double>();
      e.shear_modulus = *t["shear_modulus"].value<double>();
    } else if (enu) {
      if (!t["youngs_modulus"] || !t["poisson_ratio"])
        fail(t["youngs_modulus"] ? "youngs_modulus" : "poisson_ratio",
             "needs both youngs_modulus and poisson_ratio");
      const double E = *t["youngs_modulus"].value<double>(), nu = *t["poisson_ratio"].value<double>();
      if (!(nu > -1 && nu < 0.5)) {
        std::ostringstream m;
        m << "poisson_ratio is " << nu
          << "; it must be in (-1, 0.5) (0.5: incompressible, no finite bulk modulus)";
        fail("poisson_ratio", m.str());
      }
      e.bulk_modulus = E / (3 * (1 - 2 * nu));
      e.shear_modulus = E / (2 * (1 + nu));
    } else {
      fail("density",
           "needs its stiffness: bulk_modulus and shear_modulus, or youngs_modulus and poisson_ratio");
    }
    if (t["clamp_min"] || t["clamp_max"]) {
      if (!t["clamp_min"] || !t["clamp_max"])
        fail(t["clamp_min"] ? "clamp_min" : "clamp_max", "needs both clamp_min and clamp_max");
      e.clamp_min = numbers(*t["clamp_min"].node());
      e.clamp_max = numbers(*t["clamp_max"].node());
      // The clamp must hold some of the body's particles (min + (k + 1/2) d), and not all.
      long held = 1, all = 1;
      for (int a = 0; a < D; ++a) {
        const long cells = std::lround((e.max[a] - e.min[a]) / d);
        long in = 0;
        for (long k = 0; k < cells; ++k) {
          const double q = e.min[a] + (k + 0.5) * d;
          if (q >= e.clamp_min[a] && q <= e.clamp_max[a]) ++in;
        }
        held *= in, all *= cells;
      }
      if (held == 0)
        fail("clamp_min", "clamps none of the body's particles (they sit at min + (k + 1/2) spacing): the clamp box "
                          "must hold at least one of them");
      if (held == all)
        fail("clamp_min", "clamps every particle of the body, which could never move: a fixed obstacle is a [[solid]]");
    }
    if (auto* v = t["velocity"].node()) {
      e.initial.velocity.assign(D, 0.0);
      e.initial.velocity_expression.assign(D, "");
      for (int a = 0; a < D; ++a) {
        const toml::node& c = *v->as_array()->get(a);
        if (c.is_string())
          e.initial.velocity_expression[a] = *c.value<std::string>();
        else
          e.initial.velocity[a] = *c.value<double>();
      }
      e.initial.velocity_where = val.location(v, prefix + "velocity");
    }
    // A fixed step the elastic waves outrun is unstable from the first steps (substeps: the
    // solid takes at most solid_substeps of them in one step).
    const long long substeps = sc.method_params.integer("solid_substeps");  // [[elastic]] is wcsph's
    const double limit = static_cast<double>(substeps) * sc.smoothing_length() / e.sound_speed();
    if (sc.fixed_dt > limit) {
      std::ostringstream m;
      m << "[time] dt = " << sc.fixed_dt << " s exceeds " << label << "'s elastic wave step "
        << (substeps > 1 ? "[method] solid_substeps x " : "") << "h / c_s = " << limit
        << " s (c_s = sqrt((K + 4G/3) / rho0) = " << e.sound_speed() << " m/s)";
      val.fail(root["time"]["dt"].node(), "time.dt", m.str());
    }
    sc.elastic.push_back(std::move(e));
  }
  // Under gravity a free body needs something to rest on: fluid, a wall, a solid or a clamped
  // body; otherwise it falls until it leaves the domain (a numerical failure, minutes later).
  const bool g = std::any_of(sc.gravity.begin(), sc.gravity.end(), [](double c) { return c != 0; });
  const bool support = !sc.fluid.empty() || !sc.imports.empty() || !sc.walls.empty() || !sc.solids.empty() ||
                       !sc.meshes.empty() ||
                       std::any_of(sc.elastic.begin(), sc.elastic.end(), [](const ElasticSpec& e) { return e.clamped(); });
  for (std::size_t i = 0; i < sc.elastic.size() && g && !support; ++i)
    if (!sc.elastic[i].clamped())
      val.fail(root["elastic"][i]["min"].node(), "elastic." + std::to_string(i) + ".min",
               "[[elastic]] #" + std::to_string(i) +
                   " is free (no clamp_min/clamp_max) under gravity with nothing to rest on (no fluid, [[wall]], "
                   "[[solid]], mesh or clamped body): clamp it, add a wall, or set [physics] gravity = 0");
}

}  // namespace ryushi
