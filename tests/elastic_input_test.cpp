// Bad [[elastic]] input: each problem an error at its key, naming the body and what to do.
#include <doctest/doctest.h>

#include <string>

#include "scene_error.hpp"
#include "test_util.hpp"

using namespace ryushi;

TEST_CASE("elastic: bad solid input is an error at the key") {
  const std::string head = test::small_scene_head();
  auto body = [&](const std::string& keys, const std::string& rest = "") {
    return test::scene_error(head + rest +
                             "[[elastic]]\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\ndensity = 1000.0\n" + keys);
  };
  CHECK(body("youngs_modulus = 1e6\npoisson_ratio = 0.6\n") ==
        "bad.toml:15:17: [[elastic]] #0 poisson_ratio is 0.6; it must be in (-1, 0.5) (0.5: incompressible, "
        "no finite bulk modulus)");
  CHECK(body("youngs_modulus = 1e6\n") ==
        "bad.toml:14:18: [[elastic]] #0 needs both youngs_modulus and poisson_ratio");
  CHECK(body("") ==
        "bad.toml:13:11: [[elastic]] #0 needs its stiffness: bulk_modulus and shear_modulus, or "
        "youngs_modulus and poisson_ratio");
  CHECK(body("bulk_modulus = -1.0\nshear_modulus = 1.0\n")
            .find("'bulk_modulus' in [[elastic]] #0 is -1; it must be > 0") != std::string::npos);
  CHECK(body("bulk_modulus = 1e6\nshear_modulus = 1e6\nclamp_min = [0.0, 0.0]\n") ==
        "bad.toml:16:13: [[elastic]] #0 needs both clamp_min and clamp_max");
  // A clamp that holds none of the particles (they sit at 0.025, 0.075, ...) or all of them.
  CHECK(body("bulk_modulus = 1e6\nshear_modulus = 1e6\nclamp_min = [0.0, 0.0]\nclamp_max = [0.02, 0.5]\n") ==
        "bad.toml:16:13: [[elastic]] #0 clamps none of the body's particles (they sit at min + (k + 1/2) "
        "spacing): the clamp box must hold at least one of them");
  CHECK(body("bulk_modulus = 1e6\nshear_modulus = 1e6\nclamp_min = [-0.1, -0.1]\nclamp_max = [0.6, 0.6]\n") ==
        "bad.toml:16:13: [[elastic]] #0 clamps every particle of the body, which could never move: a fixed "
        "obstacle is a [[solid]]");
  // Free under gravity with nothing below it: it would fall out of the domain.
  CHECK(
      body("bulk_modulus = 1e6\nshear_modulus = 1e6\n") ==
      "bad.toml:11:7: [[elastic]] #0 is free (no clamp_min/clamp_max) under gravity with nothing to rest on "
      "(no fluid, [[wall]], [[solid]], mesh or clamped body): clamp it, add a wall, or set [physics] gravity "
      "= 0");
  CHECK(body("bulk_modulus = 1e6\nshear_modulus = 1e6\n", "[physics]\ngravity = [0.0, 0.0]\n").empty());
  CHECK(body("bulk_modulus = 1e6\nshear_modulus = 1e6\n", "[[wall]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n")
            .empty());
  CHECK(body("bulk_modulus = 1e6\nshear_modulus = 1e6\n", "[method]\nsolid_walls = \"seed\"\n") ==
        "bad.toml:11:15: solid_walls = \"seed\" (seed 002 eq. 28) is for solid_formulation = \"updated\": "
        "the total "
        "Lagrangian form's sums run over the rest configuration, where walls have no place");
  CHECK(body("bulk_modulus = 1e6\nshear_modulus = 1e6\n", "[method]\nname = \"mps\"\n") ==
        "bad.toml:13:7: [[elastic]] #0 is for method wcsph");
  // A fixed step the elastic waves outrun: h / c_s = 0.075 / sqrt(2.333e6 / 1000) = 1.55e-3 s.
  CHECK(test::scene_error(head + "dt = 0.01\n[[elastic]]\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\ndensity = "
                                 "1000.0\nbulk_modulus = 1e6\nshear_modulus = 1e6\n") ==
        "bad.toml:10:6: [time] dt = 0.01 s exceeds [[elastic]] #0's elastic wave step h / c_s = 0.00155265 s "
        "(c_s = sqrt((K + 4G/3) / rho0) = 48.3046 m/s)");
}
