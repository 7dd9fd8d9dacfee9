#include "systems/neighbour/cell_grid.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ryushi {

template <int D>
void CellGrid<D>::build(const Domain<D>& domain, double radius, std::span<const Vec<D>> x) {
  origin_ = domain.min;
  periodic_ = domain.periodic;
  for (int a = 0; a < D; ++a) {
    double L = domain.max[a] - domain.min[a];
    std::int64_t n;
    if (periodic_[a]) {
      // Whole cells tile a periodic axis; each at least `radius` wide.
      n = static_cast<std::int64_t>(std::floor(L / radius));
      if (n < 3)
        throw std::invalid_argument("periodic axis " + std::to_string(a) +
                                    " is shorter than three neighbour-search radii (support + skin)");
    } else {
      // A hair wider than the radius so that rounding never puts two particles exactly
      // one radius apart two cells apart.
      n = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(L / (radius * (1 + 1e-9)))));
    }
    dims_[a] = n;
    inv_cell_[a] = periodic_[a] ? n / L : 1.0 / (radius * (1 + 1e-9));
  }
  std::size_t ncell = 1;
  for (auto n : dims_) ncell *= static_cast<std::size_t>(n);

  const std::size_t N = x.size();
  cell_of_.resize(N);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      std::array<std::int64_t, D> c;
      for (int a = 0; a < D; ++a) {
        auto k = static_cast<std::int64_t>(std::floor((x[i][a] - origin_[a]) * inv_cell_[a]));
        if (periodic_[a]) {
          k %= dims_[a];
          if (k < 0) k += dims_[a];
        }
        c[a] = std::clamp<std::int64_t>(k, 0, dims_[a] - 1);  // strays are caught elsewhere
      }
      cell_of_[i] = static_cast<std::uint32_t>(cell_at(c));
    }
  });

  // Counting sort by cell (stable, so equal cells keep index order).
  cell_start_.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < N; ++i) ++cell_start_[cell_of_[i] + 1];
  for (std::size_t c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(N);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < N; ++i) sorted_[fill[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
}

template <int D>
std::array<std::int64_t, D> CellGrid<D>::coords(std::uint32_t cell) const {
  std::array<std::int64_t, D> c;
  std::int64_t rest = cell;
  for (int a = 0; a < D; ++a) {
    c[a] = rest % dims_[a];
    rest /= dims_[a];
  }
  return c;
}

template <int D>
std::int64_t CellGrid<D>::cell_at(std::array<std::int64_t, D> c) const {
  std::int64_t flat = 0, stride = 1;
  for (int a = 0; a < D; ++a) {
    std::int64_t k = c[a];
    if (k < 0 || k >= dims_[a]) {
      if (!periodic_[a]) return -1;
      k = (k % dims_[a] + dims_[a]) % dims_[a];
    }
    flat += k * stride;
    stride *= dims_[a];
  }
  return flat;
}

template class CellGrid<2>;
template class CellGrid<3>;

}  // namespace ryushi
