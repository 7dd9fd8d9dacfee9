// Worked example of a user system (docs/extending.md walks through it): a passive scalar phi
// carried by the fluid and diffusing with the SPH Laplacian of Morris et al. (1997),
//   dphi_i/dt = kappa c sum_j (m_j / rho_ij) 2 (phi_i - phi_j) x_ij . grad_i W_ij / (r^2 + 0.01 h^2)
// with rho_ij = (rho_i + rho_j)/2 and c the lattice normalisation below. The pair term is antisymmetric, so
// sum_i m_i phi_i is conserved to round-off. Registered by name; a scene adds it with
//   [[systems]]
//   name = "passive_scalar_diffusion"
//   diffusivity = 1e-3
// No core file is edited: built out of tree as a plugin (CMakeLists.txt here, `ryushi run
// --plugin`), or dropped into extensions/ to be built into ryushi.
#include <array>
#include <cmath>

#include "ecs/io.hpp"
#include "ecs/lattice.hpp"
#include "methods/plugin.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi::example {

// The scalar's column. It exists only in scenes that add this system.
inline constexpr Component<Scalar> scalar{"scalar"};

template <int D>
class PassiveScalarDiffusion final : public System<D> {
 public:
  PassiveScalarDiffusion(const toml::table& params, const MethodContext<D>& context)
      : context_(context),
        kappa_(*params["diffusivity"].value<double>()),
        width_(*params["width"].value<double>()),
        amplitude_(*params["amplitude"].value<double>()) {
    centre_.setZero();
    if (auto* c = params["centre"].as_array())
      for (int a = 0; a < D; ++a) centre_[a] = *(*c)[a].value<double>();
    normalisation_ = lattice_normalisation();
  }

  std::string name() const override { return "passive_scalar_diffusion"; }

  // The declaration is the contract: the scheduler orders this system after whatever writes
  // density or positions, and run() fetches exactly this list (SystemContext refuses anything
  // else).
  static constexpr auto io = Io{reads(components::position, components::density, components::mass,
                                      components::kind, neighbours_resource, resources::dt),
                                writes(scalar)};
  Access access() const override { return io.access(); }

  // Initial condition: a Gaussian bump phi = amplitude exp(-|x - centre|^2 / (2 width^2)).
  void initialise(World<D>& world, Resources&) override {
    auto& phi = world.ensure(scalar);
    auto& x = world.column(components::position);
    for (std::size_t i = 0; i < world.size(); ++i)
      phi[i] = amplitude_ * std::exp(-(x[i] - centre_).squaredNorm() / (2 * width_ * width_));
  }

  void run(SystemContext<D>& ctx) override {
    auto [x, rho, m, kind, nl, dt, phi] = io.fetch(ctx);
    rate_.assign(phi.size(), 0.0);
    const double h = context_.kernel.h(), eta2 = 0.01 * h * h;
    // Gather the rates first, then update: every particle sees the old phi of its neighbours.
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      double lap = 0;
      for (auto j : nl.of(i)) {
        if (kind[j] != kFluid) continue;  // walls are insulating
        Vec<D> xij = context_.domain.displacement(x[i], x[j]);
        double r2 = xij.squaredNorm();
        double F = context_.kernel.grad_factor(std::sqrt(r2));
        lap += m[j] / (0.5 * (rho[i] + rho[j])) * 2.0 * (phi[i] - phi[j]) * r2 * F / (r2 + eta2);
      }
      rate_[i] = kappa_ * normalisation_ * lap;
    });
    for_each_of_kind(kind, kFluid, [&](std::size_t i) { phi[i] += dt * rate_[i]; });
  }

 private:
  // The sum approximates the Laplacian only as well as the lattice samples the kernel: for
  // smooth kernels the factor is within 2% of 1, for the MPS weight (singular at r = 0) the
  // raw sum diffuses 25% too slowly. Scaling by 2D / (the sum for |x|^2 on the initial lattice)
  // makes a quadratic exact there, whatever the kernel the method hands over (as MPS's lambda0).
  double lattice_normalisation() const {
    const double d = context_.spacing, h = context_.kernel.h(), eta2 = 0.01 * h * h;
    const long reach = static_cast<long>(std::ceil(context_.kernel.support() / d)) + 1;
    std::array<long, D> lo, hi;
    lo.fill(-reach);
    hi.fill(reach + 1);
    double sum = 0;
    for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& k) {
      Vec<D> r;
      for (int a = 0; a < D; ++a) r[a] = k[a] * d;
      double r2 = r.squaredNorm();
      if (r2 == 0 || r2 >= context_.kernel.support() * context_.kernel.support()) return;
      sum += std::pow(d, D) * 2.0 * r2 * (-context_.kernel.grad_factor(std::sqrt(r2))) * r2 / (r2 + eta2);
    });
    return 2.0 * D / sum;
  }

  MethodContext<D> context_;
  double kappa_, width_, amplitude_, normalisation_ = 1;
  Vec<D> centre_;
  std::vector<double> rate_;
};

namespace {
KeySpec param(std::string key, KeyType type, std::string unit, std::string def, std::string doc,
              bool required = false) {
  return KeySpec{std::move(key), type, std::move(unit), std::move(def), std::move(doc), required};
}
}  // namespace

RYUSHI_REGISTER_SYSTEM(
    PassiveScalarDiffusion, "passive_scalar_diffusion",
    "Passive scalar `scalar` diffusing with the SPH (Morris) Laplacian; worked example of docs/extending.md.",
    {param("diffusivity", KeyType::Float, "m^2/s", "", "Diffusivity kappa.", true),
     param("centre", KeyType::Vector, "m", "(origin)", "Centre of the initial Gaussian bump."),
     param("width", KeyType::Float, "m", "0.1", "Standard deviation of the initial bump."),
     param("amplitude", KeyType::Float, "", "1.0", "Peak value of the initial bump.")});

}  // namespace ryushi::example
