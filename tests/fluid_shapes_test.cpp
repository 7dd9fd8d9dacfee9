// Fluid blocks of a shape: a disc and a ball of fluid fill the area and volume of their shape
// with lattice particles, and a shape without its size is bad input at the block.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "h5_read.hpp"
#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

TEST_CASE("fluid shapes: a disc and a ball of fluid hold their area and volume in particles") {
  auto dir = test::unique_scratch("fluid_shapes");
  std::filesystem::create_directories(dir);
  auto count = [&](const std::string& text) {
    auto kind = test::read_dataset(test::initial_frame(dir, text), "kind").values;
    return double(std::count(kind.begin(), kind.end(), 0.0));
  };
  // R = 10 d: the lattice points within R of the centre, pi R^2 / d^2 = 314.2 (measured 316).
  const double disc = count(
      "[scene]\ndimension = 2\n[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[particles]\n"
      "spacing = 0.01\n[physics]\ngravity = [0.0, 0.0]\n[time]\nend = 0.1\n"
      "[[fluid]]\nshape = \"cylinder\"\ncentre = [0.5, 0.5]\nradius = 0.1\n");
  CHECK(std::abs(disc / (kPi * 100) - 1) < 0.02);
  const double ball = count(
      "[scene]\ndimension = 3\n[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\n"
      "[particles]\nspacing = 0.02\n[physics]\ngravity = [0.0, 0.0, 0.0]\n[time]\nend = 0.1\n"
      "[[fluid]]\nshape = \"sphere\"\ncentre = [0.5, 0.5, 0.5]\nradius = 0.2\n");
  CHECK(std::abs(ball / (4.0 / 3 * kPi * 1000) - 1) < 0.02);  // 4,189; measured 4,224, as the STL sphere
  CAPTURE(disc);
  CAPTURE(ball);
  CHECK(test::scene_error(
            "[scene]\ndimension = 2\n[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[particles]\n"
            "spacing = 0.01\n[time]\nend = 0.1\n[[fluid]]\nshape = \"cylinder\"\nradius = 0.1\n") ==
        "bad.toml:10:1: [[fluid]] #0 (a cylinder) needs centre and radius");
}
