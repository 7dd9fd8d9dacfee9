#pragma once
// The shapes of [[solid]] bodies (geometry/shape_spec.hpp; scene.hpp SolidSpec): the signed distance that cuts fluid out
// of the blocks, and the wall particles of the body's outer layers with the normal each method
// asks for (from the fluid into the body) and its layer (1 = touching the fluid). A container
// (spec.container) is the same shape turned inside out: its wall is everything outside it.
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "ecs/math.hpp"
#include "geometry/triangle_mesh.hpp"
#include "geometry/shape_spec.hpp"

namespace ryushi {

template <int D>
struct ShellParticle {
  Vec<D> position;
  int layer;
  Vec<D> normal;  // unit, from the fluid into the body
  // Layer 1: the share of the body's surface the particle stands for (m^(D-1); the surface
  // pressure times it is the force there: solid_surface_force.hpp); 0 on deeper layers.
  double area = 0;
};

template <int D>
class SolidShape {
 public:
  // spec.min/max bound the shape (the loader sets them for a cylinder and a sphere; a 3D
  // cylinder's run through the domain along its axis).
  // mesh: the [[mesh]] of a shape = "mesh" body (3D), else null.
  explicit SolidShape(const ShapeSpec& spec, std::shared_ptr<const TriangleMesh> mesh = nullptr);
  // Negative inside the body, positive outside; exact for the box, disc, cylinder and sphere. For
  // a container, negative in its walls (outside the shape), positive where the fluid is.
  double signed_distance(const Vec<D>& x) const;
  // Whether x lies inside the shape or within `margin` of it (fluid there is cut). Cheaper than
  // the signed distance for a mesh: the bounding box first, the inside test, then the distance.
  bool within(const Vec<D>& x, double margin) const;
  // The particles of the outer `layers` at spacing d; a container's lie outside it, on the lattice
  // lattice_origin + (k + 1/2) d (the fluid's), or without one, a round container's on rings
  // (shells) at (k - 1/2) d outside it (a box's and a mesh's on the lattice from its corner).
  std::vector<ShellParticle<D>> shell(double d, const Vec<D>* lattice_origin = nullptr) const;
  // The box the particles of `layers` at spacing d occupy (a container's reaches beyond the shape;
  // a 3D cylinder's runs along its axis as the shape's does).
  std::pair<Vec<D>, Vec<D>> extent(double d) const;

 private:
  std::vector<ShellParticle<D>> box_shell(double d) const;
  std::vector<ShellParticle<D>> round_shell(double d) const;
  std::vector<ShellParticle<D>> mesh_shell(double d) const;
  std::vector<ShellParticle<D>> container_shell(double d, const Vec<D>& origin) const;
  double shape_distance(const Vec<D>& x) const;  // negative inside the shape
  double round_surface() const;
  bool endless(int axis) const { return axis < static_cast<int>(spec_.endless.size()) && spec_.endless[axis]; }
  ShapeSpec spec_;
  std::shared_ptr<const TriangleMesh> mesh_;
  Vec<D> lo_, hi_, centre_;
};

}  // namespace ryushi
