#pragma once
// World: N particles as structure-of-arrays columns addressed by component tokens.
// A column exists only once something asks for it (a system's declared access or the scene),
// so a scene pays only for what it models. Structural changes (append, erase, permute) are
// recorded in a CommandBuffer and applied between steps, never while systems run.
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ecs/column.hpp"
#include "ecs/component.hpp"

namespace ryushi {

template <int D>
class World {
 public:
  World() {
    ensure(components::id);
    ensure(components::kind);
  }

  std::size_t size() const { return size_; }
  // Counts structural changes (append, erase, permute): whoever keeps particle indices between
  // steps (a Verlet neighbour list) knows they are stale when it moved.
  std::uint64_t structure_version() const { return structure_version_; }
  bool has(std::string_view name) const { return columns_.count(std::string(name)) != 0; }
  std::vector<std::string> column_names() const {
    std::vector<std::string> names;
    for (auto& [name, _] : columns_) names.push_back(name);
    return names;
  }
  ColumnType column_type(const std::string& name) const { return columns_.at(name)->type(); }

  // Allocates the column (zero-filled) if it does not exist yet.
  template <class Kind>
  std::vector<element_t<Kind, D>>& ensure(Component<Kind> c) {
    auto it = columns_.find(std::string(c.name));
    if (it == columns_.end()) {
      auto col = std::make_unique<Column<element_t<Kind, D>>>(column_type_of<Kind>(), size_);
      it = columns_.emplace(std::string(c.name), std::move(col)).first;
    }
    return typed<Kind>(*it->second, c.name);
  }

  // The column, which must exist.
  template <class Kind>
  std::vector<element_t<Kind, D>>& column(Component<Kind> c) {
    auto it = columns_.find(std::string(c.name));
    if (it == columns_.end())
      throw std::logic_error("component column '" + std::string(c.name) + "' was never allocated");
    return typed<Kind>(*it->second, c.name);
  }
  template <class Kind>
  const std::vector<element_t<Kind, D>>& column(Component<Kind> c) const {
    return const_cast<World*>(this)->column(c);
  }

  // Appends n particles of the given kind with fresh stable ids; other columns zero-filled.
  // Returns the index of the first new particle.
  std::size_t append(std::size_t n, std::int32_t kind) {
    std::size_t first = size_;
    size_ += n;
    ++structure_version_;
    for (auto& [_, col] : columns_) col->resize(size_);
    auto& ids = column(components::id);
    auto& kinds = column(components::kind);
    for (std::size_t i = first; i < size_; ++i) {
      ids[i] = next_id_++;
      kinds[i] = kind;
    }
    return first;
  }

  // Particle `to` takes every column of particle `from` but its id (a split child inherits its
  // parent's state, including columns its method does not know).
  void copy_particle(std::size_t from, std::size_t to) {
    for (auto& [name, col] : columns_)
      if (name != components::id.name) col->copy(from, to);
  }

  // Reorders every column: new_to_old[k] is the old index of the particle that moves to k.
  // Ids travel with their particles, so they stay stable.
  void permute(std::span<const std::uint32_t> new_to_old) {
    if (new_to_old.size() != size_) throw std::logic_error("permute: wrong length");
    ++structure_version_;
    for (auto& [_, col] : columns_) col->gather(new_to_old);
  }

  // Removes the particles whose indices are listed (any order); survivors keep their order.
  void erase(std::span<const std::uint32_t> indices) {
    std::vector<char> dead(size_, 0);
    for (auto i : indices) dead.at(i) = 1;
    std::vector<std::uint32_t> keep;
    keep.reserve(size_);
    for (std::uint32_t i = 0; i < size_; ++i)
      if (!dead[i]) keep.push_back(i);
    for (auto& [_, col] : columns_) col->gather(keep);
    size_ = keep.size();
    ++structure_version_;
  }

  // Checkpoint restore: n particles, every column resized (contents to be overwritten), and the
  // id counter as it was, so that later appends give the same ids as the uninterrupted run.
  void restore_size(std::size_t n, std::int32_t next_id) {
    size_ = n;
    next_id_ = next_id;
    ++structure_version_;
    for (auto& [_, col] : columns_) col->resize(size_);
  }
  std::int32_t next_id() const { return next_id_; }

  std::size_t bytes_per_particle() const {
    std::size_t b = 0;
    for (auto& [_, col] : columns_) b += col->bytes_per_element();
    return b;
  }

 private:
  template <class Kind>
  static std::vector<element_t<Kind, D>>& typed(ColumnBase& base, std::string_view name) {
    if (base.type() != column_type_of<Kind>())
      throw std::logic_error("component '" + std::string(name) + "' used with the wrong type");
    return static_cast<Column<element_t<Kind, D>>&>(base).data();
  }

  std::size_t size_ = 0;
  std::uint64_t structure_version_ = 0;
  std::int32_t next_id_ = 0;
  std::map<std::string, std::unique_ptr<ColumnBase>> columns_;
};

// Structural changes recorded while systems run and applied by the driver between steps, in
// the order they were recorded (each refers to the particle order left by the one before).
// An append adds n particles of one kind (fresh ids, other columns zero) and then calls its
// fill(world, first) to set their columns: particle splitting records its children so.
template <int D>
class CommandBuffer {
 public:
  using Fill = std::function<void(World<D>&, std::size_t first)>;
  void erase(std::vector<std::uint32_t> indices) { ops_.push_back({Op::Erase, std::move(indices), 0, 0, {}}); }
  void permute(std::vector<std::uint32_t> new_to_old) {
    ops_.push_back({Op::Permute, std::move(new_to_old), 0, 0, {}});
  }
  void append(std::size_t n, std::int32_t kind, Fill fill) { ops_.push_back({Op::Append, {}, n, kind, std::move(fill)}); }
  bool empty() const { return ops_.empty(); }
  void apply(World<D>& world) {
    for (auto& op : ops_) {
      switch (op.type) {
        case Op::Permute: world.permute(op.indices); break;
        case Op::Erase: world.erase(op.indices); break;
        case Op::Append: {
          std::size_t first = world.append(op.count, op.kind);
          if (op.fill) op.fill(world, first);
          break;
        }
      }
    }
    ops_.clear();
  }

 private:
  struct Op {
    enum Type { Erase, Permute, Append } type;
    std::vector<std::uint32_t> indices;
    std::size_t count;
    std::int32_t kind;
    Fill fill;
  };
  std::vector<Op> ops_;
};

}  // namespace ryushi
