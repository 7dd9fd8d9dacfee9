#pragma once
// Uniform cell grid with a counting sort: cell edge >= search radius, so every neighbour of a
// particle lies in its own or an adjacent cell (3^D cells). Periodic axes wrap cell indices.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "ecs/math.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
class CellGrid {
 public:
  // Throws std::invalid_argument if a periodic axis is shorter than three cells.
  void build(const Domain<D>& domain, double radius, std::span<const Vec<D>> x);

  std::size_t cell_count() const { return cell_start_.size() - 1; }
  // Particles sorted by cell; sorted()[cell_start(c) .. cell_start(c+1)) lie in cell c.
  std::span<const std::uint32_t> sorted() const { return sorted_; }
  std::uint32_t cell_start(std::size_t c) const { return cell_start_[c]; }
  std::uint32_t cell_of(std::size_t i) const { return cell_of_[i]; }
  std::array<std::int64_t, D> coords(std::uint32_t cell) const;
  // Flat index of the cell at integer coordinates, or -1 if outside a non-periodic axis.
  std::int64_t cell_at(std::array<std::int64_t, D> c) const;
  std::array<std::int64_t, D> dims() const { return dims_; }

 private:
  Vec<D> origin_;
  Vec<D> inv_cell_;
  std::array<std::int64_t, D> dims_{};
  std::array<bool, D> periodic_{};
  std::vector<std::uint32_t> cell_of_, sorted_, cell_start_;
};

}  // namespace ryushi
