#pragma once
// Smoothing kernels W(r, h), normalised to integrate to 1 in 2D and 3D, chosen by name in the
// scene ([particles] kernel). Support radius = support_factor() * h:
//   cubic_spline  2h   sigma (1 - 3/2 q^2 + 3/4 q^3 | 1/4 (2-q)^3)      seed 002 eq. 11, seed 001 eq. 13
//   quintic_spline 3h  sigma ((3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5)          Morris et al. 1997
//   wendland_c2   2h   sigma (1 - q/2)^4 (2q + 1)                       Wendland 1995
//   spiky         2h   sigma (2 - q)^3, h = r_e                          shallow-water paper eq. 8
//   mps           h    sigma (h/r - 1), h = r_e                          MPS paper eq. 5 (normalised;
//                      MPS operators divide by n0, so the constant cancels there)
// grad_factor(r) = (dW/dr)/r, so that grad_i W_ij = (x_i - x_j) * grad_factor(r_ij); finite at
// r = 0 for every kernel except spiky (a cusp: dW/dr != 0 at r = 0) and mps (singular weight),
// both by design of those kernels.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace ryushi {

enum class KernelType { CubicSpline, QuinticSpline, WendlandC2, Spiky, Mps };

inline const std::vector<std::string>& kernel_names() {
  static const std::vector<std::string> names{"cubic_spline", "quintic_spline", "wendland_c2", "spiky",
                                              "mps"};
  return names;
}

inline KernelType kernel_from_name(const std::string& name) {
  const auto& n = kernel_names();
  for (std::size_t k = 0; k < n.size(); ++k)
    if (n[k] == name) return static_cast<KernelType>(k);
  throw std::invalid_argument("unknown kernel '" + name + "'");
}

template <int D>
class Kernel {
 public:
  Kernel(KernelType type, double h) : type_(type), h_(h), inv_h_(1.0 / h) {
    const double pi = std::numbers::pi;
    const double hd = D == 2 ? h * h : h * h * h;
    double c = 0;
    switch (type) {
      case KernelType::CubicSpline:
        c = D == 2 ? 10.0 / (7.0 * pi) : 1.0 / pi;
        break;
      case KernelType::QuinticSpline:
        c = D == 2 ? 7.0 / (478.0 * pi) : 1.0 / (120.0 * pi);
        break;
      case KernelType::WendlandC2:
        c = D == 2 ? 7.0 / (4.0 * pi) : 21.0 / (16.0 * pi);
        break;
      case KernelType::Spiky:
        c = D == 2 ? 5.0 / (16.0 * pi) : 15.0 / (64.0 * pi);
        break;
      case KernelType::Mps:
        c = D == 2 ? 1.0 / pi : 3.0 / (2.0 * pi);
        break;
    }
    sigma_ = c / hd;
  }
  double h() const { return h_; }
  KernelType type() const { return type_; }
  double support_factor() const {
    switch (type_) {
      case KernelType::QuinticSpline:
        return 3.0;
      case KernelType::Mps:
        return 1.0;
      default:
        return 2.0;
    }
  }
  double support() const { return support_factor() * h_; }

  double w(double r) const {
    const double q = r * inv_h_;
    switch (type_) {
      case KernelType::CubicSpline: {
        if (q >= 2.0) return 0.0;
        if (q < 1.0) return sigma_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
        const double t = 2.0 - q;
        return sigma_ * 0.25 * t * t * t;
      }
      case KernelType::QuinticSpline: {
        if (q >= 3.0) return 0.0;
        auto p5 = [](double t) { return t > 0 ? t * t * t * t * t : 0.0; };
        return sigma_ * (p5(3.0 - q) - 6.0 * p5(2.0 - q) + 15.0 * p5(1.0 - q));
      }
      case KernelType::WendlandC2: {
        if (q >= 2.0) return 0.0;
        const double t = 1.0 - 0.5 * q, t2 = t * t;
        return sigma_ * t2 * t2 * (2.0 * q + 1.0);
      }
      case KernelType::Spiky: {
        if (q >= 2.0) return 0.0;
        const double t = 2.0 - q;
        return sigma_ * t * t * t;
      }
      case KernelType::Mps:
        return mps_weight(q, sigma_);
    }
    return 0.0;
  }

  // w(sqrt(r2[k])) of each squared distance (out may be r2 itself), for loops whose kernel is
  // MPS: one branch-free loop that the compiler runs two pairs to a vector instruction, where
  // the square root and the division are most of an MPS pair's cost. The same values as w.
  void mps_weights(const double* r2, double* out, std::size_t n) const {
    if (type_ != KernelType::Mps) throw std::logic_error("mps_weights on a kernel that is not mps");
    const double inv_h = inv_h_, sigma = sigma_;
    for (std::size_t k = 0; k < n; ++k) out[k] = mps_weight(std::sqrt(r2[k]) * inv_h, sigma);
  }

  // sum_k w(sqrt(r2[k])) for the Wendland C2 kernel, in one branch-free loop (the MPS source's
  // smooth density, over the rows the number density narrows). The same value as summing w.
  double wendland_sum(const double* r2, std::size_t n) const {
    if (type_ != KernelType::WendlandC2)
      throw std::logic_error("wendland_sum on a kernel that is not wendland_c2");
    const double inv_h = inv_h_;
    double sum = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double q = std::sqrt(r2[k]) * inv_h, t = std::max(1.0 - 0.5 * q, 0.0), t2 = t * t;
      sum += t2 * t2 * (2.0 * q + 1.0);
    }
    return sigma_ * sum;
  }

  double grad_factor(double r) const {
    const double q = r * inv_h_;
    const double s = sigma_ * inv_h_ * inv_h_;  // dW/dr / r = s * (df/dq) / q
    switch (type_) {
      case KernelType::CubicSpline:
        return cubic_grad_factor(q, s);
      case KernelType::QuinticSpline: {
        if (q >= 3.0) return 0.0;
        auto p4 = [](double t) { return t > 0 ? t * t * t * t : 0.0; };
        // df/dq = -5 g(q), g = (3-q)^4 - 6 (2-q)^4 + 15 (1-q)^4 with g(0) = 0 and g'(0) = 24,
        // so (df/dq)/q -> -120 as q -> 0.
        if (q < 1e-8) return -120.0 * s;
        return -5.0 * s * (p4(3.0 - q) - 6.0 * p4(2.0 - q) + 15.0 * p4(1.0 - q)) / q;
      }
      case KernelType::WendlandC2: {
        if (q >= 2.0) return 0.0;
        const double t = 1.0 - 0.5 * q;
        return -5.0 * s * t * t * t;
      }
      case KernelType::Spiky: {
        if (q >= 2.0) return 0.0;
        const double t = 2.0 - q;
        return -3.0 * s * t * t / q;
      }
      case KernelType::Mps:
        return q >= 1.0 ? 0.0 : -s / (q * q * q);
    }
    return 0.0;
  }

  // grad_factor of each r (the same values), with the kernel's type decided once for the whole
  // array: the cubic spline's loop is branch-free and the compiler runs it two pairs to a vector
  // instruction, square roots and divisions included (the stencil's gather was bound by them).
  void grad_factors(const double* r, double* out, std::size_t n) const {
    if (type_ != KernelType::CubicSpline) {
      for (std::size_t k = 0; k < n; ++k) out[k] = grad_factor(r[k]);
      return;
    }
    const double inv_h = inv_h_, s = sigma_ * inv_h_ * inv_h_;
    for (std::size_t k = 0; k < n; ++k) out[k] = cubic_grad_factor(r[k] * inv_h, s);
  }

 private:
  static double mps_weight(double q, double sigma) {
    // A select, not a branch: MPS lists hold a skin beyond r_e, so q >= 1 is common.
    const double inside = sigma * (1.0 / q - 1.0);
    return q < 1.0 ? inside : 0.0;
  }
  static double cubic_grad_factor(double q, double s) {
    // Both pieces, then a select: whether a neighbour lies inside q = 1 is a coin toss, and
    // the branch mispredicted often enough to be a third of the ISPH stencil's gather.
    const double t = std::max(2.0 - q, 0.0);
    const double inner = s * (-3.0 + 2.25 * q);
    const double outer = -s * 0.75 * t * t / std::max(q, 1.0);
    return q < 1.0 ? inner : outer;
  }

  KernelType type_;
  double h_, inv_h_, sigma_ = 0;
};

}  // namespace ryushi
