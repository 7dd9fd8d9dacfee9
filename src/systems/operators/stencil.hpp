#pragma once
// The geometry of one particle's neighbourhood, gathered once: for k over neighbours.of(i) in
// order, r_k = x_k - x_i (minimum image), |r_k|, the kernel's gradient factor F_k (so that
// gW_ik = -F_k r_k) and the volume V_k. The corrected operators pass over the neighbours four or
// five times (moment matrix, quadratic moments, the B_i system, the weights, the gradient
// correction); with the stencil each pass reads these arrays instead of recomputing a minimum-
// image offset, a square root and the kernel, and a system that needs several operators at one
// particle (the ISPH predictor, the pressure rows, the shifting) gathers once for all of them.
#include <span>
#include <vector>

#include "systems/operators/particle_view.hpp"

namespace ryushi {

template <int D>
struct Stencil {
  std::size_t i = 0;
  std::span<const std::uint32_t> neighbours;
  std::vector<Vec<D>> r;
  std::vector<double> len;
  std::vector<double> factor;
  std::vector<double> volume;
  double h = 0;  // the kernel's smoothing length

  std::size_t size() const { return neighbours.size(); }
  Vec<D> grad_w(std::size_t k) const { return -factor[k] * r[k]; }

  void gather(const ParticleView<D>& v, std::size_t particle) {
    i = particle;
    neighbours = v.neighbours.of(particle);
    h = v.kernel.h();
    const std::size_t n = neighbours.size();
    r.resize(n);
    len.resize(n);
    factor.resize(n);
    volume.resize(n);
    // The scattered reads first, then the arithmetic over contiguous arrays, which vectorises
    // (the square roots and the kernel's division bound the gather when they were interleaved).
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t j = neighbours[k];
      r[k] = v.r(particle, j);
      volume[k] = v.volume[j];
    }
    for (std::size_t k = 0; k < n; ++k) len[k] = r[k].norm();
    v.kernel.grad_factors(len.data(), factor.data(), n);
  }
};

// The stencil of particle i in a per-thread buffer, for the operators called with (view, i): it
// stays valid until the calling thread gathers again, so a function that takes it may call only
// functions of the stencil, never another (view, i) form.
template <int D>
const Stencil<D>& gathered_stencil(const ParticleView<D>& v, std::size_t i) {
  thread_local Stencil<D> stencil;
  stencil.gather(v, i);
  return stencil;
}

}  // namespace ryushi
