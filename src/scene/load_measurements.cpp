// [[probe]] and [[metric]]: what a run measures and the references its errors are taken against.
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <tuple>

#include "scene/load_common.hpp"
#include "scene/load_parts.hpp"
#include "scene/reference_table.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

// A wall_pressure probe's face: `normal` (made unit) and `diameter`, both required; where the
// particles are needed (is it on a wall, does the normal point away from it) the run checks.
void load_wall_sensor(toml::table& root, Validator& val, const SceneEntries& at, std::size_t i,
                      ProbeSpec& p) {
  const std::string about = "[[probe]] '" + p.name + "' of type wall_pressure";
  auto* normal = at.where("probe", i, "normal");
  if (!normal) val.fail(root["probe"][i].node(), path_of("probe", i, "normal"), about + " needs a normal");
  p.normal = vec_of(*normal);
  double length = 0;
  for (double c : p.normal) length += c * c;
  length = std::sqrt(length);
  if (!(length > 0)) val.fail(normal, path_of("probe", i, "normal"), about + ": the normal must not be zero");
  for (double& c : p.normal) c /= length;
  auto diameter = root["probe"][i]["diameter"].value<double>();
  if (!diameter)
    val.fail(root["probe"][i].node(), path_of("probe", i, "diameter"), about + " needs a diameter");
  p.diameter = *diameter;
  p.position_where = val.location(at.where("probe", i, "position"), path_of("probe", i, "position"));
  p.normal_where = val.location(normal, path_of("probe", i, "normal"));
}

// A pressure or velocity probe with `end` and `points`: the line of `points` probes from
// `position` to `end` (both included), named NAME_0 ... NAME_{points-1} (a velocity profile across
// a cavity, a pressure profile down a wall). Empty without `end`.
std::vector<ProbeSpec> line_of_probes(toml::table& root, Validator& val, const SceneEntries& at,
                                      std::size_t i, const ProbeSpec& p) {
  auto* end_node = at.where("probe", i, "end");
  auto points = root["probe"][i]["points"].value<long long>();
  if (!end_node) {
    if (points)
      val.fail(at.where("probe", i, "points"), path_of("probe", i, "points"),
               "[[probe]] '" + p.name + "': points needs `end`, the line's other end");
    return {};
  }
  if (p.type != "pressure" && p.type != "velocity") {
    val.fail(end_node, path_of("probe", i, "end"),
             "[[probe]] '" + p.name + "': a line (`end`) is for pressure and velocity probes");
    return {};
  }
  const auto end = vec_of(*end_node);
  if (!points) {
    val.fail(end_node, path_of("probe", i, "end"), "[[probe]] '" + p.name + "': a line needs `points`");
    return {};
  }
  if (end.size() != p.position.size() || !at.inside(end, end)) {
    val.fail(end_node, path_of("probe", i, "end"), "[[probe]] '" + p.name + "': end lies outside the domain");
    return {};
  }
  std::vector<ProbeSpec> line;
  for (long long k = 0; k < *points; ++k) {
    ProbeSpec q = p;
    q.name = p.name + "_" + std::to_string(k);
    const double s = double(k) / double(*points - 1);
    for (std::size_t a = 0; a < end.size(); ++a) q.position[a] = p.position[a] + s * (end[a] - p.position[a]);
    line.push_back(std::move(q));
  }
  return line;
}

// A force probe's reference_speed and reference_length (both or neither); on another type either
// is bad input at that key.
void load_force_coefficient(toml::table& root, Validator& val, const SceneEntries& at, std::size_t i,
                            ProbeSpec& p) {
  auto entry = root["probe"][i];
  const char* given = entry["reference_speed"] ? "reference_speed" : "reference_length";
  if (p.type != "force") {
    if (entry["reference_speed"] || entry["reference_length"])
      val.fail(at.where("probe", i, given), path_of("probe", i, given),
               "[[probe]] '" + p.name + "': reference_speed and reference_length are for force probes");
    return;
  }
  p.reference_speed = entry["reference_speed"].value_or(0.0);
  p.reference_length = entry["reference_length"].value_or(0.0);
  if ((p.reference_speed > 0) != (p.reference_length > 0))
    val.fail(
        at.where("probe", i, given), path_of("probe", i, given),
        "[[probe]] '" + p.name + "': a force coefficient needs both reference_speed and reference_length");
}

// Appends a probe; two of one name are bad input at the [[probe]]'s name.
void add_probe(Scene& sc, Validator& val, const SceneEntries& at, std::size_t i, ProbeSpec p) {
  for (auto& q : sc.probes)
    if (q.name == p.name)
      val.fail(at.where("probe", i, "name"), path_of("probe", i, "name"),
               "two probes are named '" + p.name + "'");
  sc.probes.push_back(std::move(p));
}

}  // namespace

void load_measurements(toml::table& root, Validator& val, Scene& sc) {
  const std::string& path = sc.path;
  const int D = sc.dimension;
  const SceneEntries at{root, sc};
  if (auto* arr = root["probe"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      ProbeSpec p;
      p.name = *root["probe"][i]["name"].value<std::string>();
      p.type = *root["probe"][i]["type"].value<std::string>();
      if (auto* pos = at.where("probe", i, "position")) p.position = vec_of(*pos);
      if ((p.type == "pressure" || p.type == "velocity" || p.type == "water_height" ||
           p.type == "solid_displacement" || p.type == "solid_stress" || p.type == "wall_pressure") &&
          p.position.empty())
        val.fail(&(*arr)[i], path_of("probe", i, "position"),
                 "[[probe]] '" + p.name + "' of type " + p.type + " needs a position");
      if (!p.position.empty() && !at.inside(p.position, p.position))
        val.fail(at.where("probe", i, "position"), path_of("probe", i, "position"),
                 "[[probe]] '" + p.name + "' lies outside the domain");
      if (p.type == "wall_pressure") load_wall_sensor(root, val, at, i, p);
      if (p.type == "force") {
        auto solid_name = root["probe"][i]["solid"].value<std::string>();
        if (!solid_name)
          val.fail(&(*arr)[i], path_of("probe", i, "solid"),
                   "[[probe]] '" + p.name + "' of type force needs `solid`, the name of a [[solid]]");
        for (std::size_t k = 0; k < sc.solids.size(); ++k)
          if (sc.solids[k].name == *solid_name) p.solid = static_cast<int>(k);
        if (p.solid < 0)
          val.fail(at.where("probe", i, "solid"), path_of("probe", i, "solid"),
                   "[[probe]] '" + p.name + "': there is no [[solid]] named '" + *solid_name + "'");
      }
      if (p.type == "force" || p.type == "solid_displacement" || p.type == "solid_stress" ||
          p.type == "velocity") {
        p.axis = static_cast<int>(*root["probe"][i]["axis"].value<long long>());
        if (p.axis >= D)
          val.fail(at.where("probe", i, "axis"), path_of("probe", i, "axis"),
                   "[[probe]] '" + p.name + "': axis must be below the dimension");
      }
      load_force_coefficient(root, val, at, i, p);
      if (auto line = line_of_probes(root, val, at, i, p); !line.empty()) {
        for (auto& q : line) add_probe(sc, val, at, i, std::move(q));
        continue;
      }
      if (p.type.rfind("solid_", 0) == 0 && !root["elastic"])
        val.fail(at.where("probe", i, "type"), path_of("probe", i, "type"),
                 "[[probe]] '" + p.name + "': " + p.type + " needs an [[elastic]] body");
      add_probe(sc, val, at, i, std::move(p));
    }
  }
  if (auto* arr = root["metric"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      auto m = root["metric"][i];
      MetricSpec spec;
      spec.name = *m["name"].value<std::string>();
      spec.type = *m["type"].value<std::string>();
      spec.probe = m["probe"].value_or(std::string());
      spec.width = m["width"].value_or(0.0);
      spec.height_ratio = m["height_ratio"].value_or(0.0);
      if (auto v = m["surface"].value<double>()) spec.surface = *v;
      if (auto v = m["force"].value<double>()) spec.force = *v;
      if (auto v = m["depth"].value<double>()) spec.depth = *v;
      if (auto* v = at.where("metric", i, "position")) spec.position = vec_of(*v);
      spec.max_shift = *m["max_shift"].value<double>();
      spec.t_max = *m["t_max"].value<double>();
      for (auto& q : sc.metrics)
        if (q.name == spec.name)
          val.fail(at.where("metric", i, "name"), path_of("metric", i, "name"),
                   "two metrics are named '" + spec.name + "'");
      if (spec.type == "dam_break_front" && spec.probe.empty())
        for (auto& p : sc.probes)
          if (p.type == "surge_front") {
            spec.probe = p.name;
            break;
          }
      if (spec.type == "rotating_square_pressure" && spec.probe.empty())
        for (auto& p : sc.probes)
          if (p.type == "pressure") {
            spec.probe = p.name;
            break;
          }
      const bool reads_probe = spec.type == "dam_break_front" || spec.type == "probe_csv" ||
                               spec.type == "rotating_square_pressure";
      if (reads_probe) {
        const ProbeSpec* probe = nullptr;
        for (auto& p : sc.probes)
          if (p.name == spec.probe) probe = &p;
        if (!probe)
          val.fail(&(*arr)[i], path_of("metric", i, "probe"),
                   "[[metric]] '" + spec.name + "' needs a [[probe]]" +
                       (spec.type == "dam_break_front"            ? " of type surge_front"
                        : spec.type == "rotating_square_pressure" ? " of type pressure"
                                                                  : " named by its `probe` key") +
                       (spec.probe.empty() ? "" : "; there is no probe '" + spec.probe + "'"));
        if (spec.type == "rotating_square_pressure" && probe->type != "pressure")
          val.fail(at.where("metric", i, "probe"), path_of("metric", i, "probe"),
                   "[[metric]] '" + spec.name + "': probe '" + spec.probe + "' is not a pressure probe");
        if (spec.type == "dam_break_front" && probe->type != "surge_front")
          val.fail(at.where("metric", i, "probe"), path_of("metric", i, "probe"),
                   "[[metric]] '" + spec.name + "': probe '" + spec.probe + "' is not a surge_front");
      }
      if (auto r = m["reference"].value<std::string>()) {
        auto file = std::filesystem::path(*r);
        if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
        spec.reference = file.string();
      } else if (spec.type == "dam_break_front") {
        spec.reference =
            (std::filesystem::path(RYUSHI_TOOLS_DIR) / "reference" / "martin_moyce_1952_n2_2.csv").string();
      } else if (spec.type == "probe_csv") {
        val.fail(&(*arr)[i], path_of("metric", i, "reference"),
                 "[[metric]] '" + spec.name + "' of type probe_csv needs a reference CSV");
      }
      if (!spec.reference.empty()) {
        try {
          spec.table = read_reference_table(spec.reference);
        } catch (const SceneError& e) {
          val.fail(at.where("metric", i, "reference") ? at.where("metric", i, "reference") : &(*arr)[i],
                   path_of("metric", i, "reference"), std::string("metric.reference: ") + e.what());
        }
      }
      FluidBlock first;  // an imports-only scene has no block to take defaults from
      first.min.assign(D, 0.0), first.max.assign(D, 0.0);
      if (!sc.fluid.empty()) first = sc.fluid.front();
      auto need = [&](bool ok, const char* key, const std::string& what) {
        if (!ok)
          val.fail(at.where("metric", i, key) ? at.where("metric", i, key) : &(*arr)[i],
                   path_of("metric", i, key),
                   "[[metric]] '" + spec.name + "' of type " + spec.type + " " + what);
      };
      if (spec.type == "dam_break_front") {
        if (spec.width <= 0) spec.width = first.max[0] - first.min[0];
        if (spec.height_ratio <= 0 && spec.width > 0)
          spec.height_ratio = (first.max[D - 1] - first.min[D - 1]) / spec.width;
        need(spec.width > 0, "width", "needs the column width `width` > 0 (or a first [[fluid]] block)");
        need(spec.height_ratio > 0, "height_ratio",
             "needs the column's height over its width `height_ratio` > 0 (or a first [[fluid]] block)");
      }
      if (spec.type == "poiseuille_profile") {
        need(spec.width > 0, "width", "needs the channel width `width` > 0");
        need(std::isfinite(spec.force) && spec.force != 0, "force",
             "needs the body force `force` (non-zero)");
        need(sc.viscosity > 0, "type", "needs a viscous fluid ([material] viscosity > 0)");
        if (spec.position.empty()) spec.position = {0.5 * (first.min[0] + first.max[0]), 0.0};
        need(spec.position.size() >= 2, "position", "takes position = [x of the column, y of the wall]");
      }
      if (spec.type == "ritter_depth") {
        if (std::isnan(spec.depth)) spec.depth = first.depth;
        need(spec.depth > 0, "depth",
             "needs the depth behind the dam (`depth` > 0, or a first [[fluid]] with depth)");
        if (spec.position.empty()) spec.position = first.max;
      }
      if (spec.type == "rotating_square_pressure") {
        need(D == 2, "type", "is for 2D scenes");
        spec.angular_velocity = first.angular_velocity;
        need(spec.angular_velocity != 0, "type",
             "needs the first [[fluid]] block to rotate (angular_velocity)");
        if (spec.width <= 0) spec.width = first.max[0] - first.min[0];
        if (spec.position.empty())
          for (int a = 0; a < D; ++a) spec.position.push_back(0.5 * (first.min[a] + first.max[a]));
      }
      if (spec.type == "hydrostatic_pressure" && std::isnan(spec.surface))
        for (auto& b : sc.fluid)
          spec.surface = std::isnan(spec.surface) ? b.max.back() : std::max(spec.surface, b.max.back());
      sc.metrics.push_back(std::move(spec));
    }
  }
}

}  // namespace ryushi
