#pragma once
// The pair loop: for each pair of neighbours it computes the pair's geometry once (x_ij, r,
// grad_i W_ij, v_ij) and hands it to every term of a stage. A term holds one formula of the
// method and is written once, for both sides of the pair; how the pairs are visited is the
// loop's strategy:
//   gather      every written row visits all its neighbours and keeps only its own side;
//   pairs once  each pair is visited from its lower row and both sides are kept (pairs_once.hpp:
//               half the distance and kernel work, a scatter made safe by two phases of blocks).
//
// A term is a class with
//   using Sum = ...;                       // what a row accumulates (double, Vec<D>, a struct with +=)
//   Sum zero() const;
//   void operator()(const PairGeometry<D>& g, PairSides s, Sum& to_i, Sum& to_j) const;
//   void store(std::size_t i, const Sum& sum) const;   // the row's result from its sum
// where operator() adds the pair's share to to_i when s.i and to to_j when s.j (never reading
// them). The loop calls store once per written row, terms in the order given. A term that reads
// values of row i in every pair may take them once per row: it defines `Row row(std::size_t i)
// const` and its operator() takes them, operator()(g, s, row_i, to_i, to_j) (a row's sums are
// written between its pairs, so the compiler could not keep i's values from one pair to the next).
//
// Which rows are written. A row is written when it is one of the loop's kind (the fluid, for a
// fluid stage) and this process owns it. Rows [0, owned) are owned; rows from `owned` on are
// ghosts, copies of particles another process owns (the MPI issue appends them after the owned
// rows). The rule: a strategy never writes to a row it does not own. Gather visits owned rows
// only and reads ghosts as neighbours; pairs once visits pairs from their owned lower row, keeps
// the ghost's side out, and never visits a pair of two ghosts. Both therefore give an owned row
// the same sum whether its neighbours are owned or ghosts, and leave a ghost's outputs untouched.
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/math.hpp"
#include "kernels/kernel.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/loops/pairs_once.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
struct PairGeometry {
  std::uint32_t i, j;
  Vec<D> xij;    // x_i - x_j (the nearest periodic image)
  Vec<D> vij;    // v_i - v_j (zero when the loop has no velocities)
  double r2, r;  // |x_ij|^2, |x_ij|
  double F;      // grad_i W_ij = F x_ij, so that x_ij . grad_i W_ij = r2 F
  Vec<D> gradW;  // grad_i W_ij = -grad_j W_ji
};

// Which rows of the pair this visit writes (gather: i only; pairs once: both, less walls and ghosts).
struct PairSides {
  bool i, j;
};

// A term that takes its row's values once per row (see above), and how the loop calls either kind.
template <class T>
concept CachesRow = requires(const T& t, std::size_t i) {
  t.row(i);
};
struct NoRowValues {};
template <class T>
auto row_values(const T& term, std::size_t i) {
  if constexpr (CachesRow<T>)
    return term.row(i);
  else
    return NoRowValues{};
}
template <int D, class T, class Row, class Sum>
void add_pair(const T& term, const PairGeometry<D>& g, PairSides s, const Row& row_i, Sum& to_i, Sum& to_j) {
  if constexpr (CachesRow<T>)
    term(g, s, row_i, to_i, to_j);
  else
    term(g, s, to_i, to_j);
}

// f(std::true_type) or f(std::false_type): a flag fixed for a run becomes a template argument,
// out of the pair loop.
template <class F>
void with_flag(bool flag, F&& f) {
  if (flag)
    f(std::true_type{});
  else
    f(std::false_type{});
}

template <int D>
class PairLoop {
 public:
  struct Inputs {
    std::span<const Vec<D>> x;
    std::span<const Vec<D>> v;  // empty: v_ij = 0
    std::span<const std::int32_t> kind;
    std::int32_t written_kind;  // the kind of the rows the stage writes
    std::size_t owned;          // rows [0, owned) are owned; the rest are ghosts
  };

  PairLoop(const Kernel<D>& kernel, const Domain<D>& domain) : kernel_(kernel), domain_(domain) {}

  // Auto: pairs once when the particle order allows blocks (pairs_once.hpp), else gather.
  void set_strategy(PairsOnce mode) { mode_ = mode; }

  template <class... Terms>
  void run(const Inputs& in, const NeighbourList& nl, const Terms&... terms) {
    const std::size_t block = pairs_once_block_size(nl, mode_, in.owned);
    const bool periodic = domain_.any_periodic(), moving = !in.v.empty();
    with_flag(periodic, [&](auto P) {
      with_flag(moving, [&](auto M) {
        if (block > 0)
          pairs_once<P.value, M.value>(in, nl, block, std::index_sequence_for<Terms...>{}, terms...);
        else
          gather<P.value, M.value>(in, nl, std::index_sequence_for<Terms...>{}, terms...);
      });
    });
  }

 private:
  // The pair's geometry, or false beyond the kernel's support (a Verlet list's skin).
  template <bool Periodic, bool Moving>
  bool geometry(const Inputs& in, std::uint32_t i, std::uint32_t j, double support2,
                PairGeometry<D>& g) const {
    if constexpr (Periodic)
      g.xij = domain_.displacement(in.x[i], in.x[j]);
    else
      g.xij = in.x[i] - in.x[j];
    g.r2 = g.xij.squaredNorm();
    if (g.r2 >= support2) return false;
    g.i = i;
    g.j = j;
    g.r = std::sqrt(g.r2);
    g.F = kernel_.grad_factor(g.r);
    g.gradW = g.xij * g.F;
    if constexpr (Moving)
      g.vij = in.v[i] - in.v[j];
    else
      g.vij.setZero();
    return true;
  }

  template <bool Periodic, bool Moving, std::size_t... K, class... Terms>
  void gather(const Inputs& in, const NeighbourList& nl, std::index_sequence<K...>,
              const Terms&... terms) const {
    const double support2 = kernel_.support() * kernel_.support();
    for_each_of_kind(in.kind.first(in.owned), in.written_kind, [&](std::size_t i) {
      std::tuple<typename Terms::Sum...> sums{terms.zero()...};
      std::tuple<typename Terms::Sum...> unused{terms.zero()...};  // the j side, which gather never keeps
      const std::tuple rows{row_values(terms, i)...};
      PairGeometry<D> g;
      for (const std::uint32_t j : nl.of(i)) {
        if (!geometry<Periodic, Moving>(in, static_cast<std::uint32_t>(i), j, support2, g)) continue;
        (add_pair(terms, g, PairSides{true, false}, std::get<K>(rows), std::get<K>(sums),
                  std::get<K>(unused)),
         ...);
      }
      (terms.store(i, std::get<K>(sums)), ...);
    });
  }

  template <bool Periodic, bool Moving, std::size_t... K, class... Terms>
  void pairs_once(const Inputs& in, const NeighbourList& nl, std::size_t block, std::index_sequence<K...>,
                  const Terms&... terms) {
    const std::size_t owned = in.owned;
    const std::tuple<typename Terms::Sum*...> rows_sum{scratch<typename Terms::Sum>(K, owned)...};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, owned, 4096), [&](auto r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) ((std::get<K>(rows_sum)[i] = terms.zero()), ...);
    });
    const double support2 = kernel_.support() * kernel_.support();
    auto visit = [&](std::size_t lo, std::size_t hi) {
      // Local copies of the inputs and terms: a store to a row's sum cannot alias them, so their
      // spans and constants stay in registers across the pair loop.
      const Inputs local = in;
      const std::tuple<Terms...> term{terms...};
      auto written = [&](std::size_t k) { return k < local.owned && local.kind[k] == local.written_kind; };
      PairGeometry<D> g;
      for (std::size_t i = lo; i < hi; ++i) {
        const bool write_i = written(i);
        std::tuple<typename Terms::Sum...> sums{std::get<K>(term).zero()...};
        const std::tuple rows{row_values(std::get<K>(term), i)...};
        for (const std::uint32_t j : neighbours_above(nl, i)) {
          const PairSides sides{write_i, written(j)};
          if (!sides.i && !sides.j) continue;
          if (!geometry<Periodic, Moving>(local, static_cast<std::uint32_t>(i), j, support2, g)) continue;
          // A ghost j is never written: its sums slot is only read through sides.j == false.
          (add_pair(std::get<K>(term), g, sides, std::get<K>(rows), std::get<K>(sums),
                    std::get<K>(rows_sum)[sides.j ? j : i]),
           ...);
        }
        if (write_i) ((std::get<K>(rows_sum)[i] += std::get<K>(sums)), ...);
      }
    };
    for_each_block_in_two_phases(owned, block, visit);
    for_each_of_kind(in.kind.first(owned), in.written_kind,
                     [&](std::size_t i) { (terms.store(i, std::get<K>(rows_sum)[i]), ...); });
  }

  // Per-row sums of the pairs-once strategy, kept between runs (no allocation per step).
  struct Slot {
    virtual ~Slot() = default;
  };
  template <class T>
  struct TypedSlot final : Slot {
    std::vector<T> values;
  };
  template <class T>
  T* scratch(std::size_t k, std::size_t n) {
    if (slots_.size() <= k) slots_.resize(k + 1);
    auto* slot = dynamic_cast<TypedSlot<T>*>(slots_[k].get());
    if (slot == nullptr) {
      slots_[k] = std::make_unique<TypedSlot<T>>();
      slot = static_cast<TypedSlot<T>*>(slots_[k].get());
    }
    slot->values.resize(n);
    return slot->values.data();
  }

  Kernel<D> kernel_;
  Domain<D> domain_;
  PairsOnce mode_ = PairsOnce::Auto;
  std::vector<std::unique_ptr<Slot>> slots_;
};

}  // namespace ryushi
