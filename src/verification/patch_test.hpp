#pragma once
// Square (cube) patch test of the V&V paper, section 3: an operator applied to the Franke
// function on particles filling the unit box, regular or disordered, at several spacings. The
// error is the RMSE of eq. 20, sqrt(sum (approx - exact)^2 / sum exact^2), taken separately over
// interior particles and over particles whose support is cut by the box (distance to a face
// below the support radius). The order is the least-squares slope of log RMSE against log d.
#include <string>
#include <vector>

namespace ryushi {

struct PatchTestOptions {
  int dimension = 2;
  std::string op = "laplacian-sph2";
  double disorder = 0.0;  // displacement of each particle, up to this fraction of d
  std::string kernel = "wendland_c2";
  double smoothing_ratio = 1.5;  // h / d
  std::vector<double> spacings;  // default: 1/20 ... 1/160 (2D), 1/20, 1/30, 1/40 (3D)
  unsigned seed = 1;
};

struct PatchTestRow {
  double spacing;
  std::size_t interior, boundary;
  double rmse_interior, rmse_boundary;
  double seconds;  // operator evaluation only, all particles
};

struct PatchTestResult {
  std::vector<PatchTestRow> rows;
  double order_interior, order_boundary;
};

const std::vector<std::string>& patch_test_operators();
// Throws std::invalid_argument for an unknown operator, dimension or option.
PatchTestResult run_patch_test(const PatchTestOptions& options);
double least_squares_order(const std::vector<double>& spacing, const std::vector<double>& error);

}  // namespace ryushi
