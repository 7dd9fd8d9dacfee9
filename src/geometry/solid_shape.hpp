#pragma once
// The shapes of [[solid]] bodies (scene.hpp SolidSpec): the signed distance that cuts fluid out
// of the blocks, and the wall particles of the body's outer layers with the normal each method
// asks for (from the fluid into the body) and its layer (1 = touching the fluid).
#include <cmath>
#include <vector>

#include "ecs/math.hpp"
#include "scene/scene.hpp"

namespace ryushi {

template <int D>
struct ShellParticle {
  Vec<D> position;
  int layer;
  Vec<D> normal;  // unit, from the fluid into the body
};

template <int D>
class SolidShape {
 public:
  // spec.min/max bound the shape (the loader sets them for a cylinder and a sphere; a 3D
  // cylinder's run through the domain along its axis).
  explicit SolidShape(const SolidSpec& spec);
  // Negative inside, positive outside; exact for the box, disc, cylinder and sphere.
  double signed_distance(const Vec<D>& x) const;
  // The particles of the outer `layers` at spacing d.
  std::vector<ShellParticle<D>> shell(double d) const;

 private:
  std::vector<ShellParticle<D>> box_shell(double d) const;
  std::vector<ShellParticle<D>> round_shell(double d) const;
  SolidSpec spec_;
  Vec<D> lo_, hi_, centre_;
};

}  // namespace ryushi
