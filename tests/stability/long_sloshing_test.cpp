// A 2D sloshing tank for 200 periods (issue 9): the first standing mode of water H = 0.5 m deep
// in a tank L = 1 m wide, started from rest with the surface as four 0.25 m columns 0.6, 0.55,
// 0.45 and 0.4 m high (the stair of scenes/sloshing_2d.toml at half its resolution, d = 0.05 m,
// so 236 s of flow take minutes). Linear period 2 pi / sqrt(g k tanh(k H)), k = pi / L: 1.182 s.
// The stair holds A = rho g 0.25 (sum h^2 - 4 H^2) / 2 = 30.7 J/m above the flat surface, which
// the flow can only lose. The mechanical energy E = kinetic + potential must not grow, and E ends
// below E(0). The allowance, 5% of A, is the two-period energy test's (the time integration's
// error and WCSPH's stored compression).
// Not asserted: that the water ends at rest (asserted until 2026-11-26). Physics does not bring it
// to rest: the mode loses energy in the Stokes layers on the floor and the walls, at the mean rate
// rho sqrt(nu omega / 8) U0^2 per unit area (U0 the slip velocity of potential flow there: on the
// floor a omega sin(k x) / sinh(k H), on a wall a omega sinh(k (y + H)) / sinh(k H)), against its
// energy rho g a^2 L / 4: a decay rate of 3.3e-3 /s for water (nu = 1e-6), so 92% of the mode's
// energy remains after 20 periods and 46% after 200. A method that ends at rest does so by its
// own numerical dissipation (WCSPH's wave is gone within 20 periods at this resolution); the
// kinetic energy at the end is printed.
// Two measures of growth:
// - the largest rise of E above its running minimum (sample by sample, every 0.05 s): growth and
//   noise alike. WCSPH meets it over 200 periods at d = 0.05 m.
// - the same for E averaged over each period: growth only. MPS and ISPH keep a pressure noise
//   in the water (1-5 J/m of kinetic energy that no longer decays, where WCSPH's wave is gone),
//   so their E jitters by the noise's energy; that jitter is a discretization error, and it falls
//   with resolution (measured 2026-11-27, 20 periods, largest rise sample by sample: MPS 2.67,
//   1.19, 0.23 J/m at d = 0.05, 0.025, 0.0125 m; ISPH's violent-flow set-up 7.07, 1.96, 1.06,
//   0.92 J/m at d = 0.05, 0.025, 1/60, 0.0125 m), where a growth (the paper's ISPH set-up,
//   docs/stability.md) does not. So for them the tests assert no growth of the period mean (within
//   5% of A), E never more than 5% of A above E(0), and the jitter sample by sample falling with
//   resolution (MPS: within 5% of A at H/d = 20).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "stability_util.hpp"

using namespace ryushi;

namespace {

constexpr double kPeriod = 1.182,
                 kStair = 0.5 * 1000 * 9.81 * 0.25 * (0.36 + 0.3025 + 0.2025 + 0.16 - 4 * 0.25);

// The first mode's energy decay rate from the Stokes layers (the comment at the top): the slip
// velocity's square integrated over the floor (length L) and the two walls (height H), for a unit
// amplitude, times rho sqrt(nu omega / 8), over the mode's energy rho g L / 4; plus the interior's
// 4 nu k^2 (negligible here).
double stokes_layer_decay_rate() {
  const double g = 9.81, L = 1.0, H = 0.5, nu = 1e-6, k = M_PI / L;
  const double omega = std::sqrt(g * k * std::tanh(k * H)), slip = omega / std::sinh(k * H);
  const double floor = slip * slip * L / 2,
               walls = 2 * slip * slip * (std::sinh(2 * k * H) / (4 * k) - H / 2);
  return std::sqrt(nu * omega / 8) * (floor + walls) / (g * L / 4) + 4 * nu * k * k;
}

const std::string kTank = R"([scene]
dimension = 2
name = "sloshing_200_periods"
[domain]
min = [-0.2, -0.2]
max = [1.2, 1.2]
[particles]
spacing = 0.05
[material]
density = 1000.0
viscosity = 1.0e-3
[time]
end = 236.4
[output]
interval = 23.64
probe_interval = 0.05
[[fluid]]
min = [0.0, 0.0]
max = [0.25, 0.6]
[[fluid]]
min = [0.25, 0.0]
max = [0.5, 0.55]
[[fluid]]
min = [0.5, 0.0]
max = [0.75, 0.45]
[[fluid]]
min = [0.75, 0.0]
max = [1.0, 0.4]
[[wall]]
min = [0.0, 0.0]
max = [1.0, 0.9]
)";

// The two measures of growth (the comment at the top) over one run.
struct Growth {
  double sample_rise = 0;       // largest rise of E above its running minimum, sample by sample
  double period_mean_rise = 0;  // the same for E averaged over each whole period
  double above_start = 0;       // largest E - E(0)
  double end_change = 0;        // E(end) - E(0)
  double end_kinetic = 0;
};

double largest_rise_above_running_minimum(const std::vector<double>& series) {
  double lowest = series.front(), rise = 0;
  for (double E : series) {
    lowest = std::min(lowest, E);
    rise = std::max(rise, E - lowest);
  }
  return rise;
}

// Runs the tank for `periods` periods at `spacing` on one thread (the suite runs two tests at a
// time) and returns its energy, every 0.05 s.
test::EnergySeries run_tank(const std::string& label, int periods, double spacing,
                            std::vector<std::string> sets) {
  sets.push_back("time.end=" + std::to_string(periods * kPeriod));
  sets.push_back("particles.spacing=" + std::to_string(spacing));
  auto o = test::run_text("sloshing_" + label, test::with_energy_probes(kTank), std::move(sets), 1);
  INFO(label);
  test::require_completed(o);
  // 200 particles at d = 0.05 m, four times as many at each halving.
  const double per_axis = 0.05 / spacing;
  CHECK(test::json_number(o.summary, "fluid_particles") == doctest::Approx(200 * per_axis * per_axis));
  auto e = test::energy(o);
  REQUIRE(e.time.back() >= periods * kPeriod - 0.05);  // the last probe sample
  return e;
}

// The two measures over the first `periods` periods of a run.
Growth measure(const std::string& label, const test::EnergySeries& e, int periods) {
  std::vector<double> samples, kinetic, period_sums(periods, 0.0);
  std::vector<int> period_counts(periods, 0);
  for (std::size_t s = 0; s < e.time.size() && e.time[s] <= periods * kPeriod; ++s) {
    samples.push_back(e.total[s]), kinetic.push_back(e.kinetic[s]);
    const int k = static_cast<int>(e.time[s] / kPeriod);
    if (k < periods) period_sums[k] += e.total[s], ++period_counts[k];
  }
  std::vector<double> period_means;
  for (int k = 0; k < periods; ++k) {
    REQUIRE(period_counts[k] > 0);
    period_means.push_back(period_sums[k] / period_counts[k]);
  }
  Growth g;
  g.sample_rise = largest_rise_above_running_minimum(samples);
  g.period_mean_rise = largest_rise_above_running_minimum(period_means);
  g.above_start = *std::max_element(samples.begin(), samples.end()) - samples.front();
  g.end_change = samples.back() - samples.front();
  g.end_kinetic = kinetic.back();
  MESSAGE(label, ", ", periods, " periods: largest rise above the running minimum ", g.sample_rise,
          " J/m sample by sample, ", g.period_mean_rise, " J/m of the period means (A = ", kStair,
          " J/m); largest E - E(0) ", g.above_start, " J/m, E(end) - E(0) = ", g.end_change,
          " J/m; kinetic energy at the end ", g.end_kinetic, " J/m (the mode's viscous decay, ",
          stokes_layer_decay_rate(), " /s, would leave ",
          std::exp(-stokes_layer_decay_rate() * periods * kPeriod), " of its energy)");
  return g;
}

// No growth: neither measure beyond 5% of A, and the water ends below its start.
void check_no_growth(const Growth& g) {
  CHECK(g.sample_rise <= 0.05 * kStair);
  CHECK(g.end_change <= 0);
}

// No growth of the period mean, E never more than 5% of A above E(0), and E(end) below E(0): what
// a method with a pressure noise must hold where it is resolved (H/d = 20 here).
void check_no_growth_beside_noise(const Growth& g) {
  CHECK(g.period_mean_rise <= 0.05 * kStair);
  CHECK(g.above_start <= 0.05 * kStair);
  CHECK(g.end_change <= 0);
}

const std::vector<std::string> kIsphViolentFlowSetUp = {"method.name=isph",
                                                        "method.wall_rows=\"shepard\"",
                                                        "method.ppe_laplacian=\"standard\"",
                                                        "method.pressure_gradient=\"symmetric\"",
                                                        "method.free_surface_pressure=\"particle\"",
                                                        "method.viscous_laplacian=\"standard\"",
                                                        "solver.tolerance=1e-6",
                                                        "method.compression_relaxation=0.5",
                                                        "shifting.model=\"fickian\""};

}  // namespace

TEST_CASE("stability: a WCSPH sloshing tank run for 200 periods never gains energy") {
  check_no_growth(measure("wcsph", run_tank("wcsph", 200, 0.05, {}), 200));
}

// MPS at its own influence radius (r_e = 3.1 l0) and its default (smooth) source, at H/d = 20
// (272 s on one core). At H/d = 10 the noise is too strong for the bound: over 200 periods the
// period mean wanders up to 3.39 J/m above its running minimum (E never above E(0); about 2.7 J/m
// of kinetic energy stays in the water after the wave is gone) and E jitters by up to 4.63 J/m.
// At H/d = 20, measured 2026-11-27: the period mean rises at most 1.39 J/m, E never above E(0),
// 1.8-2.3 J/m of kinetic energy left from the tenth period on; the jitter sample by sample 1.19
// J/m within 20 periods, 2.03 J/m over 200 (the noise stays, and its largest excursion grows
// with the time watched; docs/stability.md).
TEST_CASE(
    "stability: an MPS sloshing tank never gains energy over 200 periods, its jitter falls with resolution") {
  const auto fine = run_tank("mps_fine", 200, 0.025, {"method.name=mps"});
  check_no_growth_beside_noise(measure("mps, d = 0.025 m", fine, 200));
  // Falls with resolution: by at least a third when d halves (a first-order error would halve;
  // the jitter is the largest excursion of a noisy signal, so some room), 20 periods each.
  const Growth fine_20 = measure("mps, d = 0.025 m", fine, 20);
  CHECK(fine_20.sample_rise <= 0.05 * kStair);
  const Growth coarse_20 =
      measure("mps, d = 0.05 m", run_tank("mps_coarse", 20, 0.05, {"method.name=mps"}), 20);
  CHECK(fine_20.sample_rise < coarse_20.sample_rise / 1.5);
}

// ISPH with the violent-flow set-up passes the two-period energy test at d = 0.025 m (+0.46 J/m at
// most). At d = 0.05 m (H/d = 10) it grows: the period mean rises 2.4 J/m above its running
// minimum within 20 periods (19.7 J/m sample by sample over 200 periods) and 5 J/m of kinetic
// energy stays in the water: something (the projection on a surface that the shifting keeps
// rearranging, on a support of a few particles) feeds the motion faster than it is damped.
// Measured 2026-11-29 (20 periods): the period mean rises 5.32 J/m, 11.2 J/m sample by sample, E
// at most 1.08 J/m above E(0), 4.6 J/m of kinetic energy at the end. Asserted (test audit round
// three, issue 50, row 3; until then should_fail, which any failed assertion passed): the known
// growth's signature, the run completes and its period mean rises more than 10% of A (3.07 J/m:
// twice the bound of 5% of A, 58% of the measured rise). A run within the bound is checked as
// the passing cases are and fails with a message: the growth may be fixed, and the case is then
// to assert check_no_growth_beside_noise.
TEST_CASE(
    "stability: an ISPH sloshing tank (violent-flow set-up) at H/d = 10 does not grow (known to fail "
    "within 20 periods)") {
  const Growth g = measure("isph, d = 0.05 m", run_tank("isph_coarse", 20, 0.05, kIsphViolentFlowSetUp), 20);
  if (g.period_mean_rise <= 0.05 * kStair) {
    check_no_growth_beside_noise(g);
    FAIL_CHECK(
        "ISPH's violent-flow set-up at H/d = 10 no longer grows within 20 periods: the known growth may be "
        "fixed; make this case assert check_no_growth_beside_noise");
    return;
  }
  CHECK_MESSAGE(g.period_mean_rise > 0.1 * kStair,
                "the period mean rises "
                    << g.period_mean_rise
                    << " J/m, above the bound but below the known growth: it has changed");
}

// One resolution up (H/d = 20) the growth within 20 periods is gone, but over 200 periods the
// compression term of eq. 19's first shell, which answers compression only, lets the water's
// volume grow about 0.3% (the potential energy climbs 3.7 J/m at a steady kinetic energy at
// H/d = 30): the period mean wandered 2.37 J/m above its running minimum (3.44 sample by sample).
// With compression_density = "full_support" the term reads the whole support's kernel sum both
// ways and returns the dilation. Measured 2026-11-27 (about 400 s on one core): the period mean
// rises at most 0.65 J/m over 200 periods, 1.44 J/m sample by sample, E at most 0.18 J/m above
// E(0) (first period).
TEST_CASE(
    "stability: an ISPH sloshing tank (violent-flow set-up, full-support compression) never gains energy "
    "over "
    "200 periods at H/d = 20, its jitter falls with resolution") {
  auto set_up = kIsphViolentFlowSetUp;
  set_up.push_back("method.compression_density=\"full_support\"");
  const auto fine = run_tank("isph_fine", 200, 0.025, set_up);
  check_no_growth_beside_noise(measure("isph, d = 0.025 m", fine, 200));
  // Falls with resolution, as for MPS above, over 20 periods.
  const Growth fine_20 = measure("isph, d = 0.025 m", fine, 20);
  check_no_growth_beside_noise(fine_20);
  const Growth coarse_20 =
      measure("isph, d = 0.05 m", run_tank("isph_coarse_reference", 20, 0.05, set_up), 20);
  CHECK(fine_20.sample_rise < coarse_20.sample_rise / 1.5);
}

// formulation = "implicit_density" (SPH's symmetric pressure force and its adjoint density
// change): the pressure does no work in the fluid. Measured 2026-11-29 undamped (the default; the
// tilted start is not settled): the period mean never rises above its running minimum (0.00 J/m),
// 1.81 J/m sample by sample, E at most 1.18 J/m above E(0), E(end) - E(0) = -35.6 J/m with the wave
// gone (kinetic energy 1.5e-6 J/m): the stair's 30.7 J/m and the rest potential energy, the water's
// level lower (a density drift the step's source does not return). With the particle-scale damping
// at 0.2 (217 s): 0.00, 1.11 above E(0), -37.5 at the end. At H/d = 30 (without the damping) E rose 1.84 J/m
// above E(0) at t = 0.05 s, over the bound (docs/isph.md): not asserted here.
TEST_CASE(
    "stability: an ISPH sloshing tank (implicit density formulation) never gains energy over 200 periods at "
    "H/d = 20") {
  const auto e = run_tank("isph_implicit_density", 200, 0.025,
                          {"method.name=isph", "method.formulation=\"implicit_density\""});
  check_no_growth_beside_noise(measure("isph implicit density, d = 0.025 m", e, 200));
}
