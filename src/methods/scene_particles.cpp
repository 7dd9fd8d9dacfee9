#include "methods/scene_particles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "ecs/lattice.hpp"
#include "geometry/solid_shape.hpp"
#include "scene/block_fields.hpp"

namespace ryushi {

template <int D>
SceneParticles<D> scene_particles(const Scene& s, bool ring_containers) {
  const double d = s.spacing;
  SceneParticles<D> out;
  // [particles] disorder: one generator over the fluid in lattice order, so a seed gives one set.
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> shake(-s.disorder * d, s.disorder * d);
  std::vector<SolidShape<D>> solids;
  for (auto& spec : s.solids) solids.emplace_back(spec, spec.mesh >= 0 ? s.meshes[spec.mesh].mesh : nullptr);
  // A block with an obstacle in it: lattice points within half a spacing of a solid are not fluid
  // (the solid's first layer lies half a spacing inside its surface). A container's wall is the
  // fluid's lattice outside it (solid_shape.cpp): the points outside are not fluid, the rest are.
  // ISPH's one wall layer, whose Neumann rows take the normals, is a ring outside a round
  // container instead (on the lattice it is a zigzag: a round tank at rest blew up at t = 0.6 s);
  // the fluid keeps a quarter spacing from its surface, so that every wall particle has water
  // within ISPH's wetted distance 1.1 sqrt(D) d (the lattice cut by a circle leaves gaps of up to
  // 0.7 d more; cut at half a spacing, as round bodies cut it, some walls saw none, p = 0, and the
  // tank blew up at t = 0.4 s). Only the Eulerian pipe keeps that ring now: with moving particles
  // a round container takes wall_rows = "adami" and the lattice's layers, as the other methods.
  auto margin = [&](std::size_t k) {
    const SolidSpec& b = s.solids[k];
    if (!b.container) return 0.5 * d * (1 - 1e-9);
    return ring_containers && b.shape != "box" && b.mesh < 0 ? 0.25 * d : 0.0;
  };
  auto inside_solid = [&](const Vec<D>& x) {
    for (std::size_t k = 0; k < solids.size(); ++k)
      if (solids[k].within(x, margin(k))) return true;
    for (auto& e : s.elastic) {  // an elastic body's box, and half a spacing around it
      bool inside = true;
      for (int a = 0; a < D; ++a) inside = inside && x[a] > e.min[a] - 0.5 * d * (1 - 1e-9) && x[a] < e.max[a] + 0.5 * d * (1 - 1e-9);
      if (inside) return true;
    }
    return false;
  };
  // The fluid's lattice, which a container's layers continue: the first block's.
  std::optional<Vec<D>> lattice_origin;
  if (!s.fluid.empty() && !ring_containers) lattice_origin = scene_vector<D>(s.fluid.front().min);
  for (std::size_t index = 0; index < s.fluid.size(); ++index) {
    const FluidBlock& b = s.fluid[index];
    const BlockFields fields(b, index);
    Vec<D> lo = scene_vector<D>(b.min);
    std::array<long, D> from{}, to{};
    for (int a = 0; a < D; ++a) to[a] = std::lround((b.max[a] - b.min[a]) / d);
    double top = b.min[D - 1] + to[D - 1] * d;
    Vec<D> centre = 0.5 * (scene_vector<D>(b.min) + scene_vector<D>(b.max));
    std::optional<SolidShape<D>> round;  // a disc, cylinder or ball of fluid: the same shape as a body's
    if (b.shape != "box") {
      ShapeSpec shape;
      shape.shape = b.shape, shape.centre = b.centre, shape.radius = b.radius, shape.axis = b.axis;
      shape.min = b.min, shape.max = b.max;
      round.emplace(shape);
    }
    for_each_lattice_point<D>(lo, d, from, to, [&](const Vec<D>& lattice) {
      if (round && round->signed_distance(lattice) >= 0) return;
      if ((!solids.empty() || !s.elastic.empty()) && inside_solid(lattice)) return;
      if constexpr (D == 3)
        if (b.mesh >= 0 && !s.meshes[b.mesh].mesh->inside(lattice)) return;
      Vec<D> x = lattice;
      if (s.disorder > 0)
        for (int a = 0; a < D; ++a) x[a] += shake(rng);
      out.fluid.push_back(x);
      out.depth.push_back(top - x[D - 1]);
      Vec<D> u;
      for (int a = 0; a < D; ++a) u[a] = fields.velocity(a, x.data(), D);
      out.pressure.push_back(fields.has_pressure() ? fields.pressure(x.data(), D)
                                                   : std::numeric_limits<double>::quiet_NaN());
      if constexpr (D == 2) u += b.angular_velocity * Vec<D>(x[1] - centre[1], -(x[0] - centre[0]));
      out.fluid_velocity.push_back(u);
      out.fluid_temperature.push_back(std::isnan(b.temperature) ? s.temperature : b.temperature);
    });
  }
  // [[import]]: as read; without a pressure the depth below the highest imported particle's top.
  for (auto& import : s.imports) {
    const auto& in = *import.particles;
    double top = -1e300;
    for (auto& x : in.position) top = std::max(top, x[D - 1] + 0.5 * d);
    for (std::size_t k = 0; k < in.position.size(); ++k) {
      Vec<D> x, u = Vec<D>::Zero();
      for (int a = 0; a < D; ++a) x[a] = in.position[k][a];
      if (!in.velocity.empty())
        for (int a = 0; a < D; ++a) u[a] = in.velocity[k][a];
      out.fluid.push_back(x);
      out.depth.push_back(top - x[D - 1]);
      out.fluid_velocity.push_back(u);
      out.pressure.push_back(in.pressure.empty() ? std::numeric_limits<double>::quiet_NaN() : in.pressure[k]);
      out.fluid_temperature.push_back(s.temperature);
    }
  }
  for (std::size_t box = 0; box < s.walls.size(); ++box) {
    const WallBox& w = s.walls[box];
    Vec<D> lo = scene_vector<D>(w.min), hi = scene_vector<D>(w.max);
    std::array<long, D> from{}, to{};
    for (int a = 0; a < D; ++a) {
      const bool open_ends = a < static_cast<int>(w.open_ends.size()) && w.open_ends[a];
      from[a] = open_ends ? 0 : -w.layers;
      to[a] = std::lround((w.max[a] - w.min[a]) / d) + ((open_ends || (a == D - 1 && w.open_top)) ? 0 : w.layers);
    }
    for_each_lattice_point<D>(lo, d, from, to, [&](const Vec<D>& q) {
      double outside = 0;  // how far the point lies outside the box, (layer - 1/2) d
      Vec<D> normal = Vec<D>::Zero();
      for (int a = 0; a < D; ++a) {
        outside = std::max({outside, lo[a] - q[a], q[a] - hi[a]});
        normal[a] = std::max(0.0, q[a] - hi[a]) - std::max(0.0, lo[a] - q[a]);
      }
      if (outside <= 0) return;
      out.wall.push_back(q);
      out.wall_layer.push_back(static_cast<int>(std::lround(outside / d + 0.5)));
      out.wall_normal.push_back(normal.normalized());
      out.wall_velocity.push_back(Vec<D>::Zero());
      out.wall_body.push_back(-1);
      out.wall_box.push_back(static_cast<int>(box));
      out.wall_area.push_back(0.0);
    });
  }
  // A solid's face that lies on a [[wall]] box's surface (a piston standing on the floor) faces
  // the wall, not the fluid: the corner it shares with a wetted face takes that face's normal,
  // not the bisector (which told ISPH's Neumann row there that the piston pushes the water down
  // into the floor: pressures of 10x hydrostatic at the piston's foot every half period, and one
  // particle launched at 8 m/s in the wave flume). A face particle with no wetted side keeps its
  // normal.
  auto beyond_a_wall_surface = [&](const Vec<D>& x, const Vec<D>& step) {
    for (const WallBox& w : s.walls) {
      const Vec<D> lo = scene_vector<D>(w.min), hi = scene_vector<D>(w.max);
      const Vec<D> y = x + step;
      bool x_in = true, y_in = true;
      for (int a = 0; a < D; ++a) {
        x_in = x_in && x[a] >= lo[a] && x[a] <= hi[a];
        y_in = y_in && y[a] >= lo[a] && y[a] <= hi[a];
      }
      if (x_in && !y_in) return true;
    }
    return false;
  };
  for (std::size_t k = 0; k < solids.size(); ++k) {
    const Vec<D> velocity = scene_vector<D>(s.solids[k].velocity);
    for (auto particle : solids[k].shell(d, lattice_origin ? &*lattice_origin : nullptr)) {
      Vec<D> wetted = Vec<D>::Zero();
      int sides = 0;
      for (int a = 0; a < D; ++a) {
        if (std::abs(particle.normal[a]) < 1e-12) continue;
        ++sides;
        Vec<D> step = Vec<D>::Zero();
        step[a] = std::copysign(d, -particle.normal[a]);  // the normal points into the body
        if (!beyond_a_wall_surface(particle.position, step)) wetted[a] = particle.normal[a];
      }
      const double kept = wetted.squaredNorm();
      if (sides > 1 && kept > 0 && kept < particle.normal.squaredNorm() * (1 - 1e-12)) {
        const double scale = particle.area > 0 ? particle.area / particle.normal.template lpNorm<1>() : 0.0;
        particle.normal = wetted.normalized();
        particle.area = scale * particle.normal.template lpNorm<1>();
      }
      out.wall.push_back(particle.position);
      out.wall_layer.push_back(particle.layer);
      out.wall_normal.push_back(particle.normal);
      out.wall_velocity.push_back(velocity);
      out.wall_body.push_back(static_cast<int>(k));
      out.wall_box.push_back(-1);
      out.wall_area.push_back(particle.area);
    }
  }
  return out;
}

template SceneParticles<2> scene_particles<2>(const Scene&, bool);
template SceneParticles<3> scene_particles<3>(const Scene&, bool);

}  // namespace ryushi
