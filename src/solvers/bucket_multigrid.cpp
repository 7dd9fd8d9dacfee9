#include "solvers/bucket_multigrid.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "solvers/vector_ops.hpp"

namespace ryushi::solvers {

namespace {

using Coord = std::array<std::int64_t, 3>;

template <class T>
struct Level {
  CsrMatrix<T> A;
  std::vector<T> inverse_diagonal;
  std::vector<std::uint32_t> to_coarse;                  // this level's element -> next level's
  std::vector<std::uint64_t> member_offsets{0};          // next level's element -> members here
  std::vector<std::uint32_t> members;
  mutable std::vector<T> r, z, tmp;
};

// Groups elements by bucket coordinate; returns the coarse coordinates and fills the map and the
// member lists (counting sort over a dense key range, members in ascending order).
std::vector<Coord> aggregate(const std::vector<Coord>& q, int D, std::vector<std::uint32_t>& to_coarse,
                             std::vector<std::uint64_t>& offsets, std::vector<std::uint32_t>& members) {
  Coord lo{0, 0, 0}, hi{0, 0, 0};
  for (int a = 0; a < D; ++a) {
    lo[a] = hi[a] = q.empty() ? 0 : q[0][a];
    for (auto& c : q) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
  }
  std::int64_t nx = hi[0] - lo[0] + 1, ny = D > 1 ? hi[1] - lo[1] + 1 : 1, nz = D > 2 ? hi[2] - lo[2] + 1 : 1;
  auto key = [&](const Coord& c) {
    return std::size_t((c[0] - lo[0]) + nx * ((D > 1 ? c[1] - lo[1] : 0) + ny * (D > 2 ? c[2] - lo[2] : 0)));
  };
  std::vector<std::uint32_t> index(std::size_t(nx * ny * nz), UINT32_MAX);
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
// slots given by the bucket offset of the column's coarse element (Algorithm 1, no atomics).
template <class T>
CsrMatrix<T> galerkin(const CsrMatrix<T>& A, const std::vector<std::uint32_t>& to_coarse,
                      const std::vector<std::uint64_t>& offsets, const std::vector<std::uint32_t>& members,
                      const std::vector<Coord>& coarse, int D, double scale) {
  const std::size_t nc = coarse.size();
  const int slots = D == 2 ? 9 : 27;
  std::vector<double> val(nc * slots, 0.0);
  std::vector<std::int64_t> col(nc * slots, -1);
  tbb::parallel_for(std::size_t(0), nc, [&](std::size_t I) {
    for (auto m = offsets[I]; m < offsets[I + 1]; ++m) {
      std::uint32_t i = members[m];
      for (auto k = A.row_ptr[i]; k < A.row_ptr[i + 1]; ++k) {
        std::uint32_t J = to_coarse[A.col[k]];
        int slot = 0, stride = 1;
        for (int a = 0; a < D; ++a, stride *= 3) {
          std::int64_t d = coarse[J][a] - coarse[I][a] + 1;
          if (d < 0 || d > 2) throw std::invalid_argument("multigrid: a matrix entry spans more than one bucket; the bucket width must be at least the influence radius");
          slot += int(d) * stride;
        }
        val[I * slots + slot] += A.val[k];
        col[I * slots + slot] = J;
      }
    }
  });
  CsrMatrix<T> Ac;
  Ac.rows = Ac.cols = nc;
  Ac.row_ptr.assign(nc + 1, 0);
  for (std::size_t I = 0; I < nc; ++I) {
    std::vector<std::pair<std::int64_t, double>> row;
    for (int s = 0; s < slots; ++s)
      if (col[I * slots + s] >= 0) row.emplace_back(col[I * slots + s], val[I * slots + s]);
    std::sort(row.begin(), row.end());
    for (auto& [c, v] : row) {
      Ac.col.push_back(static_cast<std::uint32_t>(c));
      Ac.val.push_back(static_cast<T>(scale * v));
    }
    Ac.row_ptr[I + 1] = Ac.val.size();
  }
  return Ac;
}

template <class T>
std::vector<T> inverse_diagonal(const CsrMatrix<T>& A) {
  auto d = A.diagonal();
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (d[i] == T(0) || !std::isfinite(double(d[i])))
      throw std::invalid_argument("multigrid: zero diagonal at row " + std::to_string(i));
    d[i] = T(1) / d[i];
  }
  return d;
}

}  // namespace

struct BucketMultigrid::Impl {
  virtual ~Impl() = default;
  virtual void apply(std::span<const double> r, std::span<double> z) const = 0;
  virtual std::vector<MultigridLevelInfo> levels() const = 0;
  virtual std::size_t bytes() const = 0;
};

namespace {

template <class T>
struct Hierarchy final : BucketMultigrid::Impl {
  std::vector<Level<T>> L;
  MultigridOptions o;

  Hierarchy(const CsrMatrix<double>& A, std::span<const double> x, int D, double width, const MultigridOptions& opt)
      : o(opt) {
    const std::size_t n = A.rows;
    if (x.size() != n * std::size_t(D)) throw std::invalid_argument("multigrid: coordinates do not match the matrix");
    L.emplace_back();
    L[0].A = A.template cast<T>();
    std::vector<Coord> q(n, Coord{0, 0, 0});
    std::vector<double> lo(D, INFINITY);
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < D; ++a) lo[a] = std::min(lo[a], x[i * D + a]);
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < D; ++a) q[i][a] = static_cast<std::int64_t>(std::floor((x[i * D + a] - lo[a]) / width));
    while (L.back().A.rows > o.bottom_size && L.size() < 40) {
      auto& fine = L.back();
      auto coarse = aggregate(q, D, fine.to_coarse, fine.member_offsets, fine.members);
      if (coarse.size() == fine.A.rows) break;  // nothing left to merge
      double scale = (o.scale_correction && L.size() >= 2) ? 0.5 : 1.0;  // eq. 18, not between 0 and 1
      Level<T> next;
      next.A = galerkin(fine.A, fine.to_coarse, fine.member_offsets, fine.members, coarse, D, scale);
      L.push_back(std::move(next));
      q = coarse;
      for (auto& c : q)
        for (int a = 0; a < D; ++a) c[a] = c[a] >= 0 ? c[a] / 2 : -((-c[a] + 1) / 2);  // floor division
    }
    for (auto& l : L) {
      l.inverse_diagonal = inverse_diagonal(l.A);
      l.r.assign(l.A.rows, T(0));
      l.z.assign(l.A.rows, T(0));
      l.tmp.assign(l.A.rows, T(0));
    }
  }

  // z += w D^-1 (r - A z), or z = w D^-1 r from a zero guess.
  void jacobi(const Level<T>& l, bool zero) const {
    const T w = static_cast<T>(o.jacobi_weight);
    if (zero) {
      parallel_indices(l.r.size(), [&](std::size_t i) { l.z[i] = w * l.inverse_diagonal[i] * l.r[i]; });
      return;
    }
    spmv<T, T, T>(l.A, std::span<const T>(l.z), std::span<T>(l.tmp));
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
    spmv<T, T, T>(l.A, std::span<const T>(l.z), std::span<T>(l.tmp));
    const auto& c = L[k + 1];
    parallel_indices(c.r.size(), [&](std::size_t I) {  // restriction P^T (r - A z)
      T s = 0;
      for (auto m = l.member_offsets[I]; m < l.member_offsets[I + 1]; ++m) s += l.r[l.members[m]] - l.tmp[l.members[m]];
      c.r[I] = s;
    }, 1024);
    cycle(k + 1, true);
    if (o.cycle == MultigridOptions::Cycle::W) cycle(k + 1, false);
    parallel_indices(l.z.size(), [&](std::size_t i) { l.z[i] += c.z[l.to_coarse[i]]; });  // P e_c
    for (int s = 0; s < o.post_smoothing; ++s) jacobi(l, false);
  }

  void apply(std::span<const double> r, std::span<double> z) const override {
    auto& l = L[0];
    parallel_indices(r.size(), [&](std::size_t i) { l.r[i] = static_cast<T>(r[i]); });
    cycle(0, true);
    parallel_indices(z.size(), [&](std::size_t i) { z[i] = static_cast<double>(l.z[i]); });
  }
  std::vector<MultigridLevelInfo> levels() const override {
    std::vector<MultigridLevelInfo> v;
    for (auto& l : L) v.push_back({l.A.rows, l.A.nonzeros()});
    return v;
  }
  std::size_t bytes() const override {
    std::size_t b = 0;
    for (auto& l : L)
      b += l.A.bytes() + (l.inverse_diagonal.size() + 3 * l.r.size()) * sizeof(T) +
           (l.to_coarse.size() + l.members.size()) * 4 + l.member_offsets.size() * 8;
    return b;
  }
};

}  // namespace

BucketMultigrid::BucketMultigrid(const CsrMatrix<double>& A, std::span<const double> coordinates, int dimension,
                                 double bucket_width, const MultigridOptions& options) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("multigrid: dimension must be 2 or 3");
  if (options.single_precision)
    impl_ = std::make_unique<Hierarchy<float>>(A, coordinates, dimension, bucket_width, options);
  else
    impl_ = std::make_unique<Hierarchy<double>>(A, coordinates, dimension, bucket_width, options);
}
BucketMultigrid::~BucketMultigrid() = default;
void BucketMultigrid::apply(std::span<const double> r, std::span<double> z) const { impl_->apply(r, z); }
std::string BucketMultigrid::name() const { return "multigrid"; }
std::vector<MultigridLevelInfo> BucketMultigrid::levels() const { return impl_->levels(); }
std::size_t BucketMultigrid::bytes() const { return impl_->bytes(); }

}  // namespace ryushi::solvers
