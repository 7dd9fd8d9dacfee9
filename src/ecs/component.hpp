#pragma once
// Component tokens: a static, typed name for a structure-of-arrays column.
//   inline constexpr Component<Scalar> density{"density"};
// The kind tag decides the element type once the dimension is known.
#include <cstdint>
#include <string_view>

#include "ecs/math.hpp"

namespace ryushi {

struct Scalar {};  // double per particle
struct Vector {};  // Vec<D> per particle
struct Tensor {};  // Mat<D> per particle
struct Flags {};   // int32 per particle (kind, ids, bit flags)

template <class Kind, int D>
struct element_of;
template <int D>
struct element_of<Scalar, D> {
  using type = double;
};
template <int D>
struct element_of<Vector, D> {
  using type = Vec<D>;
};
template <int D>
struct element_of<Tensor, D> {
  using type = Mat<D>;
};
template <int D>
struct element_of<Flags, D> {
  using type = std::int32_t;
};
template <class Kind, int D>
using element_t = typename element_of<Kind, D>::type;

template <class Kind>
struct Component {
  using kind = Kind;
  std::string_view name;
};

// Particle kinds stored in the `kind` column (the output contract: 0 fluid, 1 wall, 2+ other).
// kDummy: outer wall layers of MPS that carry no pressure and only complete the number density
// of the wall particles next to the fluid (Koshizuka's dummy particles).
// kElastic: particles of a linear-elastic solid body (WCSPH, seed 002 section 2.2).
enum ParticleKind : std::int32_t { kFluid = 0, kWall = 1, kDummy = 2, kElastic = 3 };

// Components every method shares. Systems of one family may declare their own next to them.
namespace components {
inline constexpr Component<Flags> id{"id"};
inline constexpr Component<Flags> kind{"kind"};
inline constexpr Component<Vector> position{"position"};
inline constexpr Component<Vector> velocity{"velocity"};
inline constexpr Component<Vector> acceleration{"acceleration"};
inline constexpr Component<Scalar> mass{"mass"};
inline constexpr Component<Scalar> density{"density"};
inline constexpr Component<Scalar> density_rate{"density_rate"};
inline constexpr Component<Scalar> pressure{"pressure"};
inline constexpr Component<Scalar> viscosity{"viscosity"};
inline constexpr Component<Vector> density_gradient{"density_gradient"};
inline constexpr Component<Vector> wall_velocity{"wall_velocity"};
inline constexpr Component<Vector> position_start{"position_start"};
inline constexpr Component<Vector> velocity_start{"velocity_start"};
inline constexpr Component<Scalar> density_start{"density_start"};
// The [[solid]] a wall particle belongs to (-1: a container wall, or fluid); only in scenes with solids.
inline constexpr Component<Flags> body{"body"};
// Where a moving [[solid]]'s particle rests (its displacement is added to it); only in scenes with one.
inline constexpr Component<Vector> body_origin{"body_origin"};
// Unit normal of a wall particle, out of the fluid into the wall (ISPH's single wall layer).
inline constexpr Component<Vector> wall_normal{"wall_normal"};
// A body's first-layer particle's share of its surface times the unit normal into it (m^(D-1));
// zero elsewhere. Only MPS and ISPH scenes with a force probe have it.
inline constexpr Component<Vector> surface_element{"surface_element"};
// A moving [[solid]]'s particle's prescribed acceleration (Adami's wall pressure); with body_origin.
inline constexpr Component<Vector> body_acceleration{"body_acceleration"};
}  // namespace components

}  // namespace ryushi
