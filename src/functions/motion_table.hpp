#pragma once
// A tabulated displacement for a [[solid]] (`displacement_table`): a CSV with a header and rows
// t, dx, dy[, dz], times increasing. Between rows the displacement is linear (the velocity that
// row's slope); before the first row it is the first, after the last the last (at rest).
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace ryushi {

struct MotionSample {
  double t;
  std::array<double, 3> displacement;
};

// Throws std::runtime_error("FILE:LINE: problem").
std::vector<MotionSample> read_motion_table(const std::string& path, int dimension);

// Displacement and velocity at time t (table not empty). The acceleration of a piecewise-linear
// motion is a train of jumps; motion_acceleration spreads each over one row interval: the change
// of the slope between t - span/2 and t + span/2, span the interval that holds t.
std::pair<std::array<double, 3>, std::array<double, 3>> sample_motion(const std::vector<MotionSample>& table,
                                                                      double t);
std::array<double, 3> motion_acceleration(const std::vector<MotionSample>& table, double t);

}  // namespace ryushi
