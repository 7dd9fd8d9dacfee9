// Heat conduction and a temperature-dependent viscosity under WCSPH (issue 14; seed 001 eqs. 2-8,
// 32-34; docs/multiphysics.md): conduction between plates against the analytic series with
// fixed-temperature (Dirichlet) and heat-flux (Neumann) walls, the heat of a hot block kept to
// round-off between adiabatic walls, a hot fluid cooling on a cold plate with the Arrhenius law
// held particle by particle, and the errors of bad thermal input.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "h5_read.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

constexpr double kPi = std::numbers::pi;
std::string bin() {
  return RYUSHI_BINARY;
}

// scenes/conduction_2d.toml: water (k = 0.6, rho c = 4.186e6) in 0 < y < L = 10 mm from T0 =
// 300 K, the plate below at T1 = 310 K, the one above at T2 = 290 K.
constexpr double kL = 0.01, kT0 = 300, kT1 = 310, kT2 = 290, kAlpha = 0.6 / (1000 * 4186.0);

double two_plates(double y, double t) {
  double T = kT1 + (kT2 - kT1) * y / kL;
  for (int n = 1; n <= 400; ++n) {
    const double sign = n % 2 ? -1.0 : 1.0;  // (-1)^n
    const double B = 2 / (n * kPi) * ((kT0 - kT1) * (1 - sign) + (kT2 - kT1) * sign);
    T += B * std::sin(n * kPi * y / kL) * std::exp(-n * n * kPi * kPi * kAlpha * t / (kL * kL));
  }
  return T;
}

// The bottom plate lets q = 1200 W/m^2 into the water, the top one holds T2: steady
// T2 + q/k (L - y), the transient in cos((n + 1/2) pi y / L) (zero gradient below, zero above),
// its coefficients by quadrature of the initial difference.
constexpr double kQ = 1200, kK = 0.6;
double flux_and_plate(double y, double t) {
  double T = kT2 + kQ / kK * (kL - y);
  const int samples = 4000;
  for (int n = 0; n < 200; ++n) {
    const double lambda = (n + 0.5) * kPi / kL;
    double c = 0;  // (2/L) int_0^L theta0 cos(lambda y) dy, midpoint rule
    for (int k = 0; k < samples; ++k) {
      const double yk = (k + 0.5) * kL / samples;
      c += (kT0 - kT2 - kQ / kK * (kL - yk)) * std::cos(lambda * yk);
    }
    c *= 2.0 / samples;
    T += c * std::cos(lambda * y) * std::exp(-lambda * lambda * kAlpha * t);
  }
  return T;
}

// Largest |T - reference(y, t)| over the fluid of a frame.
template <class Reference>
double max_temperature_error(const std::filesystem::path& frame, double t, Reference&& reference) {
  auto x = test::read_dataset(frame, "position").values, T = test::read_dataset(frame, "temperature").values,
       kind = test::read_dataset(frame, "kind").values;
  double worst = 0;
  int count = 0;
  for (std::size_t i = 0; i < kind.size(); ++i)
    if (kind[i] == 0) worst = std::max(worst, std::abs(T[i] - reference(x[3 * i + 1], t))), ++count;
  REQUIRE(count > 100);
  return worst;
}

std::string vec(double x, double y) {
  char s[96];
  std::snprintf(s, sizeof s, "[%.9g,%.9g]", x, y);
  return s;
}

// scenes/conduction_2d.toml at spacing d: its periodic width 12 d (three search radii), the
// plates three layers thick.
std::string conduction_at(double d) {
  const double w = 12 * d, t = 3 * d;
  char spacing[64];
  std::snprintf(spacing, sizeof spacing, "--set particles.spacing=%.9g", d);
  return std::string(spacing) + " --set domain.min=" + vec(0, -t - d) +
         " --set domain.max=" + vec(w, kL + t + d) + " --set fluid.0.max=" + vec(w, kL) +
         " --set solid.0.min=" + vec(0, -t) + " --set solid.0.max=" + vec(w, 0.0) +
         " --set solid.1.max=" + vec(w, kL + t);
}

}  // namespace

TEST_CASE(
    "heat: conduction between plates at fixed temperatures follows the series at two times, two "
    "resolutions") {
  // L / d = 20 and 40; frames 1 and 4 are t = 0.05 and 0.2 L^2 / alpha (34.9 s, 139.6 s).
  std::vector<double> early_errors, late_errors;
  for (int cells : {20, 40}) {
    auto dir = test::unique_scratch("conduction");
    auto r = test::run_command(bin() + " run " + test::scene_path("conduction_2d.toml") + " --quiet --out " +
                               dir.string() + " " + conduction_at(kL / cells));
    REQUIRE_MESSAGE(r.code == 0, r.output);
    const double early = max_temperature_error(test::frame_path(dir, 1), 34.9, two_plates);
    const double late = max_temperature_error(test::frame_path(dir, 4), 139.6, two_plates);
    MESSAGE("L/d = ", cells, ": max |T - series| = ", early, " K at 0.05 L^2/alpha, ", late,
            " K at 0.2 L^2/alpha (range 20 K)");
    CHECK(early < 0.01 * (kT1 - kT2));
    CHECK(late < 0.01 * (kT1 - kT2));
    early_errors.push_back(early), late_errors.push_back(late);
  }
  // Converges by a fixed factor per halving, not by any decrease (test audit round three, issue 50,
  // row 39). Measured: the largest error falls 0.0587 -> 0.0347 K at 0.05 L^2/alpha and 6.54e-4 ->
  // 3.85e-4 K at 0.2 L^2/alpha, a factor 1.69 at both (order 0.76, below first order's 2; this
  // largest error over the fluid, with the plates 10 K off the water at t = 0, is not analysed
  // further here). Asserted: at least 1.5 per halving at both times (order 0.58), 11% under the
  // measured factor: an error that stalls (1.0) or creeps down fails.
  const double early_ratio = early_errors[0] / early_errors[1], late_ratio = late_errors[0] / late_errors[1];
  MESSAGE("error ratio L/d = 20 over 40: ", early_ratio, " at 0.05 L^2/alpha, ", late_ratio,
          " at 0.2 L^2/alpha");
  CHECK(early_ratio >= 1.5);
  CHECK(late_ratio >= 1.5);
}

TEST_CASE(
    "heat: a heat-flux wall and a fixed-temperature plate follow their series to the steady slope q/k") {
  auto text = test::read_text(test::scene_path("conduction_2d.toml"));
  const auto at = text.find("temperature = 310.0");
  REQUIRE(at != std::string::npos);
  text.replace(at, std::string("temperature = 310.0").size(), "heat_flux = 1200.0");
  auto dir = test::unique_scratch("heat_flux");
  test::write_text(dir / "flux.toml", text);
  auto r = test::run_command(bin() + " run " + (dir / "flux.toml").string() + " --quiet --out " +
                             (dir / "out").string() + " --set time.end=600 --set output.interval=150");
  REQUIRE_MESSAGE(r.code == 0, r.output);
  // q L / k = 20 K across the slab; at 600 s the profile is 88% of the way to the steady one.
  for (int k : {1, 4}) {
    const double e = max_temperature_error(test::frame_path(dir / "out", k), 150.0 * k, flux_and_plate);
    MESSAGE("t = ", 150 * k, " s: max |T - series| = ", e, " K");
    CHECK(e < 0.01 * kQ * kL / kK);
  }
}

TEST_CASE("heat: a hot block in cold water keeps the total heat to round-off between adiabatic walls") {
  // Five blocks: the middle one at 360 K, the rest at 300 K, in an adiabatic tank under gravity.
  std::string text = R"([scene]
dimension = 2
[domain]
min = [-0.01, -0.01]
max = [0.05, 0.05]
[particles]
spacing = 1.0e-3
[material]
conductivity = 50.0
heat_capacity = 1000.0
temperature = 300.0
[method]
name = "wcsph"
[time]
end = 0.3
[output]
interval = 0.1
fields = ["mass"]
[[fluid]]
min = [0.0, 0.0]
max = [0.04, 0.01]
[[fluid]]
min = [0.0, 0.01]
max = [0.015, 0.02]
[[fluid]]
min = [0.015, 0.01]
max = [0.025, 0.02]
temperature = 360.0
[[fluid]]
min = [0.025, 0.01]
max = [0.04, 0.02]
[[fluid]]
min = [0.0, 0.02]
max = [0.04, 0.03]
[[wall]]
min = [0.0, 0.0]
max = [0.04, 0.04]
)";
  auto dir = test::unique_scratch("hot_block");
  test::write_text(dir / "block.toml", text);
  auto r = test::run_command(bin() + " run " + (dir / "block.toml").string() + " --quiet --out " +
                             (dir / "out").string());
  REQUIRE_MESSAGE(r.code == 0, r.output);
  auto heat = [&](int k, double* hottest) {
    auto f = test::frame_path(dir / "out", k);
    auto m = test::read_dataset(f, "mass").values, T = test::read_dataset(f, "temperature").values,
         kind = test::read_dataset(f, "kind").values;
    double sum = 0;
    *hottest = 0;
    for (std::size_t i = 0; i < kind.size(); ++i)
      if (kind[i] == 0) sum += m[i] * 1000.0 * T[i], *hottest = std::max(*hottest, T[i]);
    return sum;
  };
  double hottest0 = 0, hottest = 0;
  const double h0 = heat(0, &hottest0);
  const double h3 = heat(3, &hottest);
  // The block has given off a fair part of its excess (so heat moved), and the total is kept:
  // pairwise-antisymmetric exchange, summed in doubles over ~1,200 particles and 4,500 steps.
  CHECK(hottest0 == doctest::Approx(360.0));
  CHECK(hottest < 330.0);
  MESSAGE("total heat ", h0, " J/m -> ", h3, " J/m, relative change ", (h3 - h0) / h0);
  CHECK(std::abs(h3 - h0) / h0 < 1e-12);
}

TEST_CASE(
    "heat: a hot fluid cooling on a cold plate follows the Arrhenius law particle by particle and slows") {
  // scenes/cooling_slump_2d.toml against the same slump on a plate as hot as the fluid.
  struct Run {
    double front = 0, kinetic = 0, mean_mu = 0, worst_law = 0, coldest = 1e9;
  };
  auto run = [&](const std::string& extra) {
    auto dir = test::unique_scratch("cooling");
    auto r = test::run_command(bin() + " run " + test::scene_path("cooling_slump_2d.toml") +
                               " --quiet --out " + dir.string() + " --set time.end=0.4 " + extra);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    Run out;
    auto f = test::frame_path(dir, 8);  // t = 0.4 s
    auto x = test::read_dataset(f, "position").values, v = test::read_dataset(f, "velocity").values,
         T = test::read_dataset(f, "temperature").values, mu = test::read_dataset(f, "viscosity").values,
         kind = test::read_dataset(f, "kind").values;
    int n = 0;
    for (std::size_t i = 0; i < kind.size(); ++i) {
      if (kind[i] != 0) continue;
      out.front = std::max(out.front, x[3 * i]);
      out.kinetic += 0.5 * (v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1]);
      out.mean_mu += mu[i], ++n;
      out.coldest = std::min(out.coldest, T[i]);
      const double law = std::min(2.0, 0.05 * std::exp(4.0e4 / 8.314462618 * (1 / T[i] - 1 / 350.0)));
      out.worst_law = std::max(out.worst_law, std::abs(mu[i] / law - 1));
    }
    out.mean_mu /= n;
    return out;
  };
  const Run cold = run(""), hot = run("--set solid.0.temperature=350");
  MESSAGE("t = 0.4 s, cold plate: front ", cold.front, " m, kinetic ", cold.kinetic, ", mean mu ",
          cold.mean_mu, ", coldest ", cold.coldest, " K, worst |mu/law - 1| ", cold.worst_law);
  MESSAGE("t = 0.4 s, hot plate:  front ", hot.front, " m, kinetic ", hot.kinetic, ", mean mu ", hot.mean_mu);
  // The law particle by particle: the column holds the viscosity of the step's second stage, at
  // the midpoint temperature, the frame the step's end temperature; half a step's cooling
  // changes mu by at most 0.03% at t = 0.4 s (0.2% at 0.1 s, measured); 0.5% allows for it.
  CHECK(cold.worst_law < 5e-3);
  CHECK(hot.worst_law < 1e-12);  // at the reference temperature throughout
  CHECK(cold.coldest < 300.0);   // the plate has cooled the fluid next to it
  CHECK(cold.mean_mu > 4 * hot.mean_mu);
  CHECK(cold.front < 0.8 * hot.front);  // measured 0.075 against 0.111 m
  CHECK(cold.kinetic < 0.5 * hot.kinetic);
}

TEST_CASE("heat: bad thermal and rheology input is an error at the key") {
  const std::string head = test::small_scene_head();
  const std::string box =
      "[[fluid]]\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n[[wall]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n";
  auto material = [&](const std::string& keys, const std::string& rest = "") {
    return test::scene_error(head + "[material]\n" + keys + "\n" + box + rest);
  };
  CHECK(material("conductivity = 0.6") ==
        "bad.toml:12:1: [[fluid]] #0 needs a temperature (K): give it one or set [material] temperature");
  CHECK(material("conductivity = -1.0").find("'conductivity' in [material] is -1; it must be >= 0") !=
        std::string::npos);
  CHECK(material("heat_capacity = 0.0").find("'heat_capacity' in [material] is 0; it must be > 0") !=
        std::string::npos);
  CHECK(material("temperature = 300.0") ==
        "bad.toml:11:15: [material] temperature needs heat: conductivity > 0 or a temperature-dependent "
        "viscosity (activation_energy)");
  CHECK(material("conductivity = 0.6\ntemperature = 300.0", "temperature = 280.0\nheat_flux = 10.0\n") ==
        "bad.toml:20:13: [[wall]] #0 has both temperature (Dirichlet) and heat_flux (Neumann); give one");
  CHECK(material("viscosity = 0.1\nactivation_energy = 4e4\nmax_viscosity = 1.0\ntemperature = 300.0") ==
        "bad.toml:12:21: 'activation_energy' needs reference_temperature (K): the temperature at which the "
        "model's parameters hold");
  CHECK(material("rheology = \"power_law\"\nconsistency = 0.01\npower_index = 0.5") ==
        "bad.toml:13:15: rheology \"power_law\" with power_index 0.5 < 1 has infinite viscosity at rest: set "
        "[material] max_viscosity (Pa s)");
  CHECK(material("rheology = \"power_law\"\nconsistency = 0.01\npower_index = -0.5")
            .find("'power_index' in [material] is -0.5; it must be > 0") != std::string::npos);
  CHECK(material("rheology = \"bingham\"\nviscosity = 0.01\nyield_stress = 1.0") ==
        "bad.toml:10:1: [material] rheology = \"bingham\" needs 'regularisation'");
  CHECK(material("rheology = \"power_law\"\nconsistency = 0.01\npower_index = 1.5\nyield_stress = 1.0") ==
        "bad.toml:14:16: 'yield_stress' is not a parameter of rheology \"power_law\"");
  CHECK(material("rheology = \"power_law\"\nviscosity = 0.1\nconsistency = 0.01\npower_index = 1.5")
            .find("'viscosity' is not a parameter of rheology \"power_law\"") != std::string::npos);
  CHECK(material("rheology = \"cross\"\nzero_shear_viscosity = 1.0\ntime_constant = 1.0\npower_index = 1.0",
                 "[method]\nname = \"mps\"\n") ==
        "bad.toml:11:12: [material] rheology = \"cross\" is for method wcsph");
  // A fixed step beyond conduction's stable step.
  CHECK(test::scene_error(
            head +
            "dt = 0.01\n[material]\nconductivity = 1000.0\nheat_capacity = 1.0\ntemperature = 300.0\n" +
            box) ==
        "bad.toml:10:6: [time] dt = 0.01 s exceeds heat conduction's stable step 0.125 h^2 rho0 c / k = "
        "0.000703125 s");
}
