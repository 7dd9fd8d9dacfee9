#include "systems/neighbour/neighbour_search.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <type_traits>

#include "systems/neighbour/filter_rows.hpp"

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

namespace {

// Every particle's neighbours, gathered chunk of cells by chunk of cells: row i is
// buffers[chunk of i's cell][start[i], start[i] + count[i]), in ascending order.
struct GatheredRows {
  static constexpr std::size_t kCellsPerChunk = 64;
  std::vector<std::vector<std::uint32_t>> buffers;
  std::vector<std::uint32_t> count, start, chunk_of;
  std::span<std::uint32_t> row(std::size_t i) { return {buffers[chunk_of[i]].data() + start[i], count[i]}; }
};

template <int D>
void gather_neighbour_rows(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                           CellGrid<D>& grid, std::span<const std::int32_t> kind, std::int32_t skip_kind,
                           GatheredRows& rows) {
  grid.build(domain, radius, x);
  const std::size_t N = x.size();
  const double r2 = radius * radius;
  const bool periodic = domain.any_periodic();
  const bool skipping = !kind.empty();
  const auto offsets = stencil<D>();
  const auto sorted = grid.sorted();

  // Work goes cell by cell: the candidates of the 3^D surrounding cells are gathered once into
  // contiguous arrays (one per axis) and every particle of the cell is tested against them. Each
  // chunk of cells writes into its own buffer (no atomics); the caller then writes the rows out
  // in its own form. The test writes every candidate and advances by the outcome, without a
  // branch: about one candidate in seven is a neighbour (3D: 103 of 729), at random, and a
  // branch on it mispredicted often enough to be most of the build.
  const std::size_t ncell = grid.cell_count();
  constexpr std::size_t kCellsPerChunk = GatheredRows::kCellsPerChunk;
  const std::size_t nchunks = (ncell + kCellsPerChunk - 1) / kCellsPerChunk;
  auto& buffers = rows.buffers;
  buffers.assign(nchunks, {});
  auto& count = rows.count;
  auto& start = rows.start;
  count.resize(N);
  start.resize(N);
  rows.chunk_of.resize(N);

  // One stencil cell's run of candidates and the bounding box of their positions.
  struct Segment {
    std::uint32_t begin, end;
    Vec<D> lo, hi;
    bool own;  // the particle's own cell: the only one that holds the particle itself
  };
  auto gather = [&](auto periodic_axes, auto skipping_kind) {
    constexpr bool kPeriodic = decltype(periodic_axes)::value, kSkipping = decltype(skipping_kind)::value;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nchunks, 1), [&](auto range) {
      std::vector<std::uint32_t> cand;
      std::array<std::vector<double>, D> cand_x;
      std::vector<std::uint8_t> cand_keep;  // 0 where a pair with a skipped particle is left out
      std::vector<Segment> segments;
      for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk) {
        auto& buf = buffers[chunk];
        std::size_t used = 0;  // buf grows as a high-water mark; entries past `used` are scratch
        const std::size_t c_end = std::min(ncell, (chunk + 1) * kCellsPerChunk);
        for (std::size_t c = chunk * kCellsPerChunk; c < c_end; ++c) {
          const std::uint32_t first = grid.cell_start(c), last = grid.cell_start(c + 1);
          if (first == last) continue;
          cand.clear();
          for (auto& axis : cand_x) axis.clear();
          cand_keep.clear();
          segments.clear();
          auto cc = grid.coords(static_cast<std::uint32_t>(c));
          for (auto& o : offsets) {
            std::array<std::int64_t, D> nc;
            for (int a = 0; a < D; ++a) nc[a] = cc[a] + o[a];
            std::int64_t cell = grid.cell_at(nc);
            if (cell < 0 || grid.cell_start(cell) == grid.cell_start(cell + 1)) continue;
            Segment seg{static_cast<std::uint32_t>(cand.size()), 0, x[sorted[grid.cell_start(cell)]],
                        x[sorted[grid.cell_start(cell)]], std::size_t(cell) == c};
            for (std::uint32_t k = grid.cell_start(cell); k < grid.cell_start(cell + 1); ++k) {
              std::uint32_t j = sorted[k];
              cand.push_back(j);
              for (int a = 0; a < D; ++a) cand_x[a].push_back(x[j][a]);
              if constexpr (kSkipping) cand_keep.push_back(kind[j] == skip_kind ? 0 : 1);
              seg.lo = seg.lo.cwiseMin(x[j]);
              seg.hi = seg.hi.cwiseMax(x[j]);
            }
            seg.end = static_cast<std::uint32_t>(cand.size());
            segments.push_back(seg);
          }
          const std::size_t M = cand.size();
          for (std::uint32_t k = first; k < last; ++k) {
            const std::uint32_t i = sorted[k];
            const Vec<D> xi = x[i];
            // A skipped particle keeps only the candidates that are not skipped; others keep all.
            const std::uint8_t i_kept = kSkipping && kind[i] == skip_kind ? 0 : 1;
            if (buf.size() < used + M) buf.resize(std::max(2 * buf.size(), used + M));
            std::uint32_t* dst = buf.data() + used;
            std::uint32_t n = 0;
            for (const Segment& seg : segments) {
              if constexpr (!kPeriodic) {
                // A cell whose candidates' box lies beyond the radius holds no neighbour (in 3D
                // about a quarter of the 27 cells, by where the particle sits in its own). The
                // box distance is computed as the pair distances are, with rounding monotone in
                // each operand: never above any of its candidates' computed distance.
                double box2 = 0;
                for (int a = 0; a < D; ++a) {
                  const double e = std::max({seg.lo[a] - xi[a], 0.0, xi[a] - seg.hi[a]});
                  box2 += e * e;
                }
                if (box2 > r2) continue;
              }
              auto test = [&](auto own_cell) {
                auto kept = [&](std::size_t q) -> std::uint32_t {
                  double r2q;
                  if constexpr (kPeriodic) {
                    Vec<D> xq;
                    for (int a = 0; a < D; ++a) xq[a] = cand_x[a][q];
                    r2q = domain.displacement(xi, xq).squaredNorm();
                  } else {
                    r2q = 0;
                    for (int a = 0; a < D; ++a) {
                      const double e = xi[a] - cand_x[a][q];
                      r2q += e * e;
                    }
                  }
                  bool keep = r2q <= r2;
                  if constexpr (decltype(own_cell)::value) keep &= cand[q] != i;
                  if constexpr (kSkipping) keep &= (cand_keep[q] | i_kept) != 0;
                  return static_cast<std::uint32_t>(keep);
                };
                // Four candidates per round: each is written after the kept ones before it
                // (a later write overwrites one that was not kept), and the count advances once
                // per round, so the chain of dependent additions through n is a quarter as long.
                std::size_t q = seg.begin;
                for (; q + 4 <= seg.end; q += 4) {
                  const std::uint32_t k0 = kept(q), k1 = kept(q + 1), k2 = kept(q + 2), k3 = kept(q + 3);
                  dst[n] = cand[q];
                  dst[n + k0] = cand[q + 1];
                  dst[n + k0 + k1] = cand[q + 2];
                  dst[n + k0 + k1 + k2] = cand[q + 3];
                  n += k0 + k1 + k2 + k3;
                }
                for (; q < seg.end; ++q) {
                  dst[n] = cand[q];
                  n += kept(q);
                }
              };
              if (seg.own)
                test(std::true_type{});
              else
                test(std::false_type{});
            }
            start[i] = static_cast<std::uint32_t>(used);
            count[i] = n;
            used += n;
          }
        }
        buf.resize(used);
      }
    });
  };
  auto with_skipping = [&](auto periodic_axes) {
    if (skipping)
      gather(periodic_axes, std::true_type{});
    else
      gather(periodic_axes, std::false_type{});
  };
  if (periodic)
    with_skipping(std::true_type{});
  else
    with_skipping(std::false_type{});

  // Ascending order within a list: deterministic, and gathers walk memory forwards. With the
  // particles in cell order the candidates come out ascending already (stencil cells are
  // visited in increasing cell index); only lists that are not need the sort.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      rows.chunk_of[i] = static_cast<std::uint32_t>(grid.cell_of(i) / kCellsPerChunk);
      auto row = rows.row(i);
      if (!std::is_sorted(row.begin(), row.end())) std::sort(row.begin(), row.end());
    }
  });
}

}  // namespace

template <int D>
void build_neighbour_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                          CellGrid<D>& grid, NeighbourList& out, std::span<const std::int32_t> kind,
                          std::int32_t skip_kind) {
  GatheredRows rows;
  gather_neighbour_rows<D>(domain, radius, x, grid, kind, skip_kind, rows);
  const std::size_t N = x.size();
  out.offsets.assign(N + 1, 0);
  out.ends.clear();  // packed
  for (std::size_t i = 0; i < N; ++i) out.offsets[i + 1] = out.offsets[i] + rows.count[i];
  out.indices.resize(out.offsets[N]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      auto row = rows.row(i);
      std::copy(row.begin(), row.end(), out.indices.begin() + out.offsets[i]);
    }
  });
  out.radius = radius;
  ++out.builds;
}

template <int D>
void build_candidate_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                          CellGrid<D>& grid, CandidateList& out, std::span<const std::int32_t> kind,
                          std::int32_t skip_kind) {
  GatheredRows rows;
  gather_neighbour_rows<D>(domain, radius, x, grid, kind, skip_kind, rows);
  out.assign(x.size(), [&](std::size_t i) { return std::span<const std::uint32_t>(rows.row(i)); });
  out.radius = radius;
}

template <int D>
void filter_neighbour_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                           const NeighbourList& candidates, NeighbourList& out) {
  filter_rows<D, false>(domain, radius, x, candidates, out, [](std::size_t, const double*) {});
}

template <int D>
void filter_candidates(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                       const CandidateList& candidates, NeighbourList& out, double& kept_fraction) {
  const std::size_t N = candidates.size();
  const std::size_t total = candidates.count;
  const double radius2 = radius * radius;
  out.offsets.resize(N + 1);
  out.ends.resize(N);
  // Storage for the kept fraction of the last call and 10% more (a first call guesses 3/4: in
  // 3D a sphere of the support holds 58% of one of support + the default skin, in 2D 69%).
  auto capacity_for = [&](double fraction) {
    return std::min(
        total, static_cast<std::size_t>(static_cast<double>(total) * std::min(1.0, 1.1 * fraction)) + 4096);
  };
  std::size_t capacity = capacity_for(kept_fraction > 0 ? kept_fraction : 0.75);
  for (;;) {
    if (out.indices.size() < capacity || out.indices.size() > capacity + capacity / 4)
      std::vector<std::uint32_t>(capacity).swap(out.indices);  // fresh: nothing in it is kept
    std::atomic<std::size_t> placed{0};
    const std::size_t room = out.indices.size();
    auto pass = [&](auto periodic_axes) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 2048), [&](auto r) {
        // Rows are filtered 256 at a time into this task's scratch (in L2) and then copied to
        // the place they reserve in the list, one after the other. Blocks land in the order
        // they finish, so the list has gaps nowhere but its rows are not in index order between
        // blocks (NeighbourList::ends); every row is what it would be anywhere else.
        thread_local std::vector<std::uint32_t> scratch;
        const double reach2 = radius2;
        const Vec<D>* const pos = x.data();
        std::uint32_t* const offsets = out.offsets.data();
        std::uint32_t* const ends = out.ends.data();
        std::uint32_t* const indices = out.indices.data();
        for (std::size_t lo = r.begin(); lo < r.end(); lo += 256) {
          const std::size_t hi = std::min(r.end(), lo + 256);
          const std::size_t bound = candidates.offsets[hi] - candidates.offsets[lo];
          if (scratch.size() < bound) scratch.resize(bound);
          std::uint32_t* const dst = scratch.data();
          std::uint32_t used = 0;
          for (std::size_t i = lo; i != hi; ++i) {
            offsets[i] = used;
            used += filter_row<D, false, decltype(periodic_axes)::value>(
                domain, pos, pos[i], reach2, [&](auto&& f) { candidates.for_each(i, f); }, dst + used,
                nullptr);
            ends[i] = used;
          }
          const std::size_t base = placed.fetch_add(used, std::memory_order_relaxed);
          if (base + used > room) continue;  // out of room: the call goes again with more
          std::copy_n(dst, used, indices + base);
          for (std::size_t i = lo; i != hi; ++i) {
            offsets[i] += static_cast<std::uint32_t>(base);
            ends[i] += static_cast<std::uint32_t>(base);
          }
        }
      });
    };
    if (domain.any_periodic())
      pass(std::true_type{});
    else
      pass(std::false_type{});
    const std::size_t kept = placed.load();
    kept_fraction = total > 0 ? static_cast<double>(kept) / static_cast<double>(total) : 0.0;
    if (kept <= room) {
      out.offsets[N] = static_cast<std::uint32_t>(kept);
      break;
    }
    capacity = capacity_for(kept_fraction);
  }
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
                                       const NeighbourList&, NeighbourList&);
template void filter_neighbour_list<3>(const Domain<3>&, double, std::span<const Vec<3>>,
                                       const NeighbourList&, NeighbourList&);
template void filter_candidates<2>(const Domain<2>&, double, std::span<const Vec<2>>, const CandidateList&,
                                   NeighbourList&, double&);
template void filter_candidates<3>(const Domain<3>&, double, std::span<const Vec<3>>, const CandidateList&,
                                   NeighbourList&, double&);
template void build_candidate_list<2>(const Domain<2>&, double, std::span<const Vec<2>>, CellGrid<2>&,
                                      CandidateList&, std::span<const std::int32_t>, std::int32_t);
template void build_candidate_list<3>(const Domain<3>&, double, std::span<const Vec<3>>, CellGrid<3>&,
                                      CandidateList&, std::span<const std::int32_t>, std::int32_t);
template void build_neighbour_list<2>(const Domain<2>&, double, std::span<const Vec<2>>, CellGrid<2>&,
                                      NeighbourList&, std::span<const std::int32_t>, std::int32_t);
template void build_neighbour_list<3>(const Domain<3>&, double, std::span<const Vec<3>>, CellGrid<3>&,
                                      NeighbourList&, std::span<const std::int32_t>, std::int32_t);

}  // namespace ryushi
