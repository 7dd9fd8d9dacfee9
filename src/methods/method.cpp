#include "methods/method.hpp"

#include <cstdio>

#include "methods/mps.hpp"
#include "methods/system_registry.hpp"
#include "methods/wcsph.hpp"
#include "systems/integrate/time_step.hpp"
#include "systems/mps/mps_time_step.hpp"
#include "systems/pressure/pressure_system_dump.hpp"

namespace ryushi {

namespace {
std::string format(const char* pattern, double value) {
  char b[96];
  std::snprintf(b, sizeof b, pattern, value);
  return b;
}
}  // namespace

template <int D>
MethodSetup<D> build_method(const Scene& s, World<D>& world, const PipelineOptions& options) {
  MethodSetup<D> m;
  m.physics = wcsph_parameters<D>(s);
  if (s.method == "mps") {
    auto p = mps_parameters<D>(s);
    populate_mps_world<D>(s, p, world);
    m.pipeline = mps_pipeline<D>(s, p);
    m.first_dt = MpsTimeStep<D>(p).limit(0.0);
    m.density_may_vanish = true;
    m.summary =
        format("r_e = %.4g m", p.weight.support()) + ", " + s.solver.krylov + " + " + s.solver.preconditioner;
    if (!options.dump_matrix_dir.empty())
      m.pipeline.push_back(
          std::make_shared<PressureSystemDump<D>>(options.dump_matrix_dir, options.dump_step));
  } else {
    if (!options.dump_matrix_dir.empty())
      throw SceneError(s.path + ": --dump-matrix: method '" + s.method +
                       "' is explicit and assembles no linear system (use [method] name = \"mps\")");
    populate_world<D>(s, m.physics, world);
    m.pipeline = wcsph_pipeline<D>(s, m.physics);
    m.first_dt = TimeStepControl<D>(m.physics, s.cfl).limit(0.0, m.physics.gravity.norm());
    m.summary = format("h = %.4g m", m.physics.kernel.h()) + format(", c0 = %.4g m/s", m.physics.c0);
  }
  // The scene's registered [[systems]] go last; the scheduler places them by their access.
  for (auto& extra : s.systems)
    m.pipeline.push_back(make_registered_system<D>(extra.name, extra.params, m.physics));
  return m;
}

template MethodSetup<2> build_method<2>(const Scene&, World<2>&, const PipelineOptions&);
template MethodSetup<3> build_method<3>(const Scene&, World<3>&, const PipelineOptions&);

}  // namespace ryushi
