#include "systems/neighbour/neighbour_search.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace ryushi {

template <int D>
void build_neighbour_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                          CellGrid<D>& grid, NeighbourList& out) {
  grid.build(domain, radius, x);
  const std::size_t N = x.size();
  const double r2 = radius * radius;
  const bool periodic = domain.any_periodic();

  // Blocks of particles gather their neighbours into private buffers (no atomics), then the
  // buffers are concatenated into the CSR arrays. One distance pass, one copy.
  constexpr std::size_t kBlock = 2048;
  const std::size_t nblocks = (N + kBlock - 1) / kBlock;
  std::vector<std::vector<std::uint32_t>> buffers(nblocks);
  out.offsets.assign(N + 1, 0);

  std::array<std::array<std::int64_t, D>, (D == 2 ? 9 : 27)> stencil;
  {
    std::size_t k = 0;
    std::array<std::int64_t, D> o;
    auto fill = [&](auto&& self, int a) -> void {
      if (a == D) {
        stencil[k++] = o;
        return;
      }
      for (std::int64_t d = -1; d <= 1; ++d) {
        o[a] = d;
        self(self, a + 1);
      }
    };
    fill(fill, 0);
  }

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nblocks, 1), [&](auto range) {
    for (std::size_t b = range.begin(); b != range.end(); ++b) {
      auto& buf = buffers[b];
      buf.clear();
      std::size_t end = std::min(N, (b + 1) * kBlock);
      for (std::size_t i = b * kBlock; i < end; ++i) {
        auto c = grid.coords(grid.cell_of(i));
        std::uint32_t before = static_cast<std::uint32_t>(buf.size());
        for (auto& o : stencil) {
          std::array<std::int64_t, D> cc;
          for (int a = 0; a < D; ++a) cc[a] = c[a] + o[a];
          std::int64_t cell = grid.cell_at(cc);
          if (cell < 0) continue;
          auto sorted = grid.sorted();
          for (std::uint32_t k = grid.cell_start(cell); k < grid.cell_start(cell + 1); ++k) {
            std::uint32_t j = sorted[k];
            if (j == i) continue;
            Vec<D> d = periodic ? domain.displacement(x[i], x[j]) : Vec<D>(x[i] - x[j]);
            if (d.squaredNorm() <= r2) buf.push_back(j);
          }
        }
        out.offsets[i + 1] = static_cast<std::uint32_t>(buf.size()) - before;
      }
    }
  });
  for (std::size_t i = 0; i < N; ++i) out.offsets[i + 1] += out.offsets[i];
  out.indices.resize(out.offsets[N]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nblocks, 1), [&](auto range) {
    for (std::size_t b = range.begin(); b != range.end(); ++b)
      std::copy(buffers[b].begin(), buffers[b].end(), out.indices.begin() + out.offsets[b * kBlock]);
  });
  out.radius = radius;
}

template void build_neighbour_list<2>(const Domain<2>&, double, std::span<const Vec<2>>,
                                      CellGrid<2>&, NeighbourList&);
template void build_neighbour_list<3>(const Domain<3>&, double, std::span<const Vec<3>>,
                                      CellGrid<3>&, NeighbourList&);

}  // namespace ryushi
