#pragma once
// [[metric]] entries: a run's error against a reference that ships with ryushi, computed from
// the final state and the probe series, written under "metrics" in summary.json and printed at
// the end of the run (issue 9). Types:
//   dam_break_front       the surge_front probe as Z = x/a against T = t sqrt(2 g / a) and a
//                         reference table (default Martin & Moyce 1952, n^2 = 2,
//                         tools/reference/martin_moyce_1952_n2_2.csv): the largest relative
//                         error for T <= t_max after ONE fitted time-origin shift in
//                         [0, max_shift] (the criterion decided in the ISPH issue); NAME is
//                         that error, NAME_shift the shift, NAME_unshifted the error without it
//   hydrostatic_pressure  the fluid pressure against rho0 g (surface - z) at the end:
//                         sqrt(sum (p - p_ref)^2 / sum p_ref^2) over fluid particles below
//                         `surface` (default: the top of the tallest fluid block)
//   probe_csv             a probe's series against a CSV time series (time, value): the RMS of
//                         the difference (reference interpolated linearly at the probe times
//                         inside its range) over the RMS of the reference
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ecs/world.hpp"
#include "scene/scene.hpp"

namespace ryushi {

// One row of probes.csv: time, then one value per probe.
using ProbeRows = std::vector<std::vector<double>>;

// (name, value) pairs of every metric of the scene. A metric whose data is missing (no probe
// samples yet) reports NaN.
template <int D>
std::vector<std::pair<std::string, double>> evaluate_metrics(const Scene& scene, const World<D>& world,
                                                             const ProbeRows& probes, double rho0, double g);

// A reference table (two numeric columns after optional '#' comment lines and a header line).
// Throws SceneError "file:line: message" on a malformed line.
std::vector<std::pair<double, double>> read_reference_table(const std::string& path);

}  // namespace ryushi
