#pragma once
// A triangle surface read from an STL file (ASCII or binary) by CGAL, placed in the scene by a
// transform, with the queries the particle generator needs: is a point inside (closed meshes:
// CGAL's Side_of_triangle_mesh), the nearest point on the surface (CGAL's AABB tree). CGAL stays
// inside triangle_mesh.cpp.
#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#include "ecs/math.hpp"

namespace ryushi {

class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Applied to every vertex in this order: scale, rotations about x, then y, then z (degrees,
// right-handed), translation.
struct MeshTransform {
  double scale = 1;
  std::array<double, 3> rotate_degrees{0, 0, 0}, translate{0, 0, 0};
};

class TriangleMesh {
 public:
  // Throws MeshError("cannot open ...", "... is not a triangle mesh ...").
  static std::shared_ptr<const TriangleMesh> read(const std::string& path, const MeshTransform& transform);
  ~TriangleMesh();

  std::size_t faces() const;
  // Closed (every edge shared by two faces): it bounds a volume, faces turned outward on reading.
  bool closed() const;
  double volume() const;  // closed meshes
  double area() const;    // of the surface
  Vec<3> lower() const;
  Vec<3> upper() const;
  // Closed: strictly inside the volume. Open: behind the nearest face (against its normal).
  bool inside(const Vec<3>& x) const;
  // The nearest point of the surface.
  Vec<3> closest(const Vec<3>& x) const;
  // False when no face comes within `distance` of x (true may still be farther: the test is the
  // cube around that ball). The tree prunes far points without the nearest-point search, which
  // made a 1M-particle vessel's layers take 45 s: most lattice points are far.
  bool near(const Vec<3>& x, double distance) const;

 private:
  struct Impl;
  explicit TriangleMesh(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace ryushi
