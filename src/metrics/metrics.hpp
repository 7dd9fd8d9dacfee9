#pragma once
// [[metric]] entries: a run's error against a reference that ships with ryushi, computed from
// the final state and the probe series, written under "metrics" in summary.json and printed at
// the end of the run (issue 9). Types:
//   dam_break_front       the surge_front probe as Z = x/a against T = n t sqrt(g / a) (n^2 the
//                         column's height over a: t sqrt(2g/a) for n^2 = 2) and a reference
//                         table (default Martin & Moyce 1952, n^2 = 2,
//                         tools/reference/martin_moyce_1952_n2_2.csv): the largest relative
//                         error for T <= t_max after ONE fitted time-origin shift in
//                         [0, max_shift] (the criterion decided in the ISPH issue); NAME is
//                         that error, NAME_shift the shift, NAME_unshifted the error without it
//   hydrostatic_pressure  the fluid pressure against rho0 g (surface - z) at the end:
//                         sqrt(sum (p - p_ref)^2 / sum p_ref^2) over fluid particles below
//                         `surface` (default: the top of the tallest fluid block)
//   poiseuille_profile    the x velocity across the fluid column nearest position[0] against the
//                         start-up series of Morris, Fox & Zhu (1997, eq. 21), L2 over the
//                         column relative to the series' centreline speed
//   ritter_depth          swe: the depth against Ritter's dry-bed dam break, sum |h - h_R| /
//                         sum h_R downstream of the dam (NAME_whole: every particle; NAME_front:
//                         the front's relative lag)
//   rotating_square_pressure  a pressure probe's first sample after t = 0 against Colagrossi's
//                         series for the rotating square (the initial pressure), relative
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
                                                             const ProbeRows& probes, double rho0, double g,
                                                             double time);

}  // namespace ryushi
