#include "geometry/triangle_mesh.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <sstream>
#include <vector>

namespace ryushi {

namespace {
using Kernel3 = CGAL::Simple_cartesian<double>;
using Point = Kernel3::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel3, Primitive>>;
namespace PMP = CGAL::Polygon_mesh_processing;

Point to_point(const Vec<3>& x) {
  return {x[0], x[1], x[2]};
}
Vec<3> to_vec(const Point& p) {
  return {p.x(), p.y(), p.z()};
}
// A surface CGAL read may still be no surface to fill or stand on: a vertex that is not a finite
// number (a binary STL's NaN or infinity, which became particles "outside the domain"), or faces
// that cross each other (random triangles became a solid body without a word). Both name the
// first bad face, counted from 1 as read (the file's order, less any degenerate face the reader
// dropped). Self-intersection is decided with exact predicates (the mesh copied into CGAL's Epick kernel):
// doubles may call faces that only touch crossing.
void check_mesh(const std::string& path, const Mesh& mesh) {
  std::size_t number = 0;
  for (auto f : mesh.faces()) {
    ++number;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const Point& p = mesh.point(v);
      if (std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())) continue;
      std::ostringstream m;
      m << path << ": face " << number << " has a vertex that is not a finite number (" << p.x() << ", "
        << p.y() << ", " << p.z() << ")";
      throw MeshError(m.str());
    }
  }
  using Exact = CGAL::Exact_predicates_inexact_constructions_kernel;
  CGAL::Surface_mesh<Exact::Point_3> exact;
  std::vector<decltype(exact.add_vertex())> vertex(mesh.number_of_vertices());
  for (auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    vertex[v.idx()] = exact.add_vertex(Exact::Point_3(p.x(), p.y(), p.z()));
  }
  for (auto f : mesh.faces()) {
    std::vector<decltype(exact.add_vertex())> corners;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) corners.push_back(vertex[v.idx()]);
    exact.add_face(corners);
  }
  using ExactFace = CGAL::Surface_mesh<Exact::Point_3>::Face_index;
  std::vector<std::pair<ExactFace, ExactFace>> crossing;
  PMP::self_intersections(exact, std::back_inserter(crossing));
  if (crossing.empty()) return;
  auto [a, b] = *std::min_element(crossing.begin(), crossing.end(), [](auto& x, auto& y) {
    return std::min(x.first.idx(), x.second.idx()) < std::min(y.first.idx(), y.second.idx());
  });
  std::ostringstream m;
  m << path << ": face " << std::min(a.idx(), b.idx()) + 1 << " crosses face "
    << std::max(a.idx(), b.idx()) + 1 << " (" << crossing.size()
    << " pairs of faces intersect; a surface to fill or stand on may not cross itself)";
  throw MeshError(m.str());
}

}  // namespace

struct TriangleMesh::Impl {
  Mesh mesh;
  bool closed = false;
  Vec<3> lower, upper;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel3>> side;
};

TriangleMesh::TriangleMesh(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TriangleMesh::~TriangleMesh() = default;

std::shared_ptr<const TriangleMesh> TriangleMesh::read(const std::string& path, const MeshTransform& t) {
  if (!std::ifstream(path).good()) throw MeshError("cannot open " + path);
  auto impl = std::make_unique<Impl>();
  Mesh& mesh = impl->mesh;
  // read_polygon_mesh merges the repeated vertices of an STL's separate triangles and refuses
  // what cannot be made a valid surface (CGAL's verbose reasons would go to std::cerr: silence).
  bool ok = false;
  try {
    ok = PMP::IO::read_polygon_mesh(path, mesh, CGAL::parameters::verbose(false));
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok || mesh.number_of_faces() == 0)
    throw MeshError(path +
                    " is not a triangle mesh CGAL can read (STL, ASCII or binary; a surface without "
                    "degenerate or non-manifold faces)");
  check_mesh(path, mesh);
  // Scale, rotate about x, y, z, translate.
  const double deg = std::numbers::pi / 180;
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(t.rotate_degrees[2] * deg, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(t.rotate_degrees[1] * deg, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(t.rotate_degrees[0] * deg, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  const Vec<3> shift(t.translate[0], t.translate[1], t.translate[2]);
  for (auto v : mesh.vertices())
    mesh.point(v) = to_point(rotation * (t.scale * to_vec(mesh.point(v))) + shift);
  impl->closed = CGAL::is_closed(mesh);
  // A closed surface's faces are turned outward, whatever the file's winding.
  if (impl->closed && !PMP::is_outward_oriented(mesh)) PMP::reverse_face_orientations(mesh);
  impl->lower = Vec<3>::Constant(std::numeric_limits<double>::infinity());
  impl->upper = -impl->lower;
  for (auto v : mesh.vertices()) {
    impl->lower = impl->lower.cwiseMin(to_vec(mesh.point(v)));
    impl->upper = impl->upper.cwiseMax(to_vec(mesh.point(v)));
  }
  impl->tree = std::make_unique<Tree>(CGAL::faces(mesh).first, CGAL::faces(mesh).second, mesh);
  impl->tree->accelerate_distance_queries();
  if (impl->closed) impl->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel3>>(*impl->tree);
  return std::shared_ptr<const TriangleMesh>(new TriangleMesh(std::move(impl)));
}

std::size_t TriangleMesh::faces() const {
  return impl_->mesh.number_of_faces();
}
bool TriangleMesh::closed() const {
  return impl_->closed;
}
double TriangleMesh::volume() const {
  return impl_->closed ? PMP::volume(impl_->mesh) : 0.0;
}
double TriangleMesh::area() const {
  return PMP::area(impl_->mesh);
}
Vec<3> TriangleMesh::lower() const {
  return impl_->lower;
}
Vec<3> TriangleMesh::upper() const {
  return impl_->upper;
}

bool TriangleMesh::inside(const Vec<3>& x) const {
  if (impl_->side) return (*impl_->side)(to_point(x)) == CGAL::ON_BOUNDED_SIDE;
  auto [c, face] = impl_->tree->closest_point_and_primitive(to_point(x));
  const auto n = PMP::compute_face_normal(face, impl_->mesh);
  return (to_point(x) - c) * n < 0;
}

Vec<3> TriangleMesh::closest(const Vec<3>& x) const {
  return to_vec(impl_->tree->closest_point(to_point(x)));
}

bool TriangleMesh::near(const Vec<3>& x, double distance) const {
  // The cube around the ball: a solid box test in CGAL (a ball query may read as its surface).
  const Vec<3> lo = x - Vec<3>::Constant(distance), hi = x + Vec<3>::Constant(distance);
  return impl_->tree->do_intersect(Kernel3::Iso_cuboid_3(to_point(lo), to_point(hi)));
}

}  // namespace ryushi
