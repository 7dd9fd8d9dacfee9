#include "systems/neighbour/neighbour_search.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <type_traits>

namespace ryushi {

namespace {

template <int D>
constexpr std::size_t kStencil = D == 2 ? 9 : 27;

template <int D>
std::array<std::array<std::int64_t, D>, kStencil<D>> stencil() {
  std::array<std::array<std::int64_t, D>, kStencil<D>> s{};
  for (std::size_t k = 0; k < kStencil<D>; ++k) {
    std::size_t rest = k;
    for (int a = 0; a < D; ++a) {
      s[k][a] = static_cast<std::int64_t>(rest % 3) - 1;
      rest /= 3;
    }
  }
  return s;
}

}  // namespace

template <int D>
void build_neighbour_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                          CellGrid<D>& grid, NeighbourList& out, std::span<const std::int32_t> kind,
                          std::int32_t skip_kind) {
  grid.build(domain, radius, x);
  const std::size_t N = x.size();
  const double r2 = radius * radius;
  const bool periodic = domain.any_periodic();
  const bool skipping = !kind.empty();
  const auto offsets = stencil<D>();
  const auto sorted = grid.sorted();

  // Work goes cell by cell: the candidates of the 3^D surrounding cells are gathered once into
  // contiguous arrays and every particle of the cell is tested against them. Each chunk of cells
  // writes into its own buffer (no atomics); a second pass scatters the lists into CSR order.
  const std::size_t ncell = grid.cell_count();
  constexpr std::size_t kCellsPerChunk = 64;
  const std::size_t nchunks = (ncell + kCellsPerChunk - 1) / kCellsPerChunk;
  std::vector<std::vector<std::uint32_t>> buffers(nchunks);
  std::vector<std::uint32_t> count(N), start(N);

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nchunks, 1), [&](auto range) {
    std::vector<std::uint32_t> cand;
    std::vector<Vec<D>> cand_x;
    std::vector<char> cand_skip;
    for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk) {
      auto& buf = buffers[chunk];
      buf.clear();
      const std::size_t c_end = std::min(ncell, (chunk + 1) * kCellsPerChunk);
      for (std::size_t c = chunk * kCellsPerChunk; c < c_end; ++c) {
        const std::uint32_t first = grid.cell_start(c), last = grid.cell_start(c + 1);
        if (first == last) continue;
        cand.clear();
        cand_x.clear();
        cand_skip.clear();
        auto cc = grid.coords(static_cast<std::uint32_t>(c));
        for (auto& o : offsets) {
          std::array<std::int64_t, D> nc;
          for (int a = 0; a < D; ++a) nc[a] = cc[a] + o[a];
          std::int64_t cell = grid.cell_at(nc);
          if (cell < 0) continue;
          for (std::uint32_t k = grid.cell_start(cell); k < grid.cell_start(cell + 1); ++k) {
            std::uint32_t j = sorted[k];
            cand.push_back(j);
            cand_x.push_back(x[j]);
            cand_skip.push_back(skipping && kind[j] == skip_kind);
          }
        }
        for (std::uint32_t k = first; k < last; ++k) {
          const std::uint32_t i = sorted[k];
          const Vec<D> xi = x[i];
          const bool i_skip = skipping && kind[i] == skip_kind;
          start[i] = static_cast<std::uint32_t>(buf.size());
          for (std::size_t q = 0; q < cand.size(); ++q) {
            if (i_skip && cand_skip[q]) continue;
            Vec<D> d = periodic ? domain.displacement(xi, cand_x[q]) : Vec<D>(xi - cand_x[q]);
            if (d.squaredNorm() <= r2 && cand[q] != i) buf.push_back(cand[q]);
          }
          count[i] = static_cast<std::uint32_t>(buf.size()) - start[i];
        }
      }
    }
  });

  out.offsets.assign(N + 1, 0);
  for (std::size_t i = 0; i < N; ++i) out.offsets[i + 1] = out.offsets[i] + count[i];
  out.indices.resize(out.offsets[N]);
  // Scatter: the chunk a particle belongs to follows from its cell.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const auto& buf = buffers[grid.cell_of(i) / kCellsPerChunk];
      std::copy_n(buf.begin() + start[i], count[i], out.indices.begin() + out.offsets[i]);
      // Ascending order within a list: deterministic, and gathers walk memory forwards. With the
      // particles in cell order the candidates come out ascending already (stencil cells are
      // visited in increasing cell index); only lists that are not need the sort.
      auto first = out.indices.begin() + out.offsets[i], last = out.indices.begin() + out.offsets[i + 1];
      if (!std::is_sorted(first, last)) std::sort(first, last);
    }
  });
  out.radius = radius;
  ++out.builds;
}

template <int D>
void filter_neighbour_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                           const NeighbourList& candidates, NeighbourList& out,
                           std::vector<std::uint32_t>& scratch) {
  const std::size_t N = candidates.size();
  const double r2 = radius * radius;
  const bool periodic = domain.any_periodic();
  // One distance pass writes the survivors at the candidates' offsets (scratch), then a copy
  // packs them: no second distance evaluation.
  scratch.resize(candidates.indices.size());
  std::vector<std::uint32_t> count(N);
  auto pass = [&](auto periodic_axes) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 2048), [&](auto r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const Vec<D> xi = x[i];
        std::uint32_t* dst = scratch.data() + candidates.offsets[i];
        std::uint32_t c = 0;
        for (auto j : candidates.of(i)) {
          Vec<D> d;
          if constexpr (decltype(periodic_axes)::value)
            d = domain.displacement(xi, x[j]);
          else
            d = xi - x[j];
          dst[c] = j;
          c += d.squaredNorm() <= r2;  // branch-free: which candidates survive is not predictable
        }
        count[i] = c;
      }
    });
  };
  if (periodic)
    pass(std::true_type{});
  else
    pass(std::false_type{});
  out.offsets.resize(N + 1);
  out.offsets[0] = 0;
  for (std::size_t i = 0; i < N; ++i) out.offsets[i + 1] = out.offsets[i] + count[i];
  out.indices.resize(out.offsets[N]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      std::copy_n(scratch.begin() + candidates.offsets[i], count[i], out.indices.begin() + out.offsets[i]);
  });
  out.radius = radius;
}

template <int D>
std::pair<double, double> max_displacement_and_speed(const Domain<D>& domain, std::span<const Vec<D>> x,
                                                     std::span<const Vec<D>> ref, std::span<const Vec<D>> v) {
  using Pair = std::pair<double, double>;
  const bool periodic = domain.any_periodic();
  auto [d2, v2] = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, x.size(), 4096), Pair{0.0, 0.0},
      [&](auto r, Pair m) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          // The minimum image: a particle wrapped across a periodic side has not moved far.
          Vec<D> d = periodic ? domain.displacement(x[i], ref[i]) : Vec<D>(x[i] - ref[i]);
          m.first = std::max(m.first, d.squaredNorm());
          if (!v.empty()) m.second = std::max(m.second, v[i].squaredNorm());
        }
        return m;
      },
      [](Pair a, Pair b) {
        return Pair{std::max(a.first, b.first), std::max(a.second, b.second)};
      });
  return {std::sqrt(d2), std::sqrt(v2)};
}

template std::pair<double, double> max_displacement_and_speed<2>(const Domain<2>&, std::span<const Vec<2>>,
                                                                 std::span<const Vec<2>>,
                                                                 std::span<const Vec<2>>);
template std::pair<double, double> max_displacement_and_speed<3>(const Domain<3>&, std::span<const Vec<3>>,
                                                                 std::span<const Vec<3>>,
                                                                 std::span<const Vec<3>>);
template void filter_neighbour_list<2>(const Domain<2>&, double, std::span<const Vec<2>>,
                                       const NeighbourList&, NeighbourList&, std::vector<std::uint32_t>&);
template void filter_neighbour_list<3>(const Domain<3>&, double, std::span<const Vec<3>>,
                                       const NeighbourList&, NeighbourList&, std::vector<std::uint32_t>&);
template void build_neighbour_list<2>(const Domain<2>&, double, std::span<const Vec<2>>, CellGrid<2>&,
                                      NeighbourList&, std::span<const std::int32_t>, std::int32_t);
template void build_neighbour_list<3>(const Domain<3>&, double, std::span<const Vec<3>>, CellGrid<3>&,
                                      NeighbourList&, std::span<const std::int32_t>, std::int32_t);

}  // namespace ryushi
