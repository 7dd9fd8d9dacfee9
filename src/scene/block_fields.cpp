#include "scene/block_fields.hpp"

#include <cmath>
#include <sstream>

namespace ryushi {

BlockFields::BlockFields(const FluidBlock& block, std::size_t index, std::string label)
    : block_(block), index_(index), label_(label.empty() ? "[[fluid]] #" + std::to_string(index) : std::move(label)) {
  // The loader compiled every formula once already, so these cannot fail to compile.
  for (auto& text : block.velocity_expression)
    velocity_.push_back(text.empty() ? std::nullopt : std::optional<Expression>(Expression(text)));
  if (!block.pressure_expression.empty()) pressure_.emplace(block.pressure_expression);
}

double BlockFields::velocity(int axis, const double* x, int dimension) const {
  if (axis < static_cast<int>(velocity_.size()) && velocity_[axis])
    return evaluate(*velocity_[axis], block_.velocity_where, "velocity (axis " + std::to_string(axis) + ")",
                    x, dimension);
  return axis < static_cast<int>(block_.velocity.size()) ? block_.velocity[axis] : 0.0;
}

double BlockFields::pressure(const double* x, int dimension) const {
  return evaluate(*pressure_, block_.pressure_where, "pressure", x, dimension);
}

double BlockFields::evaluate(const Expression& e, const std::string& where, const std::string& what,
                             const double* x, int dimension) const {
  const double value = e(x[0], dimension > 1 ? x[1] : 0.0, dimension > 2 ? x[2] : 0.0);
  if (std::isfinite(value)) return value;
  std::ostringstream m;
  m << where << ": " << label_ << " " << what << " \"" << e.source() << "\" is " << value
    << " at (";
  for (int a = 0; a < dimension; ++a) m << (a ? ", " : "") << x[a];
  m << ")";
  throw SceneError(m.str());
}

}  // namespace ryushi
