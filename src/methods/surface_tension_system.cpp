// Surface tension (systems/surface_tension/) as a registered system; a scene adds it with
//   [[systems]]
//   name = "surface_tension"
//   sigma = 0.07
// It runs right after the method's free-surface detection and sets the free-surface rows'
// Dirichlet value, so the method must provide "free_surface_pressure" (ISPH's projection).
#include "methods/system_registry.hpp"
#include "systems/surface_tension/surface_tension.hpp"

namespace ryushi {

namespace {

SurfaceTensionParameters surface_tension_parameters(const toml::table& t) {
  SurfaceTensionParameters p;
  p.sigma = *t["sigma"].value<double>();
  const auto curvature = *t["curvature"].value<std::string>();
  p.curvature = curvature == "fit"          ? SurfaceCurvature::Fit
                : curvature == "tangential" ? SurfaceCurvature::Tangential
                                            : SurfaceCurvature::Paper;
  p.curvature_factor = *t["curvature_factor"].value<double>();
  p.delta_coefficient = *t["delta_coefficient"].value<double>();
  p.eigenvalue_normal = *t["normal"].value<std::string>() == "eigenvalue";
  if (auto theta = t["contact_angle"].value<double>()) p.contact_angle = *theta;
  p.capillary_step = *t["capillary_step"].value<double>();
  p.min_radius = *t["min_radius"].value<double>();
  p.viscous_normal_stress = *t["viscous_normal_stress"].value<bool>();
  return p;
}

template <int D>
class RegisteredSurfaceTension final : public SurfaceTension<D> {
 public:
  RegisteredSurfaceTension(const toml::table& t, const MethodContext<D>& context)
      : SurfaceTension<D>(surface_tension_parameters(t), context) {}
};

std::vector<KeySpec> surface_tension_keys() {
  KeySpec angle{
      "contact_angle", KeyType::Float, "degree", "",
      "Contact angle through the liquid where the surface meets a wall: the surface particles whose "
      "support reaches a wall take the normal cos(theta) n_w + sin(theta) t_w (ALE-ISPH paper Fig. 9). "
      "Left out: the normal as computed (no wetting rule)."};
  angle.min = 0.0, angle.max = 180.0, angle.min_exclusive = angle.max_exclusive = true;
  return {
      keyspec::positive("sigma", "N/m", "", "Surface tension coefficient sigma.", true),
      keyspec::choice(
          "curvature", "\"fit\"",
          "fit: kappa = div N / 2 of the quadratic h(s) fitted by weighted least squares (refitted once "
          "with Tukey's biweight of the residuals) to the particle and its surface neighbours' positions in "
          "the frame of its normal, "
          "taken half a spacing outside the particles (systems/surface_tension/curvature_fit.hpp); "
          "tangential: div_s N / 2 of the normals along the surface, corrected on the surface "
          "neighbours (tangential_divergence.hpp); paper: eq. 27 with curvature_factor. Measured on the "
          "square drop at R/d = 20 (docs/surface_tension.md): fit +0.5% of sigma / R, paper -34%; "
          "tangential unstable.",
          {"fit", "tangential", "paper"}),
      keyspec::positive("curvature_factor", "", "0.41",
                        "curvature = \"paper\": c in kappa = c sum_j V_j (N_j - N_i) . L_i gW_ij over "
                        "surface neighbours (eq. 27): the "
                        "paper's 0.41 in place of the 1/2 of kappa = div N / 2; 0.5 for the plain form."),
      keyspec::non_negative(
          "delta_coefficient", "", "0",
          "delta d of the surface force f = -sigma kappa delta N on the surface particles (eq. 26; "
          "the paper's 0.1 / d is delta_coefficient = 0.1). Off by default: on top of the surface "
          "rows' Laplace pressure it counts the jump twice (the square drop's pressure +8.5% at "
          "0.1 against +0.5% without) and made a drop at rest at water's viscosity unstable."),
      keyspec::choice(
          "normal", "\"eigenvalue\"",
          "eigenvalue: N from the gradient of the smallest eigenvalue of L_i^-1 (eqs. 24-25); "
          "kernel_sum: the free-surface detection's normal (the corrected gradient of the kernel sum).",
          {"eigenvalue", "kernel_sum"}),
      angle,
      keyspec::positive(
          "capillary_step", "", "0.5",
          "C of the capillary step limit dt <= C sqrt(rho0 d^3 / (2 pi sigma)) (Brackbill et al. "
          "1992), applied to the method's step control."),
      KeySpec{"viscous_normal_stress", KeyType::Bool, "", "true",
              "The surface rows' value is the whole normal stress balance, p_s = 2 sigma kappa + 2 mu N . "
              "grad(v) "
              "N (the predicted velocity's corrected gradient): false keeps the Laplace pressure alone."},
      keyspec::positive(
          "min_radius", "spacings", "3",
          "The smallest radius of curvature the surface takes: |kappa| is clamped to (D - 1) / (2 "
          "min_radius d), a bound on the Laplace pressure of a surface bent below what the particles "
          "resolve."),
  };
}

}  // namespace

RYUSHI_REGISTER_SYSTEM(
    RegisteredSurfaceTension, "surface_tension",
    "Surface tension on the free surface (ALE-ISPH paper eqs. 24-27): curvature, the Laplace "
    "pressure as the surface rows' Dirichlet value, the surface force and a contact angle at "
    "walls; writes `curvature`, `tension_normal` and `surface_pressure`.",
    surface_tension_keys(), {"free_surface_pressure"});

}  // namespace ryushi
