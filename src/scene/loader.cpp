#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "kernels/kernel.hpp"
#include "scene/load_common.hpp"
#include "scene/load_elastic.hpp"
#include "scene/load_heat_rheology.hpp"
#include "scene/load_method.hpp"
#include "scene/load_parts.hpp"
#include "scene/scene.hpp"
#include "scene/schema.hpp"
#include "scene/validator.hpp"

namespace ryushi {

double Scene::fluid_height() const {
  double h = 0;
  for (auto& b : fluid) h = std::max(h, b.max.back() - b.min.back());
  for (auto& import : imports) {  // from the lowest particle's bottom to the highest one's top
    double low = 1e300, high = -1e300;
    for (auto& x : import.particles->position)
      low = std::min(low, x[dimension - 1]), high = std::max(high, x[dimension - 1]);
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

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides,
                 const std::string* text) {
  std::string source;
  if (text) {
    source = *text;
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw SceneError(path + ": cannot read the scene file (" +
                       (std::filesystem::exists(path) ? "permission denied" : "no such file") + ")");
    std::ostringstream all;
    all << in.rdbuf();
    source = all.str();
  }
  toml::table root;
  try {
    root = toml::parse(source, path);
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
      val.fail_at(&k.source(), name,
                  "unknown section '" + name + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
    }
  }
  // The sections the file (or --set) wrote; the others get their defaults inserted below.
  std::set<std::string> written;
  std::set<std::string> written_keys;  // "section.key" of the keys it wrote (in any entry of [[section]])
  for (auto& [k, node] : root) {
    written.insert(std::string(k.str()));
    if (auto* t = node.as_table())
      for (auto& [key, _] : *t) written_keys.insert(std::string(k.str()) + "." + std::string(key.str()));
    if (auto* entries = node.as_array())
      for (auto& entry : *entries)
        if (auto* t = entry.as_table())
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
      if (s.required)
        val.fail(
            nullptr, s.name,
            "missing required section " + (s.array_of_tables ? "[[" + s.name + "]]" : "[" + s.name + "]"));
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
      if (!name_node || !name_node->is_string())
        val.fail(&(*arr)[i], prefix + "name", label + " needs name = \"<registered system>\"");
      std::string sys = *name_node->value<std::string>();
      if (!find_system_keys(sys)) {
        std::string hint = closest_name(sys, system_key_names());
        val.fail(
            name_node, prefix + "name",
            "no system registered as '" + sys + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
      }
      auto keys = find_system_keys(sys)->keys;
      keys.insert(keys.begin(), s.keys.begin(), s.keys.end());
      val.check_table(t, label + " (" + sys + ")", prefix, keys, &(*arr)[i]);
    }
  }

  Scene sc;
  sc.path = path;
  sc.text = source;
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
  // A section, key or value that belongs to another method ([swe] under wcsph, [time] step_rule
  // under mps, [[probe]] type = "front_depth" under isph).
  check_owned_by_other_methods(root, val, sc, written, written_keys);
  // The method's own sections (the shallow water's [swe], [bed]...), read first: the defaults
  // below may depend on them.
  if (hooks.read_sections) hooks.read_sections(sc, root, val);
  sc.disorder = root["particles"]["disorder"].value_or(0.0);
  sc.seed = static_cast<std::uint64_t>(root["particles"]["seed"].value_or(1LL));
  sc.kernel =
      root["particles"]["kernel"].value_or(hooks.kernel ? hooks.kernel(sc) : std::string("wendland_c2"));
  // After the kernel: a method's default width may depend on it.
  sc.smoothing_ratio =
      root["particles"]["smoothing_ratio"].value_or(hooks.smoothing_ratio ? hooks.smoothing_ratio(sc) : 1.5);
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
  sc.steady_tolerance = *get("time", "steady_tolerance").value<double>();
  sc.steady_window = *get("time", "steady_window").value<double>();
  sc.dt_min = *get("time", "dt_min").value<double>();
  sc.step_rule = *get("time", "step_rule").value<std::string>();
  sc.output_interval = root["output"]["interval"].value_or(sc.end_time / 20.0);
  if (sc.output_interval <= 0) sc.output_interval = sc.end_time / 20.0;
  sc.probe_interval = root["output"]["probe_interval"].value_or(sc.output_interval / 10.0);
  if (sc.probe_interval <= 0) sc.probe_interval = sc.output_interval / 10.0;
  sc.checkpoint_interval = *get("output", "checkpoint_interval").value<double>();
  for (auto& e : *root["output"]["fields"].as_array()) sc.output_fields.push_back(*e.value<std::string>());
  // Consistency checks that need more than one key.
  for (int a = 0; a < D; ++a)
    if (!(sc.domain_max[a] > sc.domain_min[a]))
      val.fail(get("domain", "max").as_array()->get(a), "domain.max",
               "domain.max must exceed domain.min on every axis (axis " + std::to_string(a) + ")");
  load_bodies(root, val, sc, default_layers, covering);
  load_measurements(root, val, sc);
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
               "periodic axis " + std::to_string(a) +
                   " is shorter than three neighbour-search radii (3 x (support + neighbour_skin spacings" +
                   std::string(hooks.step_motion > 0 ? " + the step's motion" : "") +
                   ") = " + std::to_string(3 * search_radius) + " m)");
  if (hooks.solves_pressure && sc.solver.preconditioner == "multigrid")
    for (int a = 0; a < D; ++a)
      if (sc.periodic[a])
        val.fail(get("domain", "periodic").as_array()->get(a), "domain.periodic",
                 "the bucket multigrid does not wrap periodic axes (axis " + std::to_string(a) +
                     "); use [solver] preconditioner = \"jacobi\" with a periodic domain");
  if (sc.fixed_dt > sc.end_time)
    val.fail(root["time"]["dt"].node(), "time.dt", "time.dt is larger than time.end");
  check_kernel_support(root, val, sc);
  load_health(root, sc);
  load_heat_and_rheology(root, val, sc);
  load_elastic(root, val, sc);
  if (hooks.validate) hooks.validate(sc, root, val);
  // A [[systems]] entry that needs what this method (with these keys) does not provide.
  const auto provided = hooks.provides ? hooks.provides(sc) : std::vector<std::string>{};
  for (std::size_t i = 0; i < sc.systems.size(); ++i)
    for (auto& need : find_system_keys(sc.systems[i].name)->needs)
      if (std::find(provided.begin(), provided.end(), need) == provided.end())
        val.fail(root["systems"][i]["name"].node(), "systems." + std::to_string(i) + ".name",
                 "system '" + sc.systems[i].name + "' needs " + need + ", which method '" + sc.method +
                     "' does not provide with this scene's [method] keys");
  for (std::size_t i = 0; i < sc.systems.size(); ++i)
    if (auto& check = find_system_keys(sc.systems[i].name)->validate) check(sc, root, i, val);
  // The neighbour search's cell grid covers the domain with cells of the support radius (4
  // bytes per cell): a domain far larger than the particles' extent at a tiny spacing (1e-6 m
  // particles in a 1e4 m box) would ask for more memory than the machine has.
  {
    double cells = 1;
    for (int a = 0; a < D; ++a)
      cells *= std::max(1.0, std::ceil((sc.domain_max[a] - sc.domain_min[a]) / sc.support_radius()));
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
