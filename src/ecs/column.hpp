#pragma once
// Type-erased storage for one component column. The world owns columns by name; systems see
// them as typed spans through SystemContext.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ecs/component.hpp"

namespace ryushi {

enum class ColumnType { Scalar, Vector, Tensor, Flags };

template <class Kind>
constexpr ColumnType column_type_of() {
  if constexpr (std::is_same_v<Kind, Scalar>) return ColumnType::Scalar;
  if constexpr (std::is_same_v<Kind, Vector>) return ColumnType::Vector;
  if constexpr (std::is_same_v<Kind, Tensor>) return ColumnType::Tensor;
  if constexpr (std::is_same_v<Kind, Flags>) return ColumnType::Flags;
}


class ColumnBase {
 public:
  virtual ~ColumnBase() = default;
  virtual ColumnType type() const = 0;
  virtual std::size_t size() const = 0;
  virtual std::size_t bytes_per_element() const = 0;
  virtual void resize(std::size_t n) = 0;
  // new_to_old[k] is the old index of the element that ends at index k.
  virtual void gather(std::span<const std::uint32_t> new_to_old) = 0;
  virtual void copy(std::size_t from, std::size_t to) = 0;
};

template <class T>
class Column final : public ColumnBase {
 public:
  Column(ColumnType type, std::size_t n) : type_(type), data_(n, zero()) {}
  ColumnType type() const override { return type_; }
  std::size_t size() const override { return data_.size(); }
  std::size_t bytes_per_element() const override { return sizeof(T); }
  void resize(std::size_t n) override { data_.resize(n, zero()); }
  void gather(std::span<const std::uint32_t> new_to_old) override {
    std::vector<T> out(new_to_old.size());
    for (std::size_t k = 0; k < new_to_old.size(); ++k) out[k] = data_[new_to_old[k]];
    data_.swap(out);
  }
  void copy(std::size_t from, std::size_t to) override { data_[to] = data_[from]; }
  std::vector<T>& data() { return data_; }

 private:
  static T zero() {
    if constexpr (std::is_arithmetic_v<T>) {
      return T{0};
    } else {
      return T::Zero();
    }
  }
  ColumnType type_;
  std::vector<T> data_;
};

}  // namespace ryushi
