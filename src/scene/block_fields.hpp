#pragma once
// The initial fields of one [[fluid]] block, evaluated at a particle: its numbers and its
// compiled formulas (functions/expression.hpp). A formula that gives a value that is not finite
// is bad input: SceneError naming the key's place, the block and the particle's position.
#include <optional>
#include <string>
#include <vector>

#include "functions/expression.hpp"
#include "scene/scene.hpp"

namespace ryushi {

class BlockFields {
 public:
  // label: how errors name the block ("[[fluid]] #index" when empty; [[elastic]] bodies reuse it).
  BlockFields(const FluidBlock& block, std::size_t index, std::string label = "");
  // Component `axis` of the initial velocity at x[0..dimension) (no rotation: callers add it).
  double velocity(int axis, const double* x, int dimension) const;
  bool has_pressure() const { return pressure_.has_value(); }
  double pressure(const double* x, int dimension) const;

 private:
  double evaluate(const Expression& e, const std::string& where, const std::string& what, const double* x,
                  int dimension) const;
  const FluidBlock& block_;
  std::size_t index_;
  std::string label_;
  std::vector<std::optional<Expression>> velocity_;
  std::optional<Expression> pressure_;
};

}  // namespace ryushi
