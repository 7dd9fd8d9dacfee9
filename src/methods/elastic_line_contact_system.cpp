// The soft-EHL line contact (systems/mph/elastic_line_contact.hpp) as a registered system; a
// scene adds it with
//   [[systems]]
//   name = "elastic_line_contact"
//   radius = 0.1
//   modulus = 1.95e7
//   load = 1000.0
//   gap = 6.0e-5
// It needs frozen wall particles with a face distance (MPH-I's walls).
#include <cmath>

#include "methods/system_registry.hpp"
#include "scene/scene.hpp"
#include "scene/validator.hpp"
#include "systems/mph/elastic_line_contact.hpp"

namespace ryushi {

namespace {

template <int D>
LineContactParameters line_contact_parameters(const toml::table& t, const MethodContext<D>& context) {
  LineContactParameters p;
  p.radius = *t["radius"].value<double>();
  p.modulus = *t["modulus"].value<double>();
  p.load = *t["load"].value<double>();
  p.gap = *t["gap"].value<double>();
  p.centre = t["centre"].value_or(0.5 * (context.domain.min[0] + context.domain.max[0]));
  p.plate = *t["plate"].value<double>();
  p.from = t["from"].value_or(context.domain.min[0]);
  p.to = t["to"].value_or(context.domain.max[0]);
  p.layers = static_cast<int>(*t["layers"].value<std::int64_t>());
  p.spacing = context.spacing;
  p.approach_rate = *t["approach_rate"].value<double>();
  p.lag = *t["lag"].value<double>();
  p.hertz_start = *t["start"].value<std::string>() == "hertz";
  p.recycle = *t["recycle"].value<bool>();
  return p;
}

template <int D>
class RegisteredLineContact final : public ElasticLineContact<D> {
 public:
  RegisteredLineContact(const toml::table& t, const MethodContext<D>& context)
      : ElasticLineContact<D>(line_contact_parameters(t, context), context.rho0) {}
};

std::vector<KeySpec> line_contact_keys() {
  using K = KeyType;
  using namespace keyspec;
  return {
      positive("radius", "m", "", "R, the cylinder's radius (the soft-EHL paper's 100 mm).", true),
      positive("modulus", "Pa", "",
               "E of the film-thickness equation (eq. 1) with its coefficient 2 / (pi E): the contact "
               "modulus E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2) of Hertz's line contact (the paper's "
               "1.95e7 Pa).",
               true),
      positive("load", "N/m", "",
               "W, the load per unit length that the film carries (eq. 2; the paper's 1 kN/m).", true),
      positive(
          "gap", "m", "",
          "The film at the centre at the start (the paper's h0 = 60 um); the load balance then moves the "
          "cylinder.",
          true),
      {"centre", K::Float, "m", "(the domain's middle along x)",
       "x where the undeformed cylinder is lowest."},
      {"plate", K::Float, "m", "0.0", "y of the plate's face (the top of its [[solid]] box)."},
      {"from", K::Float, "m", "(the domain's min x)",
       "Where the cylinder's surface particles begin along x."},
      {"to", K::Float, "m", "(the domain's max x)", "Where they end."},
      ranged({"layers", K::Integer, "", "4",
              "Rows of surface particles along the face's normal (the paper's 4; MPH-I's viscous radius "
              "3.5 spacings needs 4)."},
             1, 12),
      positive(
          "approach_rate", "U", "0.25",
          "The load balance (eq. 2): Delta h changes at approach_rate U (int p dx / W - 1) (the error "
          "clamped to +-1), U the plate's speed. The squeeze film bounds it: the cylinder's motion over a "
          "step is squeeze pressure the next."),
      positive(
          "lag", "b / U", "0.6",
          "The surface follows eq. 1's deformation of the film's pressure through two first-order lags of "
          "lag / 2 each (on the column pressure, then on the deformation), in entrainment times b / U "
          "(b Hertz's half-width). Bounded below by the same squeeze: one lag of 0.6 left the load "
          "swinging +-80% from step to step (docs/mph.md)."),
      choice("start", "\"hertz\"",
             "hertz: the surface starts deformed by Hertz's dry pressure of W, the film `gap` at the centre "
             "(flat over the Hertz zone); rigid: the undeformed cylinder, `gap` its lowest point.",
             {"hertz", "rigid"}),
      {"recycle", K::Bool, "", "true",
       "Fluid that leaves the domain along x re-enters at the other end at its height (the film a sliding "
       "plate carries out comes back to the inlet); the domain stays non-periodic, so the bucket "
       "multigrid applies."},
  };
}

// What the keys alone cannot say: a line contact is 2D, its surface spans at least 8 columns
// with the centre on it, and a [[solid]] slides (its speed is the lags' time scale).
void validate(const Scene& sc, const toml::table& root, std::size_t entry, Validator& val) {
  const toml::table& t = *root["systems"][entry].as_table();
  const std::string where = "systems." + std::to_string(entry);
  if (sc.dimension != 2)
    val.fail(t["name"].node(), where + ".name", "elastic_line_contact is a line contact: 2D only");
  const double from = t["from"].value_or(sc.domain_min[0]), to = t["to"].value_or(sc.domain_max[0]);
  const double centre = t["centre"].value_or(0.5 * (sc.domain_min[0] + sc.domain_max[0]));
  if (!(to - from >= 7 * sc.spacing))
    val.fail(t["to"] ? t["to"].node() : t["name"].node(), where + ".to",
             "elastic_line_contact: the surface from x = " + std::to_string(from) + " to " +
                 std::to_string(to) + " m holds fewer than 8 columns of the spacing");
  if (centre < from || centre > to)
    val.fail(t["centre"] ? t["centre"].node() : t["name"].node(), where + ".centre",
             "elastic_line_contact: the centre x = " + std::to_string(centre) + " m lies off the surface (" +
                 std::to_string(from) + " .. " + std::to_string(to) + " m)");
  double fastest = 0;
  for (auto& s : sc.solids) {
    double v2 = 0;
    for (double c : s.velocity) v2 += c * c;
    fastest = std::max(fastest, std::sqrt(v2));
  }
  if (!(fastest > 0))
    val.fail(t["name"].node(), where + ".name",
             "elastic_line_contact needs a sliding plate, a [[solid]] with a velocity: its speed U sets the "
             "time scale b / U of the surface's lag");
}

}  // namespace

RYUSHI_REGISTER_SYSTEM(
    RegisteredLineContact, "elastic_line_contact",
    "A soft-EHL line contact (soft-EHL paper eqs. 1-2): an elastic cylinder's surface over the plate as "
    "wall particles moved each step to the film-thickness equation, its approach set by the load "
    "balance; writes `film_pressure` and `film_thickness` on the surface particles (docs/mph.md).",
    line_contact_keys(), {"wall_depth"}, validate);

}  // namespace ryushi
