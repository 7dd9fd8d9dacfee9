#pragma once
// Fixed-size vector and tensor types shared by every system. Dimension D is a template
// parameter dispatched once at scene load (see methods/dispatch.hpp).
#include <Eigen/Core>

namespace ryushi {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
template <int D>
using Mat = Eigen::Matrix<double, D, D>;

}  // namespace ryushi
