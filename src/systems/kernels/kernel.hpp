#pragma once
// Smoothing kernels W(r, h) with support radius 2h, in 2D and 3D.
//   cubic spline (seed 002 eq. 11 in 2D; seed 001 eq. 13 in 3D) and Wendland C2.
// grad_factor(r) = (dW/dr)/r, so that grad_i W_ij = (x_i - x_j) * grad_factor(r_ij); written
// in a form that stays finite at r = 0.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ryushi {

enum class KernelType { CubicSpline, WendlandC2 };

inline KernelType kernel_from_name(const std::string& name) {
  if (name == "cubic_spline") return KernelType::CubicSpline;
  if (name == "wendland_c2") return KernelType::WendlandC2;
  throw std::invalid_argument("unknown kernel '" + name + "'");
}

template <int D>
class Kernel {
 public:
  Kernel(KernelType type, double h) : type_(type), h_(h), inv_h_(1.0 / h) {
    const double pi = std::numbers::pi;
    double hd = D == 2 ? h * h : h * h * h;
    if (type == KernelType::CubicSpline)
      sigma_ = (D == 2 ? 10.0 / (7.0 * pi) : 1.0 / pi) / hd;
    else
      sigma_ = (D == 2 ? 7.0 / (4.0 * pi) : 21.0 / (16.0 * pi)) / hd;
  }
  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  KernelType type() const { return type_; }

  double w(double r) const {
    double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    if (type_ == KernelType::CubicSpline) {
      if (q < 1.0) return sigma_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
      double t = 2.0 - q;
      return sigma_ * 0.25 * t * t * t;
    }
    double t = 1.0 - 0.5 * q;
    double t2 = t * t;
    return sigma_ * t2 * t2 * (2.0 * q + 1.0);
  }

  double grad_factor(double r) const {
    double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    double s = sigma_ * inv_h_ * inv_h_;
    if (type_ == KernelType::CubicSpline) {
      if (q < 1.0) return s * (-3.0 + 2.25 * q);
      double t = 2.0 - q;
      return -s * 0.75 * t * t / q;
    }
    double t = 1.0 - 0.5 * q;
    return -5.0 * s * t * t * t;
  }

 private:
  KernelType type_;
  double h_, inv_h_, sigma_;
};

}  // namespace ryushi
