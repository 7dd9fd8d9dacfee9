#pragma once
// The geometry of a body, as SolidShape needs it: a [[solid]]'s shape (scene.hpp's SolidSpec
// extends it with what the scene adds: name, motion, heat) or a round [[fluid]] block's. Plain
// values, so that geometry knows nothing of scenes.
#include <string>
#include <vector>

namespace ryushi {

struct ShapeSpec {
  std::string shape;               // box, cylinder (a disc in 2D), sphere, mesh
  std::vector<double> min, max;    // box; the bounding box of the round shapes (the loader sets it)
  std::vector<double> centre;      // cylinder, sphere
  double radius = 0;
  int axis = 2;                    // 3D cylinder: the axis it runs along (through the whole domain)
  int layers = 3;
  bool container = false;          // walls outside the shape, the fluid inside (min/max: still the shape's)
  // box: per axis, whether it spans a periodic axis of the domain end to end (a plate of a
  // Couette flow): no faces across it, its particles' normals have no part along it.
  std::vector<bool> endless;
};

}  // namespace ryushi
