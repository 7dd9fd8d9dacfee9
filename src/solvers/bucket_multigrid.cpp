#include "solvers/bucket_multigrid.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "solvers/jacobi_spectrum.hpp"
#include "solvers/reusable_buffer.hpp"
#include "solvers/vector_ops.hpp"

namespace ryushi::solvers {

namespace {

// A bucket's coordinates and, in [3], the component of a block row's unknown (0 for a scalar
// system): the components of a vector unknown aggregate separately, bucket by bucket.
using Coord = std::array<std::int64_t, 4>;
constexpr int kMaxSlots = 27 * 3;  // 3^D neighbouring buckets times at most 3 components

template <class T>
struct Level {
  CsrMatrix<T> A;     // the coarse levels' own matrices; at level 0 empty (see values0)
  CsrView<T> view;    // what the cycle reads: A, or at level 0 the caller's structure
  ReusableBuffer<T> values0;  // level 0 in float: the caller's values, converted
  std::vector<T> inverse_diagonal;
  T jacobi_weight = 0;  // the options' weight, or its bound (MultigridOptions::bound_jacobi_weight)
  std::vector<std::uint32_t> to_coarse;                  // this level's element -> next level's
  std::vector<std::uint64_t> member_offsets{0};          // next level's element -> members here
  std::vector<std::uint32_t> members;
  // A P (this level's rows, the next level's columns; 3^D slots per row, unused slots point at
  // the row's own aggregate with value 0), kept where it is much narrower than A: after the
  // coarse correction z + P e the first post-smoothing sweep needs A (z + P e) = A z + (A P) e,
  // and A z is the residual's product from before the correction, so the sweep reads A P's
  // 3^D entries instead of A's (2D MPS: 9 instead of about 30 per row).
  std::size_t ap_slots = 0;  // 0: not kept
  ReusableBuffer<std::uint32_t> ap_col;
  ReusableBuffer<T> ap_val;
  mutable std::vector<T> r, z, tmp;
};

// Groups elements by bucket coordinate; returns the coarse coordinates and fills the map and the
// member lists (counting sort over a dense key range, members in ascending order).
// With block rows the unknowns of one particle are consecutive, so the coarse elements come out
// consecutive per bucket too: a coarse element's component is its index modulo the block size.
std::vector<Coord> aggregate(const std::vector<Coord>& q, int D, int block,
                             std::vector<std::uint32_t>& to_coarse, std::vector<std::uint64_t>& offsets,
                             std::vector<std::uint32_t>& members) {
  Coord lo{0, 0, 0, 0}, hi{0, 0, 0, 0};
  for (int a = 0; a < D; ++a) {
    lo[a] = hi[a] = q.empty() ? 0 : q[0][a];
    for (auto& c : q) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
  }
  std::int64_t nx = hi[0] - lo[0] + 1, ny = D > 1 ? hi[1] - lo[1] + 1 : 1, nz = D > 2 ? hi[2] - lo[2] + 1 : 1;
  auto key = [&](const Coord& c) {
    return std::size_t(c[3] + block * ((c[0] - lo[0]) +
                                       nx * ((D > 1 ? c[1] - lo[1] : 0) + ny * (D > 2 ? c[2] - lo[2] : 0))));
  };
  std::vector<std::uint32_t> index(std::size_t(nx * ny * nz * block), UINT32_MAX);
  std::vector<Coord> coarse;
  to_coarse.resize(q.size());
  std::vector<std::uint64_t> count;
  for (std::size_t i = 0; i < q.size(); ++i) {  // coarse numbering in order of first appearance
    auto& slot = index[key(q[i])];
    if (slot == UINT32_MAX) {
      slot = static_cast<std::uint32_t>(coarse.size());
      coarse.push_back(q[i]);
      count.push_back(0);
    }
    to_coarse[i] = slot;
    ++count[slot];
  }
  offsets.assign(coarse.size() + 1, 0);
  for (std::size_t c = 0; c < coarse.size(); ++c) offsets[c + 1] = offsets[c] + count[c];
  members.resize(q.size());
  std::vector<std::uint64_t> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t i = 0; i < q.size(); ++i) members[fill[to_coarse[i]]++] = static_cast<std::uint32_t>(i);
  return coarse;
}

// A_c = scale * P^T A P, row by row: each coarse row gathers its members' rows into the 3^D
// slots given by the bucket offset of the column's coarse element (Algorithm 1, no atomics),
// times the block size: a slot per neighbouring bucket and component.
struct GalerkinScratch {
  ReusableBuffer<double> val;
  ReusableBuffer<std::int64_t> col;
};

// q: the fine elements' bucket coordinates at the coarse level's resolution (the aggregate of j
// has coordinates q[j]), read per entry beside to_coarse instead of through it. inverse_diagonal
// (optional) receives 1 / A_ii of the fine rows from the same pass over A.
template <class T>
void galerkin(const CsrView<T>& A, const std::vector<std::uint32_t>& to_coarse,
              const std::vector<std::uint64_t>& offsets, const std::vector<std::uint32_t>& members,
              const std::vector<Coord>& q, std::size_t nc, int D, int block, double scale,
              std::uint32_t* ap_col, T* ap_val, T* inverse_diagonal, GalerkinScratch& scratch,
              CsrMatrix<T>& Ac) {
  const int slots = (D == 2 ? 9 : 27) * block;
  double* val = scratch.val.ensure(nc * slots);
  std::int64_t* col = scratch.col.ensure(nc * slots);
  // One coarse row: its members' rows gathered into the slots (and A P's rows, the diagonal).
  auto gather = [&](std::size_t I) {
    std::array<double, kMaxSlots> coarse_val;
    std::array<std::int64_t, kMaxSlots> coarse_col;
    std::fill_n(coarse_val.begin(), slots, 0.0);
    std::fill_n(coarse_col.begin(), slots, -1);
    for (auto m = offsets[I]; m < offsets[I + 1]; ++m) {
      std::uint32_t i = members[m];
      const Coord& qi = q[i];
      std::array<double, kMaxSlots> row_val;
      std::array<std::uint32_t, kMaxSlots> row_col;
      std::array<bool, kMaxSlots> used;  // slot s holds an entry (possibly summing to zero)
      std::fill_n(row_val.begin(), slots, 0.0);
      std::fill_n(row_col.begin(), slots, static_cast<std::uint32_t>(I));
      std::fill_n(used.begin(), slots, false);
      T diagonal = 0;
      for (auto k = A.row_ptr[i]; k < A.row_ptr[i + 1]; ++k) {
        const std::uint32_t j = A.col[k];
        const Coord& qj = q[j];
        int slot = 0, stride = 1;
        for (int a = 0; a < D; ++a, stride *= 3) {
          std::int64_t d = qj[a] - qi[a] + 1;
          if (d < 0 || d > 2)
            throw std::invalid_argument(
                "multigrid: a matrix entry spans more than one bucket; the bucket width must be at least the "
                "influence radius");
          slot += int(d) * stride;
        }
        slot = slot * block + int(qj[3]);
        row_val[slot] += A.val[k];
        row_col[slot] = to_coarse[j];
        used[slot] = true;
        if (j == i) diagonal += A.val[k];
      }
      if (inverse_diagonal) inverse_diagonal[i] = T(1) / diagonal;
      for (int s = 0; s < slots; ++s)
        if (used[s]) {
          coarse_val[s] += row_val[s];
          coarse_col[s] = row_col[s];
        }
      if (ap_col)
        for (int s = 0; s < slots; ++s) {
          ap_col[std::size_t(i) * slots + s] = row_col[s];
          ap_val[std::size_t(i) * slots + s] = static_cast<T>(row_val[s]);
        }
    }
    std::copy_n(coarse_val.begin(), slots, val + I * slots);
    std::copy_n(coarse_col.begin(), slots, col + I * slots);
  };
  tbb::parallel_for(std::size_t(0), nc, gather);
  // Compaction in parallel: count the used slots per row, offsets, then each row sorted by column.
  Ac.rows = Ac.cols = nc;
  Ac.row_ptr.assign(nc + 1, 0);
  tbb::parallel_for(std::size_t(0), nc, [&](std::size_t I) {
    std::uint64_t used = 0;
    for (int s = 0; s < slots; ++s) used += col[I * slots + s] >= 0;
    Ac.row_ptr[I + 1] = used;
  });
  for (std::size_t I = 0; I < nc; ++I) Ac.row_ptr[I + 1] += Ac.row_ptr[I];
  Ac.col.resize(Ac.row_ptr[nc]);
  Ac.val.resize(Ac.row_ptr[nc]);
  tbb::parallel_for(std::size_t(0), nc, [&](std::size_t I) {
    std::array<std::pair<std::int64_t, double>, kMaxSlots> row;
    int used = 0;
    for (int s = 0; s < slots; ++s)
      if (col[I * slots + s] >= 0) row[used++] = {col[I * slots + s], val[I * slots + s]};
    std::sort(row.begin(), row.begin() + used);
    for (int e = 0; e < used; ++e) {
      Ac.col[Ac.row_ptr[I] + e] = static_cast<std::uint32_t>(row[e].first);
      Ac.val[Ac.row_ptr[I] + e] = static_cast<T>(scale * row[e].second);
    }
  });
}

template <class T>
void inverse_diagonal(const CsrView<T>& A, std::vector<T>& d) {
  d.resize(A.rows);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, A.rows, 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      T sum = 0;
      for (auto k = A.row_ptr[i]; k < A.row_ptr[i + 1]; ++k)
        if (A.col[k] == i) sum += A.val[k];
      d[i] = T(1) / sum;
    }
  });
}

template <class T>
void check_inverse_diagonal(const std::vector<T>& d) {
  for (std::size_t i = 0; i < d.size(); ++i)  // the first bad row, the same for any thread count
    if (!std::isfinite(double(d[i])))
      throw std::invalid_argument("multigrid: zero diagonal at row " + std::to_string(i));
}

}  // namespace

struct BucketMultigrid::Impl {
  virtual ~Impl() = default;
  virtual void build(const CsrMatrix<double>& A, std::span<const double> x, int D, double width,
                     int block) = 0;
  virtual void apply(std::span<const double> r, std::span<double> z) const = 0;
  virtual std::vector<MultigridLevelInfo> levels() const = 0;
  virtual std::size_t bytes() const = 0;
};

namespace {

template <class T>
struct Hierarchy final : BucketMultigrid::Impl {
  std::vector<Level<T>> L;  // kept with their storage between builds
  MultigridOptions o;
  std::vector<Coord> q;  // bucket coordinates of the current level's elements
  GalerkinScratch scratch;

  explicit Hierarchy(const MultigridOptions& opt) : o(opt) {}

  void build(const CsrMatrix<double>& A, std::span<const double> x, int D, double width, int block) override {
    const std::size_t n = A.rows;
    if (block < 1 || block > 3 || n % std::size_t(block) != 0 ||
        x.size() != n / std::size_t(block) * std::size_t(D))
      throw std::invalid_argument("multigrid: coordinates do not match the matrix");
    // Level 0 is the caller's matrix: its structure is shared (A must outlive the hierarchy and
    // keep its values, as it does in the pressure pipeline: assembled, set up, solved), its values
    // converted when the hierarchy is in float.
    if (L.empty()) L.emplace_back();
    L[0].view = CsrView<T>{n, A.row_ptr.data(), A.col.data(), nullptr};
    if constexpr (std::is_same_v<T, double>) {
      L[0].view.val = A.val.data();
    } else {
      T* v = L[0].values0.ensure(A.nonzeros());
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, A.nonzeros(), 1 << 16), [&](auto r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) v[k] = static_cast<T>(A.val[k]);
      });
      L[0].view.val = v;
    }
    q.resize(n);
    std::vector<double> lo(D, INFINITY);
    for (std::size_t i = 0; i < n / block; ++i)
      for (int a = 0; a < D; ++a) lo[a] = std::min(lo[a], x[i * D + a]);
    parallel_indices(n, [&](std::size_t u) {  // unknown u: particle u / block, component u % block
      const std::size_t i = u / block;
      q[u] = Coord{0, 0, 0, std::int64_t(u % block)};
      for (int a = 0; a < D; ++a)
        q[u][a] = static_cast<std::int64_t>(std::floor((x[i * D + a] - lo[a]) / width));
    });
    std::size_t count = 1;
    while (L[count - 1].view.rows > o.bottom_size && count < 40) {
      auto& fine = L[count - 1];
      fine.ap_slots = 0;
      auto coarse = aggregate(q, D, block, fine.to_coarse, fine.member_offsets, fine.members);
      if (coarse.size() == fine.view.rows) break;                     // nothing left to merge
      double scale = (o.scale_correction && count >= 2) ? 0.5 : 1.0;  // eq. 18, not between 0 and 1
      // A P is kept where its 3^D slots are well under A's entries per row (module comment).
      const int slots = (D == 2 ? 9 : 27) * block;
      const bool keep_ap =
          o.post_smoothing > 0 && slots < 0.5 * double(fine.view.nonzeros()) / double(fine.view.rows);
      if (keep_ap) fine.ap_slots = slots;
      if (L.size() == count) L.emplace_back();  // after the emplace, fine is L[count - 1] again
      auto& f = L[count - 1];
      auto& next = L[count];
      f.inverse_diagonal.resize(f.view.rows);
      galerkin(f.view, f.to_coarse, f.member_offsets, f.members, q, coarse.size(), D, block, scale,
               keep_ap ? f.ap_col.ensure(f.view.rows * slots) : nullptr,
               keep_ap ? f.ap_val.ensure(f.view.rows * slots) : nullptr, f.inverse_diagonal.data(), scratch,
               next.A);
      next.view = next.A.view();
      ++count;
      q = coarse;
      for (auto& c : q)
        for (int a = 0; a < D; ++a) c[a] = c[a] >= 0 ? c[a] / 2 : -((-c[a] + 1) / 2);  // floor division
    }
    L.resize(count);
    L.back().ap_slots = 0;
    inverse_diagonal(L.back().view, L.back().inverse_diagonal);  // the others came with their Galerkin pass
    for (auto& l : L) {
      check_inverse_diagonal(l.inverse_diagonal);
      l.jacobi_weight = static_cast<T>(o.jacobi_weight);
      if (o.bound_jacobi_weight) {
        const double rho = largest_jacobi_eigenvalue(l.view, l.inverse_diagonal);
        if (rho > 0) l.jacobi_weight = static_cast<T>(std::min(o.jacobi_weight, 4.0 / (3.0 * rho)));
      }
      l.r.assign(l.view.rows, T(0));
      l.z.assign(l.view.rows, T(0));
      l.tmp.assign(l.view.rows, T(0));
    }
  }

  // z += w D^-1 (r - A z), or z = w D^-1 r from a zero guess.
  void jacobi(const Level<T>& l, bool zero) const {
    const T w = l.jacobi_weight;
    if (zero) {
      parallel_indices(l.r.size(), [&](std::size_t i) { l.z[i] = w * l.inverse_diagonal[i] * l.r[i]; });
      return;
    }
    spmv<T, T, T>(l.view, std::span<const T>(l.z), std::span<T>(l.tmp));
    parallel_indices(l.r.size(), [&](std::size_t i) { l.z[i] += w * l.inverse_diagonal[i] * (l.r[i] - l.tmp[i]); });
  }

  void cycle(std::size_t k, bool zero) const {
    const auto& l = L[k];
    if (k + 1 == L.size()) {
      for (int s = 0; s < o.bottom_smoothing; ++s) jacobi(l, zero && s == 0);
      if (o.bottom_smoothing == 0 && zero) std::fill(l.z.begin(), l.z.end(), T(0));
      return;
    }
    for (int s = 0; s < o.pre_smoothing; ++s) jacobi(l, zero && s == 0);
    if (o.pre_smoothing == 0 && zero) std::fill(l.z.begin(), l.z.end(), T(0));
    spmv<T, T, T>(l.view, std::span<const T>(l.z), std::span<T>(l.tmp));
    const auto& c = L[k + 1];
    parallel_indices(c.r.size(), [&](std::size_t I) {  // restriction P^T (r - A z)
      T s = 0;
      for (auto m = l.member_offsets[I]; m < l.member_offsets[I + 1]; ++m) s += l.r[l.members[m]] - l.tmp[l.members[m]];
      c.r[I] = s;
    }, 1024);
    cycle(k + 1, true);
    if (o.cycle == MultigridOptions::Cycle::W) cycle(k + 1, false);
    int post = o.post_smoothing;
    if (l.ap_slots > 0) {  // z += P e_c and the first sweep, with A (z + P e_c) = tmp + (A P) e_c
      const std::size_t slots = l.ap_slots;
      const T w = l.jacobi_weight;
      parallel_indices(l.z.size(), [&](std::size_t i) {
        T az = l.tmp[i];
        const T* val = l.ap_val.data.get() + i * slots;
        const std::uint32_t* col = l.ap_col.data.get() + i * slots;
        for (std::size_t s = 0; s < slots; ++s) az += val[s] * c.z[col[s]];
        l.z[i] += c.z[l.to_coarse[i]] + w * l.inverse_diagonal[i] * (l.r[i] - az);
      });
      --post;
    } else {
      parallel_indices(l.z.size(), [&](std::size_t i) { l.z[i] += c.z[l.to_coarse[i]]; });  // P e_c
    }
    for (int s = 0; s < post; ++s) jacobi(l, false);
  }

  void apply(std::span<const double> r, std::span<double> z) const override {
    auto& l = L[0];
    parallel_indices(r.size(), [&](std::size_t i) { l.r[i] = static_cast<T>(r[i]); });
    cycle(0, true);
    parallel_indices(z.size(), [&](std::size_t i) { z[i] = static_cast<double>(l.z[i]); });
  }
  std::vector<MultigridLevelInfo> levels() const override {
    std::vector<MultigridLevelInfo> v;
    for (auto& l : L) v.push_back({l.view.rows, l.view.nonzeros()});
    return v;
  }
  std::size_t bytes() const override {
    std::size_t b = 0;
    for (auto& l : L)
      b += l.A.bytes() + l.values0.bytes() +  // level 0's structure is the caller's
           (l.inverse_diagonal.size() + 3 * l.r.size()) * sizeof(T) +
           (l.to_coarse.size() + l.members.size()) * 4 + l.member_offsets.size() * 8 + l.ap_col.bytes() +
           l.ap_val.bytes();
    return b;
  }
};

}  // namespace

BucketMultigrid::BucketMultigrid(const CsrMatrix<double>& A, std::span<const double> coordinates,
                                 int dimension, double bucket_width, const MultigridOptions& options,
                                 int block_size) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("multigrid: dimension must be 2 or 3");
  if (options.single_precision)
    impl_ = std::make_unique<Hierarchy<float>>(options);
  else
    impl_ = std::make_unique<Hierarchy<double>>(options);
  impl_->build(A, coordinates, dimension, bucket_width, block_size);
}
BucketMultigrid::~BucketMultigrid() = default;
void BucketMultigrid::rebuild(const CsrMatrix<double>& A, std::span<const double> coordinates, int dimension,
                              double bucket_width, int block_size) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("multigrid: dimension must be 2 or 3");
  impl_->build(A, coordinates, dimension, bucket_width, block_size);
}
void BucketMultigrid::apply(std::span<const double> r, std::span<double> z) const { impl_->apply(r, z); }
std::string BucketMultigrid::name() const { return "multigrid"; }
std::vector<MultigridLevelInfo> BucketMultigrid::levels() const { return impl_->levels(); }
std::size_t BucketMultigrid::bytes() const { return impl_->bytes(); }

}  // namespace ryushi::solvers
