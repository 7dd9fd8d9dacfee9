#pragma once
// Linear wave-maker theory for the piston flumes (scenes/wave_flume_2d.toml and
// wave_flume_isph_2d.toml: depth 0.2 m, stroke 0.04 m, period 1 s) and the flumes' measures:
// the wave height at a probe per period against Biesel's, the paddle's mean force.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "test_util.hpp"

namespace ryushi::test {

// Biesel's far-field height of scenes/wave_flume_2d.toml's piston: H = S 2 (cosh 2kh - 1) /
// (sinh 2kh + 2kh), with k from the dispersion relation omega^2 = g k tanh kh.
inline double biesel_height() {
  const double g = 9.81, depth = 0.2, stroke = 0.04, omega = 2 * std::numbers::pi;
  double k = omega * omega / g;
  for (int n = 0; n < 100; ++n) k = omega * omega / (g * std::tanh(k * depth));  // dispersion relation
  return stroke * 2 * (std::cosh(2 * k * depth) - 1) / (std::sinh(2 * k * depth) + 2 * k * depth);
}

// The largest minus the smallest surface elevation at a probe in each period from t = 2 s to 5 s
// (the front has passed; the reflection from the far wall returns at t ~ 8 s), over Biesel's H.
inline std::vector<double> wave_heights(const Csv& csv, const std::string& probe) {
  const auto& t = csv["time"];
  const auto& eta = csv[probe];
  std::vector<double> out;
  for (int period = 2; period < 5; ++period) {
    double high = -1e9, low = 1e9;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= period && t[i] < period + 1) high = std::max(high, eta[i]), low = std::min(low, eta[i]);
    out.push_back((high - low) / biesel_height());
  }
  return out;
}

// The force on the paddle averaged over the same whole periods.
inline double mean_paddle_force(const Csv& csv) {
  const auto& t = csv["time"];
  const auto& force = csv["piston_force"];
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= 2 && t[i] < 5) sum += force[i], ++n;
  REQUIRE(n > 0);
  return sum / n;
}

}  // namespace ryushi::test
