#pragma once
// A soft elasto-hydrodynamic line contact (soft-EHL paper "MPH法を用いたソフトEHLシミュレーション",
// eqs. 1-2): the surface of an elastic cylinder of radius R over a plate, as frozen wall particles
// (`layers` rows along the surface normal) whose face is moved every step to the film-thickness
// equation
//   h(x) = h0 + (x - xc)^2 / (2 R) + v(x) + Delta h,  v(x) = -(2 / (pi E)) int p(s) ln|(x - s) / b| ds
// (eq. 1, b Hertz's half-width; the log's scale only moves v by a constant, which Delta h takes),
// with Delta h set by the load balance int p dx = W (eq. 2). p(x) is the film's pressure, the
// mean of the fluid particles' pressure over each surface column (a column is one spacing wide;
// lubrication theory's pressure is uniform across the film), piecewise constant per column in the
// integral. E is the contact modulus E* of Hertz's line contact, as in tools/ehl_reynolds.py,
// which solves the same equations with Reynolds' equation.
//
// What the paper leaves open, chosen here (docs/mph.md measures it):
//  - the surface particles move with the velocity of their displacement over the step, so the
//    film sees a moving wall (a squeeze film), not a wall that jumps and compresses the fluid;
//  - so the surface's motion of one step is squeeze pressure the next: the surface follows eq. 1
//    through two first-order lags of lag / 2 entrainment times b / U each, on the column pressure
//    and on the deformation (relaxed by a fixed fraction per step, the load flipped sign from step
//    to step and the run blew up within 80 steps; one lag of 0.6 b / U left a swing of +-80%);
//  - the load balance, dDelta h/dt = approach_rate U (int p dx / W - 1), the error clamped to
//    +-1: a correction in time, with the filtered pressure;
//  - the start: Hertz's dry pressure and its deformation (flat over the Hertz zone, the film `gap`
//    there), or the rigid cylinder;
//  - the fluid that leaves the domain along x re-enters at the other end at its height (the
//    domain stays non-periodic, so the bucket multigrid applies); the plate is a [[solid]] with a
//    surface velocity, whose particles stay where they are.
// Each surface particle carries its column's film_position (x), film_pressure (the filtered p)
// and film_thickness (h), for the frames; tools/ehl_compare.py reads them.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "ecs/io.hpp"
#include "systems/mph/mph_number_density.hpp"

namespace ryushi {

namespace components {
// A contact surface particle's column * layers + layer + 1 (0 elsewhere).
inline constexpr Component<Flags> contact_slot{"contact_slot"};
inline constexpr Component<Scalar> film_pressure{"film_pressure"};
inline constexpr Component<Scalar> film_thickness{"film_thickness"};
inline constexpr Component<Scalar> film_position{"film_position"};  // the column's x
}  // namespace components

struct LineContactParameters {
  double radius = 0.1;      // R (m)
  double modulus = 1.95e7;  // E of eq. 1 (Pa), the contact modulus
  double load = 1e3;        // W (N per metre)
  double centre = 0;        // xc, where the undeformed cylinder is lowest (m)
  double gap = 1e-4;        // the film at the centre at the start (m)
  double plate = 0;         // the plate's face (y, m)
  double from = 0, to = 0;  // the surface's extent along x (m)
  int layers = 4;
  double spacing = 1e-5;        // l
  double approach_rate = 0.25;  // dDelta h/dt at a load error of 100%, in plate speeds
  double lag = 0.6;             // the surface's lag behind eq. 1, in entrainment times b / U
  bool recycle = true;
  bool hertz_start = true;  // the surface starts deformed by Hertz's dry pressure
};

template <int D>
class ElasticLineContact : public System<D> {
 public:
  ElasticLineContact(const LineContactParameters& p, double rho0) : p_(p), rho0_(rho0) {
    if constexpr (D != 2) throw std::invalid_argument("elastic_line_contact: a line contact is 2D only");
    const double l = p_.spacing;
    columns_ = static_cast<std::size_t>(std::floor((p_.to - p_.from) / l)) + 1;
    if (columns_ < 8)
      throw std::invalid_argument("elastic_line_contact: fewer than 8 columns between from and to");
    x_.resize(columns_);
    for (std::size_t c = 0; c < columns_; ++c) x_[c] = p_.from + c * l;
    // K p = v: -(2 / (pi E)) times the integral of ln|x_i - s| over column j's cell.
    // ln|(x - s) / b| with b Hertz's half-width sqrt(4 W R / (pi E)), as the paper writes eq. 1:
    // the deformation's additive constant (which Delta h takes) is then small near the contact.
    const double b = hertz_half_width();
    kernel_.resize(columns_ * columns_);
    auto primitive = [b](double t) { return t == 0 ? 0.0 : t * std::log(std::abs(t) / b) - t; };
    const double scale = -2.0 / (std::numbers::pi * p_.modulus);
    for (std::size_t i = 0; i < columns_; ++i)
      for (std::size_t j = 0; j < columns_; ++j)
        kernel_[i * columns_ + j] =
            scale * (primitive(x_[j] + l / 2 - x_[i]) - primitive(x_[j] - l / 2 - x_[i]));
    deformation_.assign(columns_, 0.0);
    pressure_.assign(columns_, 0.0);
    face_.resize(columns_);
  }
  std::string name() const override { return "elastic_line_contact"; }
  static constexpr auto io =
      Io{reads(components::kind, components::pressure, resources::dt, domain_resource<D>),
         writes(components::position, components::velocity, components::wall_normal,
                components::mph_wall_depth, components::contact_slot, components::film_pressure,
                components::film_thickness, components::film_position)};
  Access access() const override { return io.access(); }

  // The surface particles, and no fluid within half a spacing of the face or beyond it.
  void initialise(World<D>& world, Resources&) override {
    const double l = p_.spacing;
    {  // the plate's speed U, the time scale of the lags
      auto& v = world.column(components::velocity);
      auto& kind = world.column(components::kind);
      speed_ = 0;
      for (std::size_t i = 0; i < world.size(); ++i)
        if (kind[i] == kWall) speed_ = std::max(speed_, v[i].norm());
      if (!(speed_ > 0))
        throw std::invalid_argument(
            "elastic_line_contact: no wall slides; the scene's check should have said so");
    }
    if (p_.hertz_start) {
      // Hertz's dry pressure p0 sqrt(1 - s^2 / b^2) and its deformation; the film `gap` at the
      // centre, so the surface starts flat over the Hertz zone (K p_H = const - s^2 / (2 R) there).
      const double b = hertz_half_width(), p0 = 2 * p_.load / (std::numbers::pi * b);
      for (std::size_t c = 0; c < columns_; ++c) {
        const double s = (x_[c] - p_.centre) / b;
        pressure_[c] = std::abs(s) < 1 ? p0 * std::sqrt(1 - s * s) : 0.0;
      }
      for (std::size_t i = 0; i < columns_; ++i) deformation_[i] = deformation_of_pressure(i);
      const std::size_t middle = std::min<std::size_t>(
          columns_ - 1, static_cast<std::size_t>(std::max(0.0, std::round((p_.centre - p_.from) / l))));
      approach_ = -deformation_[middle];
    }
    update_face();
    {
      auto& x = world.column(components::position);
      auto& kind = world.column(components::kind);
      std::vector<std::uint32_t> carved;
      for (std::size_t i = 0; i < world.size(); ++i)
        if (kind[i] == kFluid && x[i][D - 1] > face_at(x[i][0]) - 0.5 * l * (1 - 1e-9))
          carved.push_back(static_cast<std::uint32_t>(i));
      world.erase(carved);
    }
    const std::size_t first = world.append(columns_ * p_.layers, kWall);
    auto& x = world.column(components::position);
    auto& slot = world.ensure(components::contact_slot);
    auto& mass = world.ensure(components::mass);
    auto& density = world.ensure(components::density);
    world.ensure(components::film_pressure);
    world.ensure(components::film_thickness);
    world.ensure(components::film_position);
    world.ensure(components::wall_normal);
    world.ensure(components::mph_wall_depth);
    if (world.has(components::body.name)) {
      auto& body = world.column(components::body);
      for (std::size_t i = first; i < world.size(); ++i) body[i] = -1;  // no [[solid]]
    }
    for (std::size_t k = 0; k < columns_ * p_.layers; ++k) {
      slot[first + k] = static_cast<std::int32_t>(k + 1);
      x[first + k][0] = x_[k / p_.layers];  // placed properly below
      density[first + k] = rho0_;
      mass[first + k] = rho0_ * std::pow(l, D);
    }
    place(world, 0.0);
  }

  void run(SystemContext<D>& ctx) override {
    auto [kind, pressure, dt, domain, x, v, normal, depth, slot, film_p, film_h, film_x] = io.fetch(ctx);
    // The film's pressure per column, and the load it carries.
    sum_.assign(columns_, 0.0), count_.assign(columns_, 0);
    const double l = p_.spacing;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (kind[i] != kFluid) continue;
      const long c = std::lround((x[i][0] - p_.from) / l);
      if (c < 0 || c >= static_cast<long>(columns_)) continue;
      sum_[c] += pressure[i], ++count_[c];
    }
    // Two first-order lags of lag / 2 each, on the pressure and on the deformation: the second
    // takes out the step-to-step (period-2) part of the loop through the squeeze film, which a
    // single lag of 0.6 b / U left at +-80% of the load.
    const double follow = std::min(1.0, 2 * dt * speed_ / (p_.lag * hertz_half_width()));  // lag in b / U
    double carried = 0;
    for (std::size_t c = 0; c < columns_; ++c) {
      const double now = count_[c] ? sum_[c] / count_[c] : 0.0;
      pressure_[c] += follow * (now - pressure_[c]);
      carried += pressure_[c] * l;
    }
    approach_ += p_.approach_rate * speed_ * dt * std::clamp(carried / p_.load - 1, -1.0, 1.0);
    tbb::parallel_for(std::size_t(0), columns_, [&](std::size_t i) {
      deformation_[i] += follow * (deformation_of_pressure(i) - deformation_[i]);
    });
    update_face();
    move(x, v, normal, depth, slot, film_p, film_h, film_x, dt);
    if (p_.recycle && !domain.periodic[0]) {
      const double length = domain.max[0] - domain.min[0];
      for (std::size_t i = 0; i < x.size(); ++i)
        if (kind[i] == kFluid) {
          if (x[i][0] >= domain.max[0])
            x[i][0] -= length;
          else if (x[i][0] < domain.min[0])
            x[i][0] += length;
        }
    }
  }

  std::vector<double> checkpoint_state(const World<D>&, const Resources&) const override {
    std::vector<double> s{approach_, speed_};
    s.insert(s.end(), deformation_.begin(), deformation_.end());
    s.insert(s.end(), pressure_.begin(), pressure_.end());
    return s;
  }
  void restore_state(const World<D>&, Resources&, std::span<const double> s) override {
    if (s.size() != 2 + 2 * columns_)
      throw std::runtime_error("elastic_line_contact: the checkpoint's surface has another size");
    approach_ = s[0], speed_ = s[1];
    std::copy(s.begin() + 2, s.begin() + 2 + columns_, deformation_.begin());
    std::copy(s.begin() + 2 + columns_, s.end(), pressure_.begin());
    update_face();
  }

 private:
  void update_face() {  // eq. 1
    for (std::size_t c = 0; c < columns_; ++c) face_[c] = undeformed(c) + deformation_[c] + approach_;
  }
  // Eq. 1's deformation at column i of the columns' pressure: row i of K times p.
  double deformation_of_pressure(std::size_t i) const {
    const double* row = &kernel_[i * columns_];
    double v = 0;
    for (std::size_t j = 0; j < columns_; ++j) v += row[j] * pressure_[j];
    return v;
  }
  double hertz_half_width() const {
    return std::sqrt(4 * p_.load * p_.radius / (std::numbers::pi * p_.modulus));
  }
  double undeformed(std::size_t c) const {
    const double s = x_[c] - p_.centre;
    return p_.plate + p_.gap + s * s / (2 * p_.radius);
  }
  // The face's height at x, linear between columns (the end columns' beyond).
  double face_at(double x) const {
    const double t = std::clamp((x - p_.from) / p_.spacing, 0.0, double(columns_ - 1));
    const std::size_t c = std::min(static_cast<std::size_t>(t), columns_ - 2);
    return face_[c] + (t - c) * (face_[c + 1] - face_[c]);
  }
  // The face's unit normal into the cylinder at column c (central differences).
  Vec<D> normal_at(std::size_t c) const {
    const std::size_t a = c == 0 ? 0 : c - 1, b = std::min(c + 1, columns_ - 1);
    const double slope = (face_[b] - face_[a]) / (x_[b] - x_[a]);
    Vec<D> n = Vec<D>::Zero();
    n[0] = -slope, n[D - 1] = 1;
    return n / n.norm();
  }
  template <class X, class V, class N, class S, class F>
  void move(X& x, V& v, N& normal, S& depth, const F& slot, S& film_p, S& film_h, S& film_x, double dt) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (slot[i] <= 0) continue;
      const std::size_t c = (slot[i] - 1) / p_.layers;
      const int layer = (slot[i] - 1) % p_.layers + 1;
      const Vec<D> n = normal_at(c);
      Vec<D> at = Vec<D>::Zero();
      at[0] = x_[c], at[D - 1] = face_[c];
      at += (layer - 0.5) * p_.spacing * n;
      v[i] = dt > 0 ? Vec<D>((at - x[i]) / dt) : Vec<D>::Zero();
      x[i] = at;
      normal[i] = n;
      depth[i] = (layer - 0.5) * p_.spacing;
      film_p[i] = pressure_[c];
      film_h[i] = face_[c] - p_.plate;
      film_x[i] = x_[c];
    }
  }
  void place(World<D>& world, double dt) {
    move(world.column(components::position), world.column(components::velocity),
         world.column(components::wall_normal), world.column(components::mph_wall_depth),
         world.column(components::contact_slot), world.column(components::film_pressure),
         world.column(components::film_thickness), world.column(components::film_position), dt);
  }

  LineContactParameters p_;
  std::size_t columns_ = 0;
  std::vector<double> x_, kernel_, deformation_, pressure_, face_, sum_;
  std::vector<std::size_t> count_;
  double rho0_;
  double approach_ = 0;
  double speed_ = 0;  // U, the plate's
};

}  // namespace ryushi
