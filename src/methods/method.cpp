#include "methods/method.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "methods/system_registry.hpp"
#include "systems/boundary/prescribed_motion.hpp"
#include "systems/neighbour/neighbour_search.hpp"

namespace ryushi {

namespace {
// Function-local so registration from any translation unit's static initialiser is safe.
std::map<std::string, MethodRegistryEntry>& registry() {
  static std::map<std::string, MethodRegistryEntry> r;
  return r;
}
}  // namespace

bool register_method(const std::string& name, MethodSpec spec, MethodRegistryEntry entry) {
  if (!register_method_spec(name, std::move(spec))) return false;  // a name taken (a plugin's)
  registry().emplace(name, std::move(entry));
  return true;
}

void unregister_method(const std::string& name) {
  registry().erase(name);
  unregister_method_spec(name);
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (auto& [n, _] : registry()) names.push_back(n);
  return names;
}

const MethodRegistryEntry& method_registry_entry(const std::string& name) {
  auto it = registry().find(name);
  if (it == registry().end()) throw std::invalid_argument("no method registered as '" + name + "'");
  return it->second;
}

void refuse_matrix_dump(const Scene& s, const PipelineOptions& options) {
  if (!options.dump_matrix_dir.empty())
    throw SceneError(s.path + ": --dump-matrix: method '" + s.method +
                     "' is explicit and assembles no linear system (use [method] name = \"mps\")");
}

template <int D>
MethodSetup<D> build_method(const Scene& s, World<D>& world, const PipelineOptions& options) {
  auto& entry = method_registry_entry(s.method);  // the loader accepted only registered names
  MethodSetup<D> m;
  if constexpr (D == 2)
    m = entry.build2(s, world, options);
  else
    m = entry.build3(s, world, options);
  // Bodies with a prescribed motion move first in the step, before the neighbour search sees them.
  std::vector<typename PrescribedMotion<D>::Body> moving;
  for (std::size_t k = 0; k < s.solids.size(); ++k) {
    if (!s.solids[k].moves()) continue;
    typename PrescribedMotion<D>::Body body{static_cast<int>(k), {}, s.solids[k].displacement_table};
    for (auto& formula : s.solids[k].displacement) body.formulas.emplace_back(formula);
    moving.push_back(std::move(body));
  }
  if (!moving.empty()) m.pipeline.insert(m.pipeline.begin(), std::make_shared<PrescribedMotion<D>>(std::move(moving)));
  for (auto& system : m.pipeline)
    if (auto* search = dynamic_cast<const NeighbourSearch<D>*>(system.get()))
      m.search_cell = search->cell_size();
  // The scene's registered [[systems]] go last, or right after the system they name; the
  // scheduler places them by their access.
  for (auto& extra : s.systems) {
    auto system = make_registered_system<D>(extra.name, extra.params, m.context);
    const std::string after = system->place_after();
    if (after.empty()) {
      m.pipeline.push_back(std::move(system));
      continue;
    }
    auto it =
        std::find_if(m.pipeline.rbegin(), m.pipeline.rend(), [&](auto& p) { return p->name() == after; });
    if (it == m.pipeline.rend())  // the loader's `needs` check refuses such a scene first
      throw std::invalid_argument("system '" + extra.name + "' must follow '" + after + "', which method '" +
                                  s.method + "' does not run with this scene's keys");
    m.pipeline.insert(it.base(), std::move(system));
  }
  return m;
}

template MethodSetup<2> build_method<2>(const Scene&, World<2>&, const PipelineOptions&);
template MethodSetup<3> build_method<3>(const Scene&, World<3>&, const PipelineOptions&);

}  // namespace ryushi
