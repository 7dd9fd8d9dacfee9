// A 2D sloshing tank for 200 periods (issue 9): the first standing mode of water H = 0.5 m deep
// in a tank L = 1 m wide, started from rest with the surface as four 0.25 m columns 0.6, 0.55,
// 0.45 and 0.4 m high (the stair of scenes/sloshing_2d.toml at half its resolution, d = 0.05 m,
// so 236 s of flow take minutes). Linear period 2 pi / sqrt(g k tanh(k H)), k = pi / L: 1.182 s.
// The stair holds A = rho g 0.25 (sum h^2 - 4 H^2) / 2 = 30.7 J/m above the flat surface, which
// the flow can only lose. The mechanical energy E = kinetic + potential must not grow: every rise
// of E above its lowest value so far stays within 5% of A (the allowance of the two-period energy
// test: the time integration's error and WCSPH's stored compression), over all 200 periods, and
// E ends below E(0).
// Not asserted: that the water ends at rest (asserted until 2026-11-26). Physics does not bring it
// to rest: the mode loses energy in the Stokes layers on the floor and the walls, at the mean rate
// rho sqrt(nu omega / 8) U0^2 per unit area (U0 the slip velocity of potential flow there: on the
// floor a omega sin(k x) / sinh(k H), on a wall a omega sinh(k (y + H)) / sinh(k H)), against its
// energy rho g a^2 L / 4: a decay rate of 3.3e-3 /s for water (nu = 1e-6), so 92% of the mode's
// energy remains after 20 periods and 46% after 200. A method that ends at rest does so by its
// own numerical dissipation (WCSPH's wave is gone within 20 periods at this resolution); the
// kinetic energy at the end is printed.
// Run under WCSPH for 200 periods; the ISPH violent-flow set-up and MPS are known failures (their
// energy rises above its running minimum), shown within 20 periods.
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

void check_long_sloshing(const std::string& label, int periods, std::vector<std::string> sets) {
  sets.push_back("time.end=" + std::to_string(periods * kPeriod));
  auto o = test::run_text("sloshing_200_" + label, test::with_energy_probes(kTank), std::move(sets), 1);
  INFO(label);
  test::require_completed(o);
  auto e = test::energy(o);
  REQUIRE(e.time.back() >= periods * kPeriod - 0.05);  // the last probe sample, every 0.05 s
  double lowest = e.total.front(), largest_rise = 0;
  for (double E : e.total) {
    lowest = std::min(lowest, E);
    largest_rise = std::max(largest_rise, E - lowest);
  }
  MESSAGE(label, ": largest rise above the running minimum ", largest_rise, " J/m (A = ", kStair,
          " J/m), E(end) - E(0) = ", e.total.back() - e.total.front(), " J/m");
  CHECK(largest_rise <= 0.05 * kStair);
  CHECK(e.total.back() <= e.total.front());
  MESSAGE(label, ": kinetic energy at the end ", e.kinetic.back(), " J/m (the mode's viscous decay, ",
          stokes_layer_decay_rate(), " /s, would leave ",
          std::exp(-stokes_layer_decay_rate() * e.time.back()), " of its energy)");
  CHECK(test::json_number(o.summary, "fluid_particles") == 200);
}

}  // namespace

TEST_CASE("stability: a WCSPH sloshing tank run for 200 periods never gains energy") {
  check_long_sloshing("wcsph", 200, {});
}
// ISPH with the violent-flow set-up passes the two-period energy test at d = 0.025 m (+0.46 J/m at
// most), but at this resolution it keeps about 5 J/m of kinetic energy from the first ten periods
// to the 200th (rms speed 0.14 m/s) where the wave is gone, and its energy rises by up to 19.7 J/m
// above its running minimum before falling again: something (the projection on a surface that the
// shifting keeps rearranging) feeds the motion as fast as it is damped. It breaks the bound in the
// first period already (its energy first rises 5% of A above the running minimum at t = 1.0 s;
// 7.1 J/m within 20 periods), so a known failure is shown by 20 periods as well as by 200 (67 s of
// the suite's time, now 7). At d = 0.025 m it rises 1.96 J/m (at t = 10 s) within 20 periods and
// still sloshes at the end (0.036 m between the walls). Marked should_fail: it turns red when
// fixed; then make it 200 periods like the WCSPH case.
TEST_CASE(
    "stability: an ISPH sloshing tank (violent-flow set-up) never gains energy (known to fail within 20 "
    "periods)" *
    doctest::should_fail()) {
  check_long_sloshing(
      "isph", 20,
      {"method.name=isph", "method.wall_rows=\"shepard\"", "method.ppe_laplacian=\"standard\"",
       "method.pressure_gradient=\"symmetric\"", "method.free_surface_pressure=\"particle\"",
       "method.viscous_laplacian=\"standard\"", "solver.tolerance=1e-6", "method.compression_relaxation=0.5",
       "shifting.model=\"fickian\""});
}

// MPS at its own influence radius (r_e = 3.1 l0), measured with the number-density source of the
// BMG paper (the default until 2026-11-26): over 200 periods (37 s on 2 threads) E never rises
// above E(0) and does not drift (after the first ten periods it stays 28-32 J/m below E(0)), but
// the source's pressure noise (the jitter of the resting tank, docs/mps.md) keeps 1.3-2.8 J/m of
// kinetic energy in the water (rms speed about 0.1 m/s) where the wave is gone (0.016 m between
// the walls after 20 periods), and E wanders up to 4.8 J/m above its running minimum (the bound is
// 1.5): energy the noise puts in before it is damped. 20 periods show it (4.2 J/m). With the
// smooth source (the default since) the stair's collapse gains nothing (tests/energy_test.cpp)
// but the noise remains: 2.67 J/m above the running minimum within 20 periods, 3.5 J/m of kinetic
// energy at the end (source_support 0.8-1.0: 1.7-3.5 J/m).
// Marked should_fail.
TEST_CASE(
    "stability: an MPS sloshing tank never gains energy (known to fail within 20 periods: its pressure "
    "noise)" *
    doctest::should_fail()) {
  check_long_sloshing("mps", 20, {"method.name=mps"});
}
