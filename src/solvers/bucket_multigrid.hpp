#pragma once
// Bucket-based multigrid (BMG) preconditioner, paper "粒子法におけるポアソンソルバのマルチグリッド
// 法を用いたGPU高速計算" sections 3-4:
//  - level 1 groups the particles (level 0) into buckets of width = the influence radius, each
//    further level groups 2^D buckets (width doubling);
//  - piecewise-constant prolongation P (eq. 11), restriction P^T;
//  - Galerkin coarse operator A_c = P^T A P (eq. 10), at most 3^D nonzeros per coarse row, built
//    per coarse row from its members (Algorithm 1's slots, gathered instead of atomically added);
//  - scale correction A_c = 1/2 P^T A P from level 1 down, not between levels 0 and 1 (eq. 18);
//  - weighted Jacobi smoothing, V or W cycles, bottom level when n <= bottom_size;
//  - the whole hierarchy in float (mixed precision) or double.
// It is a linear, symmetric preconditioner for a symmetric A (same smoother before and after).
// Block rows (a vector unknown per particle, MPH-I paper eqs. 5-6): with block_size b the
// unknowns of particle i are rows i b .. i b + b - 1, and each component is summed over a bucket
// on its own, so a coarse level has b unknowns per bucket.
#include <memory>
#include <span>
#include <vector>

#include "solvers/csr_matrix.hpp"
#include "solvers/krylov.hpp"

namespace ryushi::solvers {

struct MultigridOptions {
  enum class Cycle { V, W };
  Cycle cycle = Cycle::W;
  bool scale_correction = true;  // W + scale correction = the paper's S-W cycle
  bool single_precision = true;  // hierarchy and cycle in float, Krylov method in double
  int pre_smoothing = 1, post_smoothing = 1, bottom_smoothing = 2;
  std::size_t bottom_size = 1024;
  double jacobi_weight = 2.0 / 3.0;
  // Each level's weight at most 4 / (3 rho), rho the largest eigenvalue of D^-1 A estimated by
  // power iteration at setup: for matrices that are not diagonally dominant (MPH-I's, rho about
  // 6 against a Laplacian's 2), where a fixed weight's sweep amplifies the upper modes.
  bool bound_jacobi_weight = false;
};

struct MultigridLevelInfo {
  std::size_t rows, nonzeros;
};

class BucketMultigrid final : public Preconditioner {
 public:
  // coordinates: (rows / block_size) x dimension, row-major; bucket_width: the influence radius
  // r_e (no entry of A couples particles further apart than one bucket). The finest
  // level reads A's row pointers and columns (and, in double, its values) in place: A must
  // outlive the preconditioner and keep its entries while it is applied.
  BucketMultigrid(const CsrMatrix<double>& A, std::span<const double> coordinates, int dimension,
                  double bucket_width, const MultigridOptions& options = {}, int block_size = 1);
  ~BucketMultigrid() override;
  // The hierarchy for a new matrix (same options), in the storage of the last one: the pressure
  // pipeline sets up every step, and fresh large arrays cost the kernel's page zeroing.
  void rebuild(const CsrMatrix<double>& A, std::span<const double> coordinates, int dimension,
               double bucket_width, int block_size = 1);
  void apply(std::span<const double> r, std::span<double> z) const override;
  std::string name() const override;
  std::vector<MultigridLevelInfo> levels() const;
  std::size_t bytes() const;
  struct Impl;  // float or double hierarchy (bucket_multigrid.cpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace ryushi::solvers
