// The scene's bodies: meshes, fluid blocks, imported particles, walls, solids and fixed-pressure
// boxes, each checked at its key, then against each other (overlaps, bodies in containers).
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <tuple>

#include "geometry/solid_shape.hpp"
#include "scene/load_common.hpp"
#include "scene/load_parts.hpp"
#include "scene/overlaps.hpp"
#include "scene/particle_import.hpp"
#include "scene/validator.hpp"

namespace ryushi {

void load_bodies(toml::table& root, Validator& val, Scene& sc, int default_layers, int covering) {
  const std::string& path = sc.path;
  const int D = sc.dimension;
  const bool walls_hold_particles = find_method_spec(sc.method)->hooks.walls_hold_particles;
  const SceneEntries at{root, sc};
  if (auto* arr = root["mesh"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      auto t = root["mesh"][i];
      MeshSpec m{*t["name"].value<std::string>(), *t["file"].value<std::string>(), nullptr};
      const std::string label = "[[mesh]] '" + m.name + "'";
      if (D != 3)
        val.fail(at.where("mesh", i, "file"), path_of("mesh", i, "file"),
                 label + ": meshes are for 3D scenes");
      for (auto& other : sc.meshes)
        if (other.name == m.name)
          val.fail(at.where("mesh", i, "name"), path_of("mesh", i, "name"),
                   "two meshes are named '" + m.name + "'");
      auto file = std::filesystem::path(m.file);
      if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
      MeshTransform transform;
      transform.scale = *t["scale"].value<double>();
      auto rotate = vec_of(*at.where("mesh", i, "rotate")),
           translate = vec_of(*at.where("mesh", i, "translate"));
      for (int a = 0; a < 3; ++a)
        transform.rotate_degrees[a] = rotate[a], transform.translate[a] = translate[a];
      try {
        m.mesh = TriangleMesh::read(file.string(), transform);
      } catch (const MeshError& e) {
        val.fail(at.where("mesh", i, "file"), path_of("mesh", i, "file"), label + ": " + e.what());
      }
      sc.meshes.push_back(std::move(m));
    }
  }
  // A [[mesh]] by name: its index, or an error at the key.
  auto mesh_named = [&](const char* section, std::size_t i, const std::string& label) -> int {
    const std::string name = *root[section][i]["mesh"].value<std::string>();
    for (std::size_t k = 0; k < sc.meshes.size(); ++k)
      if (sc.meshes[k].name == name) return static_cast<int>(k);
    val.fail(at.where(section, i, "mesh"), path_of(section, i, "mesh"),
             label + ": there is no [[mesh]] named '" + name + "'");
  };
  // centre, radius and axis of a round [[fluid]] block or [[solid]] body.
  auto read_round = [&](const char* section, std::size_t i, auto& b) {
    b.centre = vec_of(*at.where(section, i, "centre"));
    b.radius = *root[section][i]["radius"].value<double>();
    b.axis = static_cast<int>(*root[section][i]["axis"].value<long long>());
  };
  if (auto* arr = root["fluid"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      FluidBlock b;
      const std::string label = "[[fluid]] #" + std::to_string(i);
      b.shape = *root["fluid"][i]["shape"].value<std::string>();
      if (b.shape == "box") {
        if (!at.where("fluid", i, "min") || !at.where("fluid", i, "max"))
          val.fail(&(*arr)[i], path_of("fluid", i, "min"), label + " (a box) needs min and max");
        b.min = vec_of(*at.where("fluid", i, "min"));
        b.max = vec_of(*at.where("fluid", i, "max"));
      } else {
        if (!at.where("fluid", i, "centre") || !at.where("fluid", i, "radius"))
          val.fail(&(*arr)[i], path_of("fluid", i, "centre"),
                   label + " (a " + b.shape + ") needs centre and radius");
        read_round("fluid", i, b);
        const bool given = at.where("fluid", i, "min") && at.where("fluid", i, "max");
        if (D == 3 && b.shape == "cylinder" && !given)
          val.fail(&(*arr)[i], path_of("fluid", i, "min"),
                   label + " (a 3D cylinder) needs min and max for its extent along its axis");
        std::tie(b.min, b.max) =
            given ? std::pair{vec_of(*at.where("fluid", i, "min")), vec_of(*at.where("fluid", i, "max"))}
                  : round_box(b.centre, b.radius, -1, {}, {});
      }
      if (auto* v = at.where("fluid", i, "velocity")) {
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
      if (at.where("fluid", i, "mesh")) {
        b.mesh = mesh_named("fluid", i, label);
        if (!sc.meshes[b.mesh].mesh->closed())
          val.fail(at.where("fluid", i, "mesh"), path_of("fluid", i, "mesh"),
                   label + ": [[mesh]] '" + sc.meshes[b.mesh].name +
                       "' is not closed, so it has no inside to fill (it can be a [[solid]] surface)");
      }
      if (auto* pr = at.where("fluid", i, "pressure")) {
        b.pressure_expression = field_text(*pr);
        b.pressure_where = val.location(pr, path_of("fluid", i, "pressure"));
      }
      b.angular_velocity = *root["fluid"][i]["angular_velocity"].value<double>();
      if (auto v = root["fluid"][i]["depth"].value<double>()) b.depth = *v;
      if (auto v = root["fluid"][i]["surface_elevation"].value<double>()) b.surface_elevation = *v;
      if (b.angular_velocity != 0 && D != 2)
        val.fail(at.where("fluid", i, "angular_velocity"), path_of("fluid", i, "angular_velocity"),
                 "[[fluid]] #" + std::to_string(i) + ": angular_velocity is for 2D scenes");
      for (int a = 0; a < D; ++a)
        if (std::lround((b.max[a] - b.min[a]) / sc.spacing) < 1)
          val.fail(at.where("fluid", i, "max"), path_of("fluid", i, "max"),
                   "[[fluid]] #" + std::to_string(i) +
                       " is empty: thinner than one particle spacing on axis " + std::to_string(a));
      for (int a = 0; a < D; ++a) {
        double n = std::lround((b.max[a] - b.min[a]) / sc.spacing), filled = n * sc.spacing;
        if (std::abs(filled - (b.max[a] - b.min[a])) > 1e-6 * sc.spacing)
          spdlog::warn(
              "{}: [[fluid]] #{} is {} m wide on axis {}, not a multiple of the spacing {} m: filled with {} "
              "particles ({} m)",
              path, i, b.max[a] - b.min[a], a, sc.spacing, n, filled);
      }
      if (!at.inside(b.min, b.max))
        val.fail(at.where("fluid", i, "min"), path_of("fluid", i, "min"),
                 "[[fluid]] #" + std::to_string(i) + " lies (partly) outside the domain");
      sc.fluid.push_back(std::move(b));
    }
  }
  if (auto* arr = root["import"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      ImportSpec spec{*root["import"][i]["file"].value<std::string>(), nullptr};
      const std::string label = "[[import]] #" + std::to_string(i);
      auto file = std::filesystem::path(spec.file);
      if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
      try {
        spec.particles = import_particles(file.string(), D);
      } catch (const ImportError& e) {
        val.fail(at.where("import", i, "file"), path_of("import", i, "file"), label + ": " + e.what());
      }
      for (auto& x : spec.particles->position) {
        std::vector<double> point(x.begin(), x.begin() + D);
        if (!at.inside(point, point)) {
          std::ostringstream m;
          m << label << ": a particle at (" << x[0] << ", " << x[1]
            << (D == 3 ? ", " + std::to_string(x[2]) : "") << ") lies outside the domain";
          val.fail(at.where("import", i, "file"), path_of("import", i, "file"), m.str());
        }
      }
      sc.imports.push_back(std::move(spec));
    }
  }
  if (sc.fluid.empty() && sc.imports.empty() && !root["elastic"])
    val.fail(root["fluid"].node(), "fluid",
             "the scene has no [[fluid]] block, no [[import]] and no [[elastic]] body");
  if (auto* arr = root["wall"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      WallBox w{vec_of(*at.where("wall", i, "min")),
                vec_of(*at.where("wall", i, "max")),
                static_cast<int>(root["wall"][i]["layers"].value_or(static_cast<long long>(default_layers))),
                *root["wall"][i]["open_top"].value<bool>(),
                {},
                {}};
      w.open_ends.assign(D, false);
      if (auto* open = root["wall"][i]["open_ends"].as_array())
        for (int a = 0; a < D; ++a) w.open_ends[a] = *(*open)[a].value<bool>();
      for (int a = 0; a < D; ++a)
        if (!(w.max[a] > w.min[a]))
          val.fail(at.where("wall", i, "max"), path_of("wall", i, "max"),
                   "[[wall]] #" + std::to_string(i) + " is empty (max <= min)");
      double thick = w.layers * sc.spacing;
      std::vector<double> lo = w.min, hi = w.max;
      for (int a = 0; a < D; ++a) {
        if (w.open_ends[a]) continue;
        lo[a] -= thick;
        if (a < D - 1 || !w.open_top) hi[a] += thick;
      }
      if (!at.inside(lo, hi))
        val.fail(at.where("wall", i, "min"), path_of("wall", i, "min"),
                 "[[wall]] #" + std::to_string(i) + " with its " + std::to_string(w.layers) +
                     " layers lies outside the domain");
      // Layers that cover the support, unless the method keeps fewer (ISPH's one with normals;
      // its resolve hook checks them).
      if (default_layers >= covering && thick + 1e-12 < sc.support_radius()) {
        std::ostringstream m;
        m << "[[wall]] #" << i << ": " << w.layers << " layers (" << thick
          << " m) do not cover the support radius " << sc.support_radius()
          << " m; use layers >= " << covering;
        val.fail(root["wall"][i]["layers"].node() ? root["wall"][i]["layers"].node() : &(*arr)[i],
                 path_of("wall", i, "layers"), m.str());
      }
      sc.walls.push_back(std::move(w));
    }
  }
  // The box a body's particles occupy: a container's layers lie outside its shape.
  auto solid_extent = [&](const SolidSpec& b) {
    std::vector<double> lo = b.min, hi = b.max;
    if (b.container)
      for (int a = 0; a < D; ++a)
        if (!(D == 3 && b.shape == "cylinder" && a == b.axis))
          lo[a] -= b.layers * sc.spacing, hi[a] += b.layers * sc.spacing;
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
        if (!ok)
          val.fail(at.where("solid", i, key) ? at.where("solid", i, key) : &(*arr)[i],
                   path_of("solid", i, key), label + " " + what);
      };
      SolidSpec b;
      b.name = t["name"].value_or("solid" + std::to_string(i));
      b.shape = *t["shape"].value<std::string>();
      b.layers = static_cast<int>(t["layers"].value_or(static_cast<long long>(default_layers)));
      b.velocity.assign(D, 0.0);
      if (auto* v = at.where("solid", i, "velocity")) b.velocity = vec_of(*v);
      if (auto* motion = at.where("solid", i, "displacement")) {
        need(!at.where("solid", i, "velocity"), "displacement",
             "has both velocity (a surface sliding in place) and displacement (moving particles); give one");
        for (auto& e : *motion->as_array()) b.displacement.push_back(field_text(e));
        b.displacement_where = val.location(motion, path_of("solid", i, "displacement"));
      }
      if (auto table = t["displacement_table"].value<std::string>()) {
        need(!at.where("solid", i, "velocity") && !at.where("solid", i, "displacement"), "displacement_table",
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
        need(at.where("solid", i, "mesh"), "shape", "(a mesh) needs `mesh`, the name of a [[mesh]]");
        b.mesh = mesh_named("solid", i, label);
        const auto& mesh = *sc.meshes[b.mesh].mesh;
        // An open surface's layers lie behind it: the box grows by them.
        const double behind = mesh.closed() ? 0.0 : b.layers * sc.spacing;
        b.min.assign(D, 0.0), b.max.assign(D, 0.0);
        for (int a = 0; a < D; ++a) b.min[a] = mesh.lower()[a] - behind, b.max[a] = mesh.upper()[a] + behind;
      } else if (b.shape == "box") {
        need(at.where("solid", i, "min") && at.where("solid", i, "max"), "min", "(a box) needs min and max");
        b.min = vec_of(*at.where("solid", i, "min"));
        b.max = vec_of(*at.where("solid", i, "max"));
        for (int a = 0; a < D; ++a)
          need(b.max[a] > b.min[a], "max", "is empty (max <= min on axis " + std::to_string(a) + ")");
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
              << ": a box body takes whole spacings (its particles sit on min + (k + 1/2) d); make max - min "
                 "a multiple of "
              << sc.spacing;
            need(false, "max", m.str());
          }
        }
      } else {
        need(at.where("solid", i, "centre") && at.where("solid", i, "radius"), "centre",
             "(a " + b.shape + ") needs centre and radius");
        read_round("solid", i, b);
        std::tie(b.min, b.max) = round_box(b.centre, b.radius, D == 3 && b.shape == "cylinder" ? b.axis : -1,
                                           sc.domain_min, sc.domain_max);
      }
      b.container = *t["container"].value<bool>();
      need(!b.container || b.mesh < 0 || sc.meshes[b.mesh].mesh->closed(), "container",
           "is an open [[mesh]]: a container needs a closed one (an open surface already holds fluid on its "
           "normals' side)");
      const auto [outer_min, outer_max] = solid_extent(b);
      need(at.inside(outer_min, outer_max),
           b.shape == "box"    ? "min"
           : b.shape == "mesh" ? "mesh"
                               : "centre",
           b.container ? "lies (partly) outside the domain with its layers"
                       : "lies (partly) outside the domain");
      for (auto& other : sc.solids)
        need(other.name != b.name, "name", "has the name of another solid, '" + b.name + "'");
      for (std::size_t k = 0; k < sc.solids.size(); ++k) {
        const SolidSpec& other = sc.solids[k];
        const auto [other_min, other_max] = solid_extent(other);
        if (b.container != other.container)  // the body must lie inside the container
          need(body_in_container(b.container ? other : b, b.container ? b : other), "shape",
               b.container ? "holds [[solid]] '" + other.name +
                                 "' only partly (bodies must lie inside a container, clear of its wall)"
                           : "lies (partly) outside container '" + other.name +
                                 "' (bodies must lie inside a container, clear of its wall)");
        else
          need(!boxes_overlap(outer_min, outer_max, other_min, other_max, 1e-6 * sc.spacing), "shape",
               "overlaps [[solid]] '" + other.name + "' (their particles would sit on each other)");
      }
      FluidBlock extent;
      extent.min = outer_min, extent.max = outer_max;
      for (std::size_t k = 0; k < sc.walls.size(); ++k)
        need(!fluid_in_wall_layers(extent, sc.walls[k], sc.spacing, 1e-6 * sc.spacing), "shape",
             "reaches into the particle layers of [[wall]] #" + std::to_string(k) +
                 " (their particles would sit on each other)");
      sc.solids.push_back(std::move(b));
    }
  }
  check_imports(root, val, sc, walls_hold_particles);
  // Fluid on top of wall particles or of other fluid: r = 0 pairs, not a flow. Shallow-water walls
  // are mirrored ghosts, not particles, so only the fluid-fluid test applies there.
  const double overlap_tol = 1e-6 * sc.spacing;
  for (std::size_t i = 0; i < sc.fluid.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k)
      if (boxes_overlap(sc.fluid[i].min, sc.fluid[i].max, sc.fluid[k].min, sc.fluid[k].max, overlap_tol))
        val.fail(at.where("fluid", i, "min"), path_of("fluid", i, "min"),
                 "[[fluid]] #" + std::to_string(i) + " overlaps [[fluid]] #" + std::to_string(k) +
                     " (their particles would sit on each other)");
    for (std::size_t k = 0; walls_hold_particles && k < sc.walls.size(); ++k)
      if (fluid_in_wall_layers(sc.fluid[i], sc.walls[k], sc.spacing, overlap_tol))
        val.fail(at.where("fluid", i, "min"), path_of("fluid", i, "min"),
                 "[[fluid]] #" + std::to_string(i) + " reaches into the " +
                     std::to_string(sc.walls[k].layers) + " particle layers of [[wall]] #" +
                     std::to_string(k) +
                     "; keep fluid blocks inside the wall's min..max (the layers lie outside it)");
  }
  if (auto* arr = root["fixed_pressure"].as_array()) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      FixedPressureBox b{vec_of(*at.where("fixed_pressure", i, "min")),
                         vec_of(*at.where("fixed_pressure", i, "max")), std::vector<double>(D, 0.0),
                         *root["fixed_pressure"][i]["pressure"].value<double>()};
      if (auto* g = at.where("fixed_pressure", i, "gradient")) b.gradient = vec_of(*g);
      for (int a = 0; a < D; ++a)
        if (!(b.max[a] > b.min[a]))
          val.fail(at.where("fixed_pressure", i, "max"), path_of("fixed_pressure", i, "max"),
                   "[[fixed_pressure]] #" + std::to_string(i) + " is empty (max <= min)");
      if (!std::isfinite(b.pressure))
        val.fail(at.where("fixed_pressure", i, "pressure"), path_of("fixed_pressure", i, "pressure"),
                 "[[fixed_pressure]] #" + std::to_string(i) + ": pressure must be finite");
      sc.fixed_pressure.push_back(std::move(b));
    }
  }
}

}  // namespace ryushi
