// A million particles in a 2D scene on one thread for one step (issue 9): a 1 m x 1 m tank at
// d = 1 mm under each method. What can break at this size is indexing and allocation (cell
// keys, neighbour offsets, the multigrid's levels), so the step must complete, keep every
// particle and leave the tank at rest: WCSPH within its 1% compressibility, and no particle
// faster than the CFL step allows (the health check after every step).
#include <doctest/doctest.h>

#include "stability_util.hpp"

using namespace ryushi;

TEST_CASE(
    "stability: a 2D tank of a million particles takes one step on one thread under WCSPH, MPS and ISPH") {
  const std::string scene =
      "[scene]\ndimension = 2\n[domain]\nmin = [-0.1, -0.1]\nmax = [1.1, 1.2]\n[particles]\nspacing = 0.001\n"
      "[time]\nend = 1.0\nmax_steps = 1\n[output]\ninterval = 100.0\n"
      "[[fluid]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[[wall]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.1]\n";
  for (const char* method : {"wcsph", "mps", "isph"}) {
    auto o =
        test::run_text(std::string("million_") + method, scene, {std::string("method.name=") + method}, 1);
    INFO(method);
    test::require_completed(o);
    CHECK(test::json_number(o.summary, "fluid_particles") == 1000000);
    CHECK(test::json_number(o.summary, "steps") == 1);
    if (std::string(method) == "wcsph") CHECK(test::json_number(o.summary, "max_density_deviation") < 0.01);
  }
}
