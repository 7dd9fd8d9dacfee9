#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include <spdlog/spdlog.h>

#include "geometry/solid_shape.hpp"
#include "scene/expression.hpp"
#include "scene/load_elastic.hpp"
#include "scene/load_heat_rheology.hpp"
#include "scene/load_method.hpp"
#include "scene/particle_import.hpp"
#include "scene/overlaps.hpp"
#include "scene/scene.hpp"
#include "scene/schema.hpp"
#include "scene/validator.hpp"
#include "systems/kernels/kernel.hpp"
#include "metrics/metrics.hpp"

namespace ryushi {

double Scene::fluid_height() const {
  double h = 0;
  for (auto& b : fluid) h = std::max(h, b.max.back() - b.min.back());
  for (auto& import : imports) {  // from the lowest particle's bottom to the highest one's top
    double low = 1e300, high = -1e300;
    for (auto& x : import.particles->position) low = std::min(low, x[dimension - 1]), high = std::max(high, x[dimension - 1]);
    h = std::max(h, high - low + spacing);
  }
  return h;
}
double Scene::support_radius() const {
  return Kernel<2>(kernel_from_name(kernel), smoothing_length()).support();
}
double Scene::gravity_magnitude() const {
  double g2 = 0;
  for (double g : gravity) g2 += g * g;
  return std::sqrt(g2);
}
double Scene::resolved_sound_speed() const {
  if (sound_speed > 0) return sound_speed;
  double c = sound_speed_factor * std::sqrt(2.0 * gravity_magnitude() * fluid_height());
  return c > 0 ? c : sound_speed_factor;  // no gravity: c0 = factor (m/s), documented in scenes.md
}

namespace {


std::vector<double> vec_of(const toml::node& n) {
  std::vector<double> v;
  for (auto& e : *n.as_array()) v.push_back(*e.value<double>());
  return v;
}

// A number or formula entry (KeyType::FieldValue) as the text of a formula: numbers exactly
// (17 digits), so that a number and its formula give the same value.
std::string field_text(const toml::node& n) {
  if (n.is_string()) return *n.value<std::string>();
  std::ostringstream number;
  number.precision(17);
  number << *n.value<double>();
  return number.str();
}

// The bounding box of a disc or ball of `radius` about `centre`; on axis `along` (a 3D
// cylinder's; -1: none) the box spans [lo, hi] instead.
std::pair<std::vector<double>, std::vector<double>> round_box(const std::vector<double>& centre, double radius,
                                                              int along, const std::vector<double>& lo,
                                                              const std::vector<double>& hi) {
  std::vector<double> min = centre, max = centre;
  for (std::size_t a = 0; a < centre.size(); ++a) {
    min[a] = static_cast<int>(a) == along ? lo[a] : centre[a] - radius;
    max[a] = static_cast<int>(a) == along ? hi[a] : centre[a] + radius;
  }
  return {min, max};
}

// Applies one `section.key=value` or `section.N.key=value` override to the tree.
void apply_override(toml::table& root, const std::string& text, Validator& val) {
  auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError("--set " + text + ": expected section.key=value");
  std::string path = text.substr(0, eq), value = text.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  std::string where = "--set " + text;
  const SectionSpec* section = parts.empty() ? nullptr : find_section(parts[0]);
  if (!section) {
    std::vector<std::string> names;
    for (auto& s : scene_schema()) names.push_back(s.name);
    std::string hint = parts.empty() ? "" : closest_name(parts[0], names);
    throw SceneError(where + ": unknown section '" + (parts.empty() ? "" : parts[0]) + "'" +
                     (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
  }
  toml::table* target = nullptr;
  std::string key, key_path;
  if (section->array_of_tables) {
    if (parts.size() != 3) throw SceneError(where + ": use " + parts[0] + ".N.key for [[" + parts[0] + "]]");
    auto* arr = root[parts[0]].as_array();
    std::size_t idx = 0;
    try {
      idx = std::stoul(parts[1]);
    } catch (...) {
      throw SceneError(where + ": '" + parts[1] + "' is not an index");
    }
    if (!arr || idx >= arr->size() || !(*arr)[idx].is_table())
      throw SceneError(where + ": the scene has no [[" + parts[0] + "]] entry " + parts[1]);
    target = (*arr)[idx].as_table();
    key = parts[2];
    key_path = parts[0] + "." + parts[1] + "." + key;
  } else {
    // section.key, or section.table.key for a table inside it ([method.isph] keys).
    if (parts.size() != 2 && parts.size() != 3) throw SceneError(where + ": use section.key");
    if (!root.contains(parts[0])) root.insert(parts[0], toml::table{});
    target = root[parts[0]].as_table();
    if (!target) throw SceneError(where + ": [" + parts[0] + "] is not a table in the scene");
    if (parts.size() == 3) {
      if (!target->contains(parts[1])) target->insert(parts[1], toml::table{});
      target = target->get_as<toml::table>(parts[1]);
      if (!target) throw SceneError(where + ": " + parts[0] + "." + parts[1] + " is not a table in the scene");
    }
    key = parts.back();
    key_path = path;
  }
  toml::table holder;
  try {
    holder = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    holder = toml::table{};
    holder.insert("v", value);  // a bare word is a string
  }
  target->insert_or_assign(key, *holder["v"].node());
  val.overridden[key_path] = where;
}

}  // namespace

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  {
    std::ifstream probe(path);
    if (!probe) throw SceneError(path + ": cannot read the scene file (" +
                                 (std::filesystem::exists(path) ? "permission denied" : "no such file") + ")");
  }
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    std::ostringstream out;
    out << path << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw SceneError(out.str());
  }
  Validator val(path, root);
  for (auto& o : overrides) apply_override(root, o, val);

  std::vector<std::string> section_names;
  for (auto& s : scene_schema()) section_names.push_back(s.name);
  for (auto& [k, node] : root) {
    std::string name(k.str());
    if (!find_section(name)) {
      std::string hint = closest_name(name, section_names);
      val.fail_at(&k.source(), name, "unknown section '" + name + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
    }
  }
  // The sections the file (or --set) wrote; the others get their defaults inserted below.
  std::set<std::string> written;
  std::set<std::string> written_keys;  // "section.key" of the plain sections' keys it wrote
  for (auto& [k, node] : root) {
    written.insert(std::string(k.str()));
    if (auto* t = node.as_table())
      for (auto& [key, _] : *t) written_keys.insert(std::string(k.str()) + "." + std::string(key.str()));
  }
  // The dimension first: vector lengths depend on it.
  {
    auto* scene_tbl = root["scene"].as_table();
    if (!scene_tbl) val.fail(root["scene"].node(), "scene", "missing required section [scene]");
    val.check_table(*scene_tbl, "[scene]", "scene.", find_section("scene")->keys, root["scene"].node());
    val.dimension = static_cast<int>(*(*scene_tbl)["dimension"].value<long long>());
  }
  for (auto& s : scene_schema()) {
    if (s.name == "method") continue;  // checked against the chosen method's keys below
    toml::node* node = root.get(s.name);
    if (!node) {
      if (s.required) val.fail(nullptr, s.name, "missing required section " + (s.array_of_tables ? "[[" + s.name + "]]" : "[" + s.name + "]"));
      if (!s.array_of_tables) {
        root.insert(s.name, toml::table{});
        val.check_table(*root[s.name].as_table(), "[" + s.name + "]", s.name + ".", s.keys, nullptr);
      }
      continue;
    }
    if (!s.array_of_tables) {
      if (!node->is_table()) val.fail(node, s.name, "[" + s.name + "] must be a table");
      val.check_table(*node->as_table(), "[" + s.name + "]", s.name + ".", s.keys, node);
      continue;
    }
    auto* arr = node->as_array();
    if (!arr || !arr->is_array_of_tables())
      val.fail(node, s.name, "'" + s.name + "' must be an array of tables: write [[" + s.name + "]]");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      auto& t = *(*arr)[i].as_table();
      std::string label = "[[" + s.name + "]] #" + std::to_string(i);
      std::string prefix = s.name + "." + std::to_string(i) + ".";
      if (s.name != "systems") {
        val.check_table(t, label, prefix, s.keys, &(*arr)[i]);
        continue;
      }
      // A system entry: `name` plus the parameters the registered system declares.
      auto* name_node = t.get("name");
      if (!name_node || !name_node->is_string()) val.fail(&(*arr)[i], prefix + "name", label + " needs name = \"<registered system>\"");
      std::string sys = *name_node->value<std::string>();
      if (!find_system_keys(sys)) {
        std::string hint = closest_name(sys, system_key_names());
        val.fail(name_node, prefix + "name", "no system registered as '" + sys + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
      }
      auto keys = find_system_keys(sys)->keys;
      keys.insert(keys.begin(), s.keys.begin(), s.keys.end());
      val.check_table(t, label + " (" + sys + ")", prefix, keys, &(*arr)[i]);
    }
  }

  Scene sc;
  sc.path = path;
  const int D = val.dimension;
  sc.dimension = D;
  auto get = [&](const char* sec, const char* key) -> toml::node& { return *root[sec][key].node(); };
  sc.name = root["scene"]["name"].value_or(std::filesystem::path(path).stem().string());
  sc.description = get("scene", "description").value_or(std::string());
  sc.domain_min = vec_of(get("domain", "min"));
  sc.domain_max = vec_of(get("domain", "max"));
  sc.outflow_removes = *get("domain", "outflow").value<std::string>() == "remove";
  sc.periodic.assign(D, false);
  if (auto* p = root["domain"]["periodic"].as_array())
    for (int a = 0; a < D; ++a) sc.periodic[a] = *(*p)[a].value<bool>();
  sc.spacing = *get("particles", "spacing").value<double>();
  load_method_section(root, val, sc);
  const MethodHooks& hooks = find_method_spec(sc.method)->hooks;
  // A section or key that belongs to another method ([swe] under wcsph, [time] step_rule under mps).
  for (auto& owner : method_spec_names()) {
    if (owner == sc.method) continue;
    for (auto& owned : find_method_spec(owner)->owns) {
      const auto dot = owned.find('.');
      if (dot == std::string::npos && written.count(owned) && find_section(owned)->array_of_tables)
        val.fail_entry(root, owned, 0, "min", "[[" + owned + "]] #0 is for method " + owner);
      if (dot == std::string::npos && written.count(owned))
        val.fail(root[owned].node(), owned, "[" + owned + "] is for [method] name = \"" + owner + "\"");
      if (dot != std::string::npos && written_keys.count(owned)) {
        const std::string section = owned.substr(0, dot), key = owned.substr(dot + 1);
        val.fail(root[section][key].node(), owned, "[" + section + "] " + key + " is for method " + owner);
      }
    }
  }
  const bool swe = sc.method == "swe";
  sc.swe.influence_ratio = *get("swe", "influence_ratio").value<double>();
  sc.disorder = root["particles"]["disorder"].value_or(0.0);
  sc.seed = static_cast<std::uint64_t>(root["particles"]["seed"].value_or(1LL));
  sc.smoothing_ratio = root["particles"]["smoothing_ratio"].value_or(hooks.smoothing_ratio ? hooks.smoothing_ratio(sc) : 1.5);
  sc.kernel = root["particles"]["kernel"].value_or(hooks.kernel ? hooks.kernel(D) : std::string("wendland_c2"));
  sc.reorder_interval = static_cast<int>(*get("particles", "reorder_interval").value<long long>());
  sc.neighbour_skin = *get("particles", "neighbour_skin").value<double>();
  sc.density = *get("material", "density").value<double>();
  sc.viscosity = *get("material", "viscosity").value<double>();
  sc.sound_speed = *get("material", "sound_speed").value<double>();
  sc.sound_speed_factor = *get("material", "sound_speed_factor").value<double>();
  sc.gamma = *get("material", "gamma").value<double>();
  sc.gravity.assign(D, 0.0);
  sc.gravity[D - 1] = -9.81;
  if (root["physics"]["gravity"]) sc.gravity = vec_of(get("physics", "gravity"));
  // The method's defaults and checks that depend on the scene (before its geometry is read).
  if (hooks.resolve) hooks.resolve(sc, root, val);
  // The default layers of [[wall]] and [[solid]]: enough to cover the support, or the method's.
  const int covering = static_cast<int>(std::ceil(sc.support_radius() / sc.spacing - 1e-9));
  const int default_layers = hooks.wall_layers ? hooks.wall_layers(sc) : covering;
  sc.shifting_model = root["shifting"]["model"].value_or(hooks.shifting);
  sc.shifting_coefficient = *get("shifting", "coefficient").value<double>();
  sc.fickian_coefficient = *get("shifting", "fickian_coefficient").value<double>();
  sc.anti_clumping = *get("shifting", "anti_clumping").value<double>();
  sc.max_shift = *get("shifting", "max_shift").value<double>();
  sc.xsph_epsilon = *get("shifting", "xsph_epsilon").value<double>();
  {
    auto& sv = sc.solver;
    auto str = [&](const char* key) { return *get("solver", key).value<std::string>(); };
    auto integer = [&](const char* key) { return *get("solver", key).value<long long>(); };
    sv.krylov = str("krylov");
    sv.preconditioner = str("preconditioner");
    sv.cycle = str("cycle");
    sv.precision = str("precision");
    sv.initial_guess = str("initial_guess");
    sv.tolerance = *get("solver", "tolerance").value<double>();
    sv.max_iterations = static_cast<int>(std::min<long long>(integer("max_iterations"), 1 << 30));
    sv.pre_smoothing = static_cast<int>(integer("pre_smoothing"));
    sv.post_smoothing = static_cast<int>(integer("post_smoothing"));
    sv.bottom_smoothing = static_cast<int>(integer("bottom_smoothing"));
    sv.bottom_size = integer("bottom_size");
    sv.jacobi_weight = root["solver"]["jacobi_weight"].value_or(hooks.jacobi_weight);
  }
  sc.end_time = *get("time", "end").value<double>();
  sc.cfl = root["time"]["cfl"].value_or(hooks.cfl);
  sc.fixed_dt = *get("time", "dt").value<double>();
  sc.max_steps = *get("time", "max_steps").value<long long>();
  sc.dt_min = *get("time", "dt_min").value<double>();
  sc.step_rule = *get("time", "step_rule").value<std::string>();
  sc.output_interval = root["output"]["interval"].value_or(sc.end_time / 20.0);
  if (sc.output_interval <= 0) sc.output_interval = sc.end_time / 20.0;
  sc.probe_interval = root["output"]["probe_interval"].value_or(sc.output_interval / 10.0);
  if (sc.probe_interval <= 0) sc.probe_interval = sc.output_interval / 10.0;
  sc.checkpoint_interval = *get("output", "checkpoint_interval").value<double>();
  for (auto& e : *root["output"]["fields"].as_array()) sc.output_fields.push_back(*e.value<std::string>());
  if (swe) {
    auto& w = sc.swe;
    w.gravity = *get("swe", "gravity").value<double>();
    w.manning = *get("swe", "manning").value<double>();
    w.slip = *get("swe", "walls").value<std::string>() == "slip";
    w.edge_correction = *get("swe", "edge_correction").value<bool>();
    w.momentum = *get("swe", "momentum").value<std::string>();
    if (root["swe"]["ritter_dam_x"] || root["swe"]["ritter_depth"]) {
      if (!root["swe"]["ritter_dam_x"] || !root["swe"]["ritter_depth"])
        val.fail(root["swe"].node(), "swe.ritter_dam_x", "[swe] ritter_dam_x and ritter_depth go together");
      w.ritter_dam_x = *get("swe", "ritter_dam_x").value<double>();
      w.ritter_depth = *get("swe", "ritter_depth").value<double>();
    }
    w.splitting = *get("splitting", "enabled").value<bool>();
    w.split_area_ratio = *get("splitting", "area_ratio").value<double>();
    w.split_distance = *get("splitting", "distance").value<double>();
    w.split_along_gap = *get("splitting", "direction").value<std::string>() == "gap";
    w.max_particles = root["splitting"]["max_particles"].value_or(0LL);
    auto& bed = *w.bed;
    bed.elevation_base = *get("bed", "elevation").value<double>();
    if (auto raster = root["bed"]["raster"].value<std::string>()) {
      auto file = std::filesystem::path(*raster);
      if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
      try {
        bed.raster = std::make_shared<Raster>(read_esri_ascii(file));
      } catch (const RasterError& e) {
        val.fail(root["bed"]["raster"].node(), "bed.raster", std::string("bed.raster: ") + e.what());
      }
      if (bed.raster->nodata_cells > 0)
        spdlog::info("{}: {} no-data cells of {} are dry high ground", file.string(), bed.raster->nodata_cells,
                     bed.raster->z.size());
    }
    auto xy = [&](const toml::node* n) {
      auto v = vec_of(*n);
      return std::array<double, 2>{v[0], v[1]};
    };
    if (auto* arr = root["bed_hump"].as_array())
      for (std::size_t i = 0; i < arr->size(); ++i)
        bed.humps.push_back({xy(root["bed_hump"][i]["centre"].node()), *root["bed_hump"][i]["height"].value<double>(),
                             *root["bed_hump"][i]["width"].value<double>()});
    if (auto* arr = root["bed_ramp"].as_array())
      for (std::size_t i = 0; i < arr->size(); ++i) {
        auto r = root["bed_ramp"][i];
        bed.ramps.push_back({xy(r["min"].node()), xy(r["max"].node()), xy(r["origin"].node()), xy(r["gradient"].node())});
      }
    sc.gravity.assign(D, 0.0);
  }

  auto where = [&](const char* sec, std::size_t i, const char* key) -> const toml::node* {
    return root[sec][i][key].node();
  };
  auto path_of = [](const char* sec, std::size_t i, const char* key) {
    return std::string(sec) + "." + std::to_string(i) + "." + key;
  };
  // Consistency checks that need more than one key.
  for (int a = 0; a < D; ++a)
    if (!(sc.domain_max[a] > sc.domain_min[a]))
      val.fail(get("domain", "max").as_array()->get(a), "domain.max",
               "domain.max must exceed domain.min on every axis (axis " + std::to_string(a) + ")");
  auto inside = [&](const std::vector<double>& lo, const std::vector<double>& hi) {
    for (int a = 0; a < D; ++a)
      if (lo[a] < sc.domain_min[a] - 1e-12 || hi[a] > sc.domain_max[a] + 1e-12) return false;
    return true;
  };
  if (auto* arr = root["mesh"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      auto t = root["mesh"][i];
      MeshSpec m{*t["name"].value<std::string>(), *t["file"].value<std::string>(), nullptr};
      const std::string label = "[[mesh]] '" + m.name + "'";
      if (D != 3) val.fail(where("mesh", i, "file"), path_of("mesh", i, "file"), label + ": meshes are for 3D scenes");
      for (auto& other : sc.meshes)
        if (other.name == m.name) val.fail(where("mesh", i, "name"), path_of("mesh", i, "name"), "two meshes are named '" + m.name + "'");
      auto file = std::filesystem::path(m.file);
      if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
      MeshTransform transform;
      transform.scale = *t["scale"].value<double>();
      auto rotate = vec_of(*where("mesh", i, "rotate")), translate = vec_of(*where("mesh", i, "translate"));
      for (int a = 0; a < 3; ++a) transform.rotate_degrees[a] = rotate[a], transform.translate[a] = translate[a];
      try {
        m.mesh = TriangleMesh::read(file.string(), transform);
      } catch (const MeshError& e) {
        val.fail(where("mesh", i, "file"), path_of("mesh", i, "file"), label + ": " + e.what());
      }
      sc.meshes.push_back(std::move(m));
    }
  }
  // A [[mesh]] by name: its index, or an error at the key.
  auto mesh_named = [&](const char* section, std::size_t i, const std::string& label) -> int {
    const std::string name = *root[section][i]["mesh"].value<std::string>();
    for (std::size_t k = 0; k < sc.meshes.size(); ++k)
      if (sc.meshes[k].name == name) return static_cast<int>(k);
    val.fail(where(section, i, "mesh"), path_of(section, i, "mesh"), label + ": there is no [[mesh]] named '" + name + "'");
  };
  // centre, radius and axis of a round [[fluid]] block or [[solid]] body.
  auto read_round = [&](const char* section, std::size_t i, auto& b) {
    b.centre = vec_of(*where(section, i, "centre"));
    b.radius = *root[section][i]["radius"].value<double>();
    b.axis = static_cast<int>(*root[section][i]["axis"].value<long long>());
  };
  if (auto* arr = root["fluid"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      FluidBlock b;
      const std::string label = "[[fluid]] #" + std::to_string(i);
      b.shape = *root["fluid"][i]["shape"].value<std::string>();
      if (b.shape == "box") {
        if (!where("fluid", i, "min") || !where("fluid", i, "max"))
          val.fail(&(*arr)[i], path_of("fluid", i, "min"), label + " (a box) needs min and max");
        b.min = vec_of(*where("fluid", i, "min"));
        b.max = vec_of(*where("fluid", i, "max"));
      } else {
        if (!where("fluid", i, "centre") || !where("fluid", i, "radius"))
          val.fail(&(*arr)[i], path_of("fluid", i, "centre"), label + " (a " + b.shape + ") needs centre and radius");
        read_round("fluid", i, b);
        const bool given = where("fluid", i, "min") && where("fluid", i, "max");
        if (D == 3 && b.shape == "cylinder" && !given)
          val.fail(&(*arr)[i], path_of("fluid", i, "min"), label + " (a 3D cylinder) needs min and max for its extent along its axis");
        std::tie(b.min, b.max) = given ? std::pair{vec_of(*where("fluid", i, "min")), vec_of(*where("fluid", i, "max"))}
                                       : round_box(b.centre, b.radius, -1, {}, {});
      }
      if (auto* v = where("fluid", i, "velocity")) {
        b.velocity.assign(D, 0.0);
        b.velocity_expression.assign(D, "");
        for (int a = 0; a < D; ++a) {
          const toml::node& e = *v->as_array()->get(a);
          if (e.is_string())
            b.velocity_expression[a] = *e.value<std::string>();
          else
            b.velocity[a] = *e.value<double>();
        }
        b.velocity_where = val.location(v, path_of("fluid", i, "velocity"));
      }
      if (where("fluid", i, "mesh")) {
        b.mesh = mesh_named("fluid", i, label);
        if (!sc.meshes[b.mesh].mesh->closed())
          val.fail(where("fluid", i, "mesh"), path_of("fluid", i, "mesh"),
                   label + ": [[mesh]] '" + sc.meshes[b.mesh].name + "' is not closed, so it has no inside to fill (it can be a [[solid]] surface)");
      }
      if (auto* pr = where("fluid", i, "pressure")) {
        if (sc.method == "swe")
          val.fail(pr, path_of("fluid", i, "pressure"), "[[fluid]] #" + std::to_string(i) + ": pressure is for methods wcsph, mps and isph (swe sets depth)");
        b.pressure_expression = field_text(*pr);
        b.pressure_where = val.location(pr, path_of("fluid", i, "pressure"));
      }
      b.angular_velocity = *root["fluid"][i]["angular_velocity"].value<double>();
      if (auto v = root["fluid"][i]["depth"].value<double>()) b.depth = *v;
      if (auto v = root["fluid"][i]["surface_elevation"].value<double>()) b.surface_elevation = *v;
      if (swe && std::isnan(b.depth) == std::isnan(b.surface_elevation))
        val.fail(&(*arr)[i], path_of("fluid", i, "depth"),
                 "[[fluid]] #" + std::to_string(i) + ": method swe needs one of depth and surface_elevation");
      if (!swe && !(std::isnan(b.depth) && std::isnan(b.surface_elevation)))
        val.fail(&(*arr)[i], path_of("fluid", i, "depth"),
                 "[[fluid]] #" + std::to_string(i) + ": depth and surface_elevation are for method swe");
      if (b.angular_velocity != 0 && D != 2)
        val.fail(where("fluid", i, "angular_velocity"), path_of("fluid", i, "angular_velocity"),
                 "[[fluid]] #" + std::to_string(i) + ": angular_velocity is for 2D scenes");
      for (int a = 0; a < D; ++a)
        if (std::lround((b.max[a] - b.min[a]) / sc.spacing) < 1)
          val.fail(where("fluid", i, "max"), path_of("fluid", i, "max"),
                   "[[fluid]] #" + std::to_string(i) + " is empty: thinner than one particle spacing on axis " + std::to_string(a));
      for (int a = 0; a < D; ++a) {
        double n = std::lround((b.max[a] - b.min[a]) / sc.spacing), filled = n * sc.spacing;
        if (std::abs(filled - (b.max[a] - b.min[a])) > 1e-6 * sc.spacing)
          spdlog::warn("{}: [[fluid]] #{} is {} m wide on axis {}, not a multiple of the spacing {} m: filled with {} particles ({} m)",
                       path, i, b.max[a] - b.min[a], a, sc.spacing, n, filled);
      }
      if (!inside(b.min, b.max))
        val.fail(where("fluid", i, "min"), path_of("fluid", i, "min"),
                 "[[fluid]] #" + std::to_string(i) + " lies (partly) outside the domain");
      sc.fluid.push_back(std::move(b));
    }
  }
  if (auto* arr = root["import"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      ImportSpec spec{*root["import"][i]["file"].value<std::string>(), nullptr};
      const std::string label = "[[import]] #" + std::to_string(i);
      if (swe) val.fail(where("import", i, "file"), path_of("import", i, "file"), label + " is for methods wcsph, mps and isph");
      auto file = std::filesystem::path(spec.file);
      if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
      try {
        spec.particles = import_particles(file.string(), D);
      } catch (const ImportError& e) {
        val.fail(where("import", i, "file"), path_of("import", i, "file"), label + ": " + e.what());
      }
      for (auto& x : spec.particles->position) {
        std::vector<double> at(x.begin(), x.begin() + D);
        if (!inside(at, at)) {
          std::ostringstream m;
          m << label << ": a particle at (" << x[0] << ", " << x[1] << (D == 3 ? ", " + std::to_string(x[2]) : "")
            << ") lies outside the domain";
          val.fail(where("import", i, "file"), path_of("import", i, "file"), m.str());
        }
      }
      sc.imports.push_back(std::move(spec));
    }
  }
  if (sc.fluid.empty() && sc.imports.empty() && !root["elastic"])
    val.fail(root["fluid"].node(), "fluid", "the scene has no [[fluid]] block, no [[import]] and no [[elastic]] body");
  if (auto* arr = root["wall"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      WallBox w{vec_of(*where("wall", i, "min")), vec_of(*where("wall", i, "max")),
                static_cast<int>(root["wall"][i]["layers"].value_or(static_cast<long long>(default_layers))),
                *root["wall"][i]["open_top"].value<bool>(), {}, {}};
      w.open_ends.assign(D, false);
      if (auto* open = root["wall"][i]["open_ends"].as_array())
        for (int a = 0; a < D; ++a) w.open_ends[a] = *(*open)[a].value<bool>();
      for (int a = 0; a < D; ++a)
        if (!(w.max[a] > w.min[a]))
          val.fail(where("wall", i, "max"), path_of("wall", i, "max"), "[[wall]] #" + std::to_string(i) + " is empty (max <= min)");
      double thick = w.layers * sc.spacing;
      std::vector<double> lo = w.min, hi = w.max;
      for (int a = 0; a < D; ++a) {
        if (w.open_ends[a]) continue;
        lo[a] -= thick;
        if (a < D - 1 || !w.open_top) hi[a] += thick;
      }
      if (!inside(lo, hi))
        val.fail(where("wall", i, "min"), path_of("wall", i, "min"),
                 "[[wall]] #" + std::to_string(i) + " with its " + std::to_string(w.layers) + " layers lies outside the domain");
      // Layers that cover the support, unless the method keeps fewer (ISPH's one with normals;
      // its resolve hook checks them).
      if (default_layers >= covering && thick + 1e-12 < sc.support_radius()) {
        std::ostringstream m;
        m << "[[wall]] #" << i << ": " << w.layers << " layers (" << thick << " m) do not cover the support radius "
          << sc.support_radius() << " m; use layers >= " << covering;
        val.fail(root["wall"][i]["layers"].node() ? root["wall"][i]["layers"].node() : &(*arr)[i], path_of("wall", i, "layers"), m.str());
      }
      sc.walls.push_back(std::move(w));
    }
  }
  // The box a body's particles occupy: a container's layers lie outside its shape.
  auto solid_extent = [&](const SolidSpec& b) {
    std::vector<double> lo = b.min, hi = b.max;
    if (b.container)
      for (int a = 0; a < D; ++a)
        if (!(D == 3 && b.shape == "cylinder" && a == b.axis)) lo[a] -= b.layers * sc.spacing, hi[a] += b.layers * sc.spacing;
    return std::pair{lo, hi};
  };
  // Whether every corner of the body's box lies where the container holds fluid, half a spacing
  // clear of its wall (a round body in a round container: its box, conservatively).
  auto body_in_container = [&](const SolidSpec& body, const SolidSpec& container) {
    auto check = [&](auto dim) {
      constexpr int DD = decltype(dim)::value;
      SolidShape<DD> shape(container, container.mesh >= 0 ? sc.meshes[container.mesh].mesh : nullptr);
      bool ok = true;
      for (int corner = 0; corner < (1 << DD); ++corner) {
        Vec<DD> x;
        for (int a = 0; a < DD; ++a) x[a] = (corner >> a & 1) ? body.max[a] : body.min[a];
        ok = ok && !shape.within(x, 0.5 * sc.spacing);
      }
      return ok;
    };
    return D == 2 ? check(std::integral_constant<int, 2>{}) : check(std::integral_constant<int, 3>{});
  };
  if (auto* arr = root["solid"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      auto t = root["solid"][i];
      const std::string label = "[[solid]] #" + std::to_string(i);
      auto need = [&](bool ok, const char* key, const std::string& what) {
        if (!ok) val.fail(where("solid", i, key) ? where("solid", i, key) : &(*arr)[i], path_of("solid", i, key), label + " " + what);
      };
      need(!swe, "shape", "is for methods wcsph, mps and isph (swe walls are [[wall]] mirror lines)");
      SolidSpec b;
      b.name = t["name"].value_or("solid" + std::to_string(i));
      b.shape = *t["shape"].value<std::string>();
      b.layers = static_cast<int>(t["layers"].value_or(static_cast<long long>(default_layers)));
      b.velocity.assign(D, 0.0);
      if (auto* v = where("solid", i, "velocity")) b.velocity = vec_of(*v);
      if (auto* motion = where("solid", i, "displacement")) {
        need(!where("solid", i, "velocity"), "displacement", "has both velocity (a surface sliding in place) and displacement (moving particles); give one");
        for (auto& e : *motion->as_array()) b.displacement.push_back(field_text(e));
        b.displacement_where = val.location(motion, path_of("solid", i, "displacement"));
      }
      if (auto table = t["displacement_table"].value<std::string>()) {
        need(!where("solid", i, "velocity") && !where("solid", i, "displacement"), "displacement_table",
             "has displacement_table with velocity or displacement; give one");
        auto file = std::filesystem::path(*table);
        if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
        try {
          b.displacement_table = read_motion_table(file.string(), D);
        } catch (const std::runtime_error& e) {
          need(false, "displacement_table", std::string("displacement_table: ") + e.what());
        }
      }
      if (b.shape == "mesh") {
        need(where("solid", i, "mesh"), "shape", "(a mesh) needs `mesh`, the name of a [[mesh]]");
        b.mesh = mesh_named("solid", i, label);
        const auto& mesh = *sc.meshes[b.mesh].mesh;
        // An open surface's layers lie behind it: the box grows by them.
        const double behind = mesh.closed() ? 0.0 : b.layers * sc.spacing;
        b.min.assign(D, 0.0), b.max.assign(D, 0.0);
        for (int a = 0; a < D; ++a) b.min[a] = mesh.lower()[a] - behind, b.max[a] = mesh.upper()[a] + behind;
      } else if (b.shape == "box") {
        need(where("solid", i, "min") && where("solid", i, "max"), "min", "(a box) needs min and max");
        b.min = vec_of(*where("solid", i, "min"));
        b.max = vec_of(*where("solid", i, "max"));
        for (int a = 0; a < D; ++a) need(b.max[a] > b.min[a], "max", "is empty (max <= min on axis " + std::to_string(a) + ")");
        b.endless.assign(D, false);
        for (int a = 0; a < D; ++a)
          b.endless[a] = sc.periodic[a] && b.min[a] <= sc.domain_min[a] + 1e-9 * sc.spacing &&
                         b.max[a] >= sc.domain_max[a] - 1e-9 * sc.spacing;
        // Its particles sit on min + (k + 1/2) d: a box of 1.5 spacings put its last column on its
        // face, half a spacing from the fluid (the piston of the wave flume at d = 0.02 m let
        // water through under it).
        for (int a = 0; a < D; ++a) {
          const double cells = (b.max[a] - b.min[a]) / sc.spacing;
          if (std::abs(cells - std::round(cells)) > 1e-6 * std::max(1.0, cells)) {
            std::ostringstream m;
            m << "is " << cells << " spacings wide on axis " << a
              << ": a box body takes whole spacings (its particles sit on min + (k + 1/2) d); make max - min a multiple of "
              << sc.spacing;
            need(false, "max", m.str());
          }
        }
      } else {
        need(where("solid", i, "centre") && where("solid", i, "radius"), "centre", "(a " + b.shape + ") needs centre and radius");
        read_round("solid", i, b);
        std::tie(b.min, b.max) = round_box(b.centre, b.radius, D == 3 && b.shape == "cylinder" ? b.axis : -1,
                                           sc.domain_min, sc.domain_max);
      }
      b.container = *t["container"].value<bool>();
      need(!b.container || b.mesh < 0 || sc.meshes[b.mesh].mesh->closed(), "container",
           "is an open [[mesh]]: a container needs a closed one (an open surface already holds fluid on its normals' side)");
      const auto [outer_min, outer_max] = solid_extent(b);
      need(inside(outer_min, outer_max), b.shape == "box" ? "min" : b.shape == "mesh" ? "mesh" : "centre",
           b.container ? "lies (partly) outside the domain with its layers" : "lies (partly) outside the domain");
      for (auto& other : sc.solids)
        need(other.name != b.name, "name", "has the name of another solid, '" + b.name + "'");
      for (std::size_t k = 0; k < sc.solids.size(); ++k) {
        const SolidSpec& other = sc.solids[k];
        const auto [other_min, other_max] = solid_extent(other);
        if (b.container != other.container)  // the body must lie inside the container
          need(body_in_container(b.container ? other : b, b.container ? b : other), "shape",
               b.container ? "holds [[solid]] '" + other.name + "' only partly (bodies must lie inside a container, clear of its wall)"
                           : "lies (partly) outside container '" + other.name + "' (bodies must lie inside a container, clear of its wall)");
        else
          need(!boxes_overlap(outer_min, outer_max, other_min, other_max, 1e-6 * sc.spacing), "shape",
               "overlaps [[solid]] '" + other.name + "' (their particles would sit on each other)");
      }
      FluidBlock extent;
      extent.min = outer_min, extent.max = outer_max;
      for (std::size_t k = 0; k < sc.walls.size(); ++k)
        need(!fluid_in_wall_layers(extent, sc.walls[k], sc.spacing, 1e-6 * sc.spacing), "shape",
             "reaches into the particle layers of [[wall]] #" + std::to_string(k) + " (their particles would sit on each other)");
      sc.solids.push_back(std::move(b));
    }
  }
  // Imported particles are placed as given, not cut around bodies: one inside a body (outside a
  // container) is an error. Not one merely near it: a body's first wall layer lies half a spacing
  // inside its surface (a container's outside it), and a settled run's fluid comes as close as
  // that to the surface, closer than the generator's margin (a round tank's own frame was refused
  // when the test was half a spacing).
  for (std::size_t i = 0; i < sc.imports.size() && !sc.solids.empty(); ++i) {
    auto overlap = [&](auto dim) {
      constexpr int DD = decltype(dim)::value;
      for (std::size_t k = 0; k < sc.solids.size(); ++k) {
        SolidShape<DD> shape(sc.solids[k], sc.solids[k].mesh >= 0 ? sc.meshes[sc.solids[k].mesh].mesh : nullptr);
        for (auto& p : sc.imports[i].particles->position) {
          Vec<DD> x;
          for (int a = 0; a < DD; ++a) x[a] = p[a];
          if (shape.within(x, 0.0)) {
            std::ostringstream m;
            m << "[[import]] #" << i << ": a particle at (" << p[0] << ", " << p[1] << (DD == 3 ? ", " + std::to_string(p[2]) : "")
              << ") lies " << (sc.solids[k].container ? "outside container '" : "in [[solid]] '")
              << sc.solids[k].name << "'";
            val.fail(where("import", i, "file"), path_of("import", i, "file"), m.str());
          }
        }
      }
    };
    if (D == 2)
      overlap(std::integral_constant<int, 2>{});
    else
      overlap(std::integral_constant<int, 3>{});
  }
  // Fluid on top of wall particles or of other fluid: r = 0 pairs, not a flow. Shallow-water walls
  // are mirrored ghosts, not particles, so only the fluid-fluid test applies there.
  const double overlap_tol = 1e-6 * sc.spacing;
  for (std::size_t i = 0; i < sc.fluid.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k)
      if (boxes_overlap(sc.fluid[i].min, sc.fluid[i].max, sc.fluid[k].min, sc.fluid[k].max, overlap_tol))
        val.fail(where("fluid", i, "min"), path_of("fluid", i, "min"),
                 "[[fluid]] #" + std::to_string(i) + " overlaps [[fluid]] #" + std::to_string(k) +
                     " (their particles would sit on each other)");
    for (std::size_t k = 0; !swe && k < sc.walls.size(); ++k)
      if (fluid_in_wall_layers(sc.fluid[i], sc.walls[k], sc.spacing, overlap_tol))
        val.fail(where("fluid", i, "min"), path_of("fluid", i, "min"),
                 "[[fluid]] #" + std::to_string(i) + " reaches into the " + std::to_string(sc.walls[k].layers) +
                     " particle layers of [[wall]] #" + std::to_string(k) +
                     "; keep fluid blocks inside the wall's min..max (the layers lie outside it)");
  }
  if (auto* arr = root["fixed_pressure"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      FixedPressureBox b{vec_of(*where("fixed_pressure", i, "min")), vec_of(*where("fixed_pressure", i, "max")),
                         std::vector<double>(D, 0.0), *root["fixed_pressure"][i]["pressure"].value<double>()};
      if (auto* g = where("fixed_pressure", i, "gradient")) b.gradient = vec_of(*g);
      for (int a = 0; a < D; ++a)
        if (!(b.max[a] > b.min[a]))
          val.fail(where("fixed_pressure", i, "max"), path_of("fixed_pressure", i, "max"),
                   "[[fixed_pressure]] #" + std::to_string(i) + " is empty (max <= min)");
      if (!std::isfinite(b.pressure))
        val.fail(where("fixed_pressure", i, "pressure"), path_of("fixed_pressure", i, "pressure"),
                 "[[fixed_pressure]] #" + std::to_string(i) + ": pressure must be finite");
      sc.fixed_pressure.push_back(std::move(b));
    }
  }
  if (auto* arr = root["probe"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      ProbeSpec p{*root["probe"][i]["name"].value<std::string>(), *root["probe"][i]["type"].value<std::string>(), {}};
      if (auto* pos = where("probe", i, "position")) p.position = vec_of(*pos);
      if ((p.type == "pressure" || p.type == "water_height" || p.type == "solid_displacement" || p.type == "solid_stress") &&
          p.position.empty())
        val.fail(&(*arr)[i], path_of("probe", i, "position"), "[[probe]] '" + p.name + "' of type " + p.type + " needs a position");
      if (!p.position.empty() && !inside(p.position, p.position))
        val.fail(where("probe", i, "position"), path_of("probe", i, "position"), "[[probe]] '" + p.name + "' lies outside the domain");
      if (p.type == "force") {
        auto solid_name = root["probe"][i]["solid"].value<std::string>();
        if (!solid_name)
          val.fail(&(*arr)[i], path_of("probe", i, "solid"), "[[probe]] '" + p.name + "' of type force needs `solid`, the name of a [[solid]]");
        for (std::size_t k = 0; k < sc.solids.size(); ++k)
          if (sc.solids[k].name == *solid_name) p.solid = static_cast<int>(k);
        if (p.solid < 0)
          val.fail(where("probe", i, "solid"), path_of("probe", i, "solid"), "[[probe]] '" + p.name + "': there is no [[solid]] named '" + *solid_name + "'");
        p.axis = static_cast<int>(*root["probe"][i]["axis"].value<long long>());
        if (p.axis >= D)
          val.fail(where("probe", i, "axis"), path_of("probe", i, "axis"), "[[probe]] '" + p.name + "': axis must be below the dimension");
      }
      if (p.type == "solid_displacement" || p.type == "solid_stress") {
        p.axis = static_cast<int>(*root["probe"][i]["axis"].value<long long>());
        if (p.axis >= D)
          val.fail(where("probe", i, "axis"), path_of("probe", i, "axis"), "[[probe]] '" + p.name + "': axis must be below the dimension");
      }
      if (p.type.rfind("solid_", 0) == 0 && !root["elastic"])
        val.fail(where("probe", i, "type"), path_of("probe", i, "type"), "[[probe]] '" + p.name + "': " + p.type + " needs an [[elastic]] body");
      if (p.type == "front_depth" && !swe)
        val.fail(where("probe", i, "type"), path_of("probe", i, "type"), "[[probe]] '" + p.name + "': front_depth is for method swe");
      for (auto& q : sc.probes)
        if (q.name == p.name) val.fail(where("probe", i, "name"), path_of("probe", i, "name"), "two probes are named '" + p.name + "'");
      sc.probes.push_back(std::move(p));
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
      if (auto* v = where("metric", i, "position")) spec.position = vec_of(*v);
      spec.max_shift = *m["max_shift"].value<double>();
      spec.t_max = *m["t_max"].value<double>();
      for (auto& q : sc.metrics)
        if (q.name == spec.name) val.fail(where("metric", i, "name"), path_of("metric", i, "name"), "two metrics are named '" + spec.name + "'");
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
      const bool reads_probe =
          spec.type == "dam_break_front" || spec.type == "probe_csv" || spec.type == "rotating_square_pressure";
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
          val.fail(where("metric", i, "probe"), path_of("metric", i, "probe"), "[[metric]] '" + spec.name + "': probe '" + spec.probe + "' is not a pressure probe");
        if (spec.type == "dam_break_front" && probe->type != "surge_front")
          val.fail(where("metric", i, "probe"), path_of("metric", i, "probe"), "[[metric]] '" + spec.name + "': probe '" + spec.probe + "' is not a surge_front");
      }
      if (auto r = m["reference"].value<std::string>()) {
        auto file = std::filesystem::path(*r);
        if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
        spec.reference = file.string();
      } else if (spec.type == "dam_break_front") {
        spec.reference = (std::filesystem::path(RYUSHI_TOOLS_DIR) / "reference" / "martin_moyce_1952_n2_2.csv").string();
      } else if (spec.type == "probe_csv") {
        val.fail(&(*arr)[i], path_of("metric", i, "reference"), "[[metric]] '" + spec.name + "' of type probe_csv needs a reference CSV");
      }
      if (!spec.reference.empty()) {
        try {
          spec.table = read_reference_table(spec.reference);
        } catch (const SceneError& e) {
          val.fail(where("metric", i, "reference") ? where("metric", i, "reference") : &(*arr)[i],
                   path_of("metric", i, "reference"), std::string("metric.reference: ") + e.what());
        }
      }
      FluidBlock first;  // an imports-only scene has no block to take defaults from
      first.min.assign(D, 0.0), first.max.assign(D, 0.0);
      if (!sc.fluid.empty()) first = sc.fluid.front();
      auto need = [&](bool ok, const char* key, const std::string& what) {
        if (!ok)
          val.fail(where("metric", i, key) ? where("metric", i, key) : &(*arr)[i], path_of("metric", i, key),
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
        need(std::isfinite(spec.force) && spec.force != 0, "force", "needs the body force `force` (non-zero)");
        need(sc.viscosity > 0, "type", "needs a viscous fluid ([material] viscosity > 0)");
        if (spec.position.empty()) spec.position = {0.5 * (first.min[0] + first.max[0]), 0.0};
        need(spec.position.size() >= 2, "position", "takes position = [x of the column, y of the wall]");
      }
      if (spec.type == "ritter_depth") {
        need(swe, "type", "is for method swe");
        if (std::isnan(spec.depth)) spec.depth = first.depth;
        need(spec.depth > 0, "depth", "needs the depth behind the dam (`depth` > 0, or a first [[fluid]] with depth)");
        if (spec.position.empty()) spec.position = first.max;
      }
      if (spec.type == "rotating_square_pressure") {
        need(D == 2, "type", "is for 2D scenes");
        spec.angular_velocity = first.angular_velocity;
        need(spec.angular_velocity != 0, "type", "needs the first [[fluid]] block to rotate (angular_velocity)");
        if (spec.width <= 0) spec.width = first.max[0] - first.min[0];
        if (spec.position.empty())
          for (int a = 0; a < D; ++a) spec.position.push_back(0.5 * (first.min[a] + first.max[a]));
      }
      if (spec.type == "hydrostatic_pressure" && std::isnan(spec.surface))
        for (auto& b : sc.fluid) spec.surface = std::isnan(spec.surface) ? b.max.back() : std::max(spec.surface, b.max.back());
      sc.metrics.push_back(std::move(spec));
    }
  }
  if (auto* arr = root["systems"].as_array())
    for (auto& e : *arr) {
      SystemSpec s{*(*e.as_table())["name"].value<std::string>(), *e.as_table()};
      s.params.erase("name");
      sc.systems.push_back(std::move(s));
    }
  // The neighbour search tiles a periodic axis with at least three cells of its search radius:
  // the support, plus the Verlet skin, plus (MPS, ISPH) the step's own motion (their
  // parameters' search_radius()).
  const double search_radius =
      sc.support_radius() + sc.neighbour_skin * sc.spacing + hooks.step_motion * sc.cfl * sc.spacing;
  for (int a = 0; a < D; ++a)
    if (sc.periodic[a] && (sc.domain_max[a] - sc.domain_min[a]) < 3 * search_radius)
      val.fail(get("domain", "periodic").as_array()->get(a), "domain.periodic",
               "periodic axis " + std::to_string(a) + " is shorter than three neighbour-search radii (3 x (support + neighbour_skin spacings" +
                   std::string(hooks.step_motion > 0 ? " + the step's motion" : "") + ") = " + std::to_string(3 * search_radius) + " m)");
  if (hooks.solves_pressure && sc.solver.preconditioner == "multigrid")
    for (int a = 0; a < D; ++a)
      if (sc.periodic[a])
        val.fail(get("domain", "periodic").as_array()->get(a), "domain.periodic",
                 "the bucket multigrid does not wrap periodic axes (axis " + std::to_string(a) +
                     "); use [solver] preconditioner = \"jacobi\" with a periodic domain");
  if (sc.fixed_dt > sc.end_time) val.fail(root["time"]["dt"].node(), "time.dt", "time.dt is larger than time.end");
  load_heat_and_rheology(root, val, sc);
  load_elastic(root, val, sc);
  if (hooks.validate) hooks.validate(sc, root, val);
  // The neighbour search's cell grid covers the domain with cells of the support radius (4
  // bytes per cell): a domain far larger than the particles' extent at a tiny spacing (1e-6 m
  // particles in a 1e4 m box) would ask for more memory than the machine has.
  {
    double cells = 1;
    for (int a = 0; a < D; ++a) cells *= std::max(1.0, std::ceil((sc.domain_max[a] - sc.domain_min[a]) / sc.support_radius()));
    if (cells > double(1ULL << 28)) {
      std::ostringstream m;
      m << "the domain spans " << cells << " cells of the support radius " << sc.support_radius()
        << " m (the neighbour search allows 2^28 = 268435456): shrink [domain] towards the particles' extent";
      val.fail(get("domain", "max").as_array(), "domain.max", m.str());
    }
  }
  return sc;
}

}  // namespace ryushi
