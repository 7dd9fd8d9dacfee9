// ISPH's [method] keys and the scene rules that depend on it (scene/registered_keys.hpp):
// registered with the method in isph.cpp.
#include "methods/isph_spec.hpp"

#include <cmath>

#include "methods/common_method_keys.hpp"
#include "scene/scene.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

using namespace keyspec;

std::vector<KeySpec> isph_keys() {
  using K = KeyType;
  return {
      choice(
          "description", "\"ale\"",
          "isph: how particles move (ISPH paper eqs. 6-7): lagrangian (with the fluid, w = v, no shifting), "
          "ale (w = v + dr_shift/dt with the [shifting] model, velocities Taylor-corrected to the shifted "
          "position) or eulerian (fixed particles, w = 0, the convective term in the predictor).",
          {"lagrangian", "ale", "eulerian"}),
      choice("ppe_laplacian", "\"corrected\"",
             "isph: Laplacian of the pressure equation: standard (Morris), corrected (Fatehi-Manzari, ISPH "
             "paper eqs. 11-14) or sph2 (trace of the SPH(2) Hessian).",
             {"standard", "corrected", "sph2"}),
      choice("viscous_laplacian", "\"corrected\"",
             "isph: Laplacian of the viscous term (eq. 15): standard, corrected or sph2.",
             {"standard", "corrected", "sph2"}),
      choice("pressure_gradient", "\"corrected\"",
             "isph: pressure gradient of the corrector: corrected (difference form with L_i, eq. 9), "
             "symmetric (sum (p_i + p_j) V_j gW_ij, I-SPH(2) eq. 11: momentum-conserving, pushes particles "
             "apart in proportion to the pressure; a collapsing column's pressure diverges with it from a/d "
             "= 100 up, docs/isph.md) or hybrid (symmetric where the free surface cuts the support: det(M_i) "
             "< symmetric_gradient_det and a free-surface particle in it; corrected everywhere else, walls "
             "and corners included).",
             {"corrected", "symmetric", "hybrid"}),
      choice("free_surface_pressure", "\"extrapolated\"",
             "isph: where p = 0 on the free surface: extrapolated (half a spacing outside each surface "
             "particle along its normal: p_i + d/2 N . grad p = 0) or particle (p_i = 0 at the surface "
             "particles, the ISPH paper's eq. 18, which puts the surface d/2 too deep).",
             {"extrapolated", "particle"}),
      {"confined", K::Bool, "", "false",
       "isph: the fluid fills its walls and has no free surface (a pipe, a channel): no free-surface "
       "detection and no p = 0 rows, so no particle beside a wide gap to a round wall is taken for surface. "
       "The pressure's level is set by a [[fixed_pressure]] box where there is one; without one (a periodic "
       "box, a closed box full of water) the equation has no Dirichlet row and its level is a convention, "
       "the lowest pressure 0 (src/systems/pressure/pressure_gauge.hpp). A closed box needs [[wall]] "
       "open_top = false (or a lid): with the default open top the water's upper edge has no condition at "
       "all, and the solve fails within a few steps (a 2D tank filled to its rim: step 105)."},
      choice(
          "wall_rows", "\"corrected\"",
          "isph: the walls' pressure rows. corrected and shepard keep one wall layer with normals and give "
          "each wetted wall particle a Neumann row (eq. 17, n . grad p = rho0/dt (v* - v_wall) . n) with the "
          "corrected gradient at the wall particle (the paper's) or with one-sided differences to the fluid "
          "neighbours averaged with W (positive weights, no coupling between wall particles); "
          "shepard_hydrostatic as shepard with the gradient along the wall taken hydrostatic, rho0 (g - "
          "a_w)_t, where shepard neglects it (a wall particle at the contact line then reads its fluid "
          "neighbours' higher pressure as its own: a resting tank circulated at 0.08 m/s). adami keeps "
          "the layers that cover the kernel support, as wcsph does, and gives every wall particle with fluid "
          "in its support Adami's wall pressure as its row, p_w - sum_f s_f p_f = rho0 (g - a_w) . sum_f s_f "
          "(x_w - x_f) with s_f = W_wf / sum W; the fluid rows' divergence sees the walls moving at v_wall + "
          "dt g. The default, and the only choice, where a round or mesh container holds moving particles "
          "(one layer on a curve is not stable; docs/isph.md, \"Round and mesh containers\").",
          {"corrected", "shepard", "shepard_hydrostatic", "adami"}),
      ranged({"compression_relaxation", K::Float, "", "0.0",
              "isph: alpha of the stabilised source (Asai et al. 2012): interior rows add alpha rho0 "
              "(<rho>_i/rho0 - 1)/tau^2 (compression_density says which density), tau the larger of dt and "
              "the step of the flow at rest at a CFL of 0.2 (0.2 d / sqrt(2 g H)); it keeps particles from "
              "pairing up in "
              "violent flows, and the water's volume from drifting (the corrected gradient is not the "
              "adjoint of the divergence, and the projection alone let a sloshing tank swell); 0 turns it "
              "off (the paper's divergence-free source). Not used with description = \"eulerian\"."},
             0.0, 1.0),
      choice("compression_density", "\"first_shell\"",
             "isph with compression_relaxation > 0: the density error the source answers. full_support: "
             "where no surface particle lies in the support, the kernel sum over the whole support (the "
             "wall's two missing layers completed, a box corner's over the quarter plane behind it) against the "
             "lattice's, both ways (within compression_dead_band counted as none), a dilation at most 1% (a deeper "
             "deficit is air in a splash); first_shell where the support reaches the surface. first_shell: "
             "eq. 19 over the lattice's first shell (which one wall layer fills), compression only; nothing "
             "returns a slow dilation (the one-set-up candidate's sloshing tank grew 258 J/m of potential "
             "energy by t = 16 s without the full support's term; docs/isph.md).",
             {"first_shell", "full_support"}),
      ranged({"compression_dead_band", K::Float, "", "0.0",
              "isph with compression_density = \"full_support\": a density error within this fraction counts "
              "as none. With the corrected gradient the stiff term held a standing divergence against a resting "
              "tank's floor rows, which read a few 1e-4 (1.3e-4 sqrt(g H) of motion, the pressure 3.7% off after "
              "a shorter step); 5e-4 leaves the tank at rest (5.7e-5) but lets the volume wander within it (the "
              "200-period sloshing tank's period means by 1.9 J/m with the one-set-up candidate, 3.1 with the "
              "violent-flow set-up; docs/isph.md)."},
             0.0, 0.01),
      ranged({"uncorrected_divergence_det", K::Float, "", "0.8",
              "isph: where det(M_i) (M_i = L_i^-1) is below this, the divergence of the pressure source is "
              "not corrected (I-SPH(2) section 3(2))."},
             0.0, 1.0),
      ranged(
          {"symmetric_gradient_det", K::Float, "", "0.8",
           "isph with pressure_gradient = \"hybrid\": where det(M_i) is below this and a free-surface "
           "particle lies in the support, the corrector takes the symmetric gradient (with the wall's two "
           "missing layers) instead of the corrected one. On a lattice (cubic spline, h = 1.2 d) the "
           "interior has 0.98, a flat wall's first row 0.92, the box's corner particle 0.69. At 0.6 the a/d "
           "= 20 dam break throws 562 of its 800 particles over the walls by t = 2.2 s (0.7 and 0.8: 1)."},
          0.0, 1.0),
      ranged({"collision_distance", K::Float, "spacing", "0.0",
              "isph: fluid particles closer than this (times the spacing) that still approach each other "
              "collide inelastically (the isph_collision system; src/systems/fluid/pair_collision.hpp). The "
              "corrected gradient does not push a close pair apart: without it the dam break fails in the "
              "fragmented flow after the plunging wave (a/d = 20: t = 1.37 s); with 0.8 it runs through. A fluid "
              "at rest (pairs a spacing apart) never collides; a strained lattice does (the Taylor-Green "
              "vortices lose energy). 0 (the default) leaves the system out; not used with description = "
              "\"eulerian\"."},
             0.0, 1.0),
      ranged({"collision_restitution", K::Float, "", "0.2",
              "isph: restitution coefficient e of the collision (MPS's)."},
             0.0, 1.0),
      choice("collision_approach", "\"full\"",
             "isph with collision_distance > 0: which part of a close fluid pair's approach collides. full: all "
             "of it (MPS's model). beyond_resolved_flow: only what the velocity gradient fitted over the pair's "
             "surroundings does not explain, so a smooth strain that brings pairs close (a stretched lattice "
             "at a stagnation point) is left alone; where the surroundings cannot fit a gradient (a drop of a "
             "few particles) all of it (src/systems/fluid/pair_collision.hpp).",
             {"full", "beyond_resolved_flow"}),
      choice("formulation", "\"projection\"",
             "isph: what the pressure equation asks. projection: the paper's, a velocity divergence (with "
             "the compression term) solved as a linear system at the [solver] settings, with the keys above. "
             "implicit_density: each particle's kernel sum kept through the step, with SPH's symmetric pressure "
             "force and its adjoint density change (after Ihmsen et al. 2014 and DFSPH), solved by relaxed "
             "Jacobi with p >= 0 (no free-surface detection, no shifting, the wall layers that cover the "
             "support with Adami's pressure; of the keys above only description and the collision keys "
             "apply). In 3D its default kernel is wendland_c2 with smoothing_ratio 1.0: with the ISPH paper's "
             "cubic spline at 1.2 a 3D lattice under pressure is unstable (docs/isph.md, \"Which kernel holds "
             "a lattice under pressure\").",
             {"projection", "implicit_density"}),
      ranged({"density_tolerance", K::Float, "", "1e-4",
              "isph with formulation = \"implicit_density\": the solve stops when the mean density error left "
              "over the fluid (either way where p > 0, compression where p = 0) is below this fraction of rho0."},
             1e-8, 1e-2),
      ranged({"density_relaxation", K::Float, "", "0.5",
              "isph with formulation = \"implicit_density\": omega of the relaxed Jacobi iteration. With wider "
              "kernels than the defaults it may have to fall (Wendland C2 at h = 1.5 d in 2D diverged at step "
              "2 at 0.5 and holds at 0.1)."},
             0.01, 1.0),
      ranged({"particle_damping", K::Float, "", "0",
              "isph with formulation = \"implicit_density\": eps of the particle-scale damping after the solve, "
              "v <- v - eps L(L v) with L XSPH's smoothing (src/systems/fluid/particle_scale_damping.hpp): "
              "a particle-scale jitter loses about eps a step. Off by default: it lowers and broadens "
              "travelling waves (a solitary wave's crest 20 depths from the paddle -5.8% at 0.2, -19.4% at "
              "0.1, -3.0% at 0, d = h/20), and the resting tank's motion that it held down comes from the "
              "lattice's start, which settle_steps removes (docs/isph.md, \"Settling before t = 0\"). A "
              "start far from equilibrium (a 30% disordered lattice) keeps its particle-scale energy without "
              "it; 0.2 takes it out within 2 s. Above about 0.5 the damping would overshoot on a "
              "checkerboard."},
             0.0, 0.5),
      ranged({"settle_steps", K::Integer, "", "1000",
              "isph with formulation = \"implicit_density\": steps run before t = 0 with every fluid velocity "
              "scaled by 0.99 after each, the clock held at 0, so that water at rest starts in the discrete "
              "equilibrium near the lattice (where the surface meets a wall the lattice's corner particle is "
              "pushed at 0.03 g and, undamped, keeps a 2D tank moving at 6.4e-4 sqrt(g H)). A fluid that is "
              "not at rest (a dam-break column) moves a particle half a spacing within a few dozen steps: the "
              "settle stops and the run starts as the scene made it; a fluid given a velocity is not "
              "settled. summary.json's settle block says which (app/settle.hpp; docs/isph.md, \"Settling "
              "before t = 0\"). 0: no settling."},
             0, 100000),
      wall_slip_key(),
      hydrostatic_init_key()};
}

bool implicit_density(const Scene& sc) {
  return sc.method_params.text("formulation") == "implicit_density";
}

bool one_wall_layer(const Scene& sc) {
  return sc.method_params.text("wall_rows") != "adami" && !implicit_density(sc);
}

void resolve(Scene& sc, const toml::table& root, Validator& val) {
  auto& params = sc.method_params;
  // ISPH's one wall layer with normals is a zigzag on the lattice around a curve, and the ring
  // that replaced it there was not stable (docs/isph.md, "Round and mesh containers"): a round
  // or mesh container with moving particles takes the layers of the other methods and Adami's
  // wall pressure as rows. The Eulerian pipe keeps its ring (no contact line, validated).
  const bool eulerian = params.text("description") == "eulerian";
  bool curved_container = false;
  if (auto* solids = root["solid"].as_array())
    for (std::size_t i = 0; i < solids->size(); ++i) {
      const std::string shape = root["solid"][i]["shape"].value_or(std::string("box"));
      curved_container = curved_container || (root["solid"][i]["container"].value_or(false) &&
                                              shape != "box" && !(eulerian && shape != "mesh"));
    }
  if (curved_container && !params.given("wall_rows")) params.set("wall_rows", std::string("adami"));
  if (curved_container && params.text("wall_rows") != "adami")
    val.fail(
        root["method"]["wall_rows"].node(), "method.wall_rows",
        "wall_rows = \"" + params.text("wall_rows") +
            "\" keeps one wall layer with normals, which a round or mesh container does not hold stably (a "
            "half-full ball at rest blew up at t = 0.36 s); leave wall_rows out or set \"adami\"");
}

// ISPH's one wall layer with normals (ISPH paper section 4); with wall_rows = "adami", enough to
// cover the support, as for the other methods.
int wall_layers(const Scene& sc) {
  return one_wall_layer(sc) ? 1 : static_cast<int>(std::ceil(sc.support_radius() / sc.spacing - 1e-9));
}

void validate(const Scene& sc, const toml::table& root, Validator& val) {
  const bool eulerian = sc.method_params.text("description") == "eulerian";
  const std::string one_layer =
      "method isph uses one layer of wall particles (with normals); leave layers out or set 1";
  for (std::size_t i = 0; i < sc.walls.size(); ++i)
    if (one_wall_layer(sc) && sc.walls[i].layers != 1)
      val.fail_entry(root, "wall", i, "layers", "[[wall]] #" + std::to_string(i) + ": " + one_layer);
  for (std::size_t i = 0; i < sc.solids.size(); ++i) {
    const auto& b = sc.solids[i];
    const std::string label = "[[solid]] #" + std::to_string(i) + " ";
    if (b.moves() && eulerian)
      val.fail_entry(
          root, "solid", i, b.displacement.empty() ? "displacement_table" : "displacement",
          label + "moves, but method isph with description = \"eulerian\" keeps every particle in place");
    if (one_wall_layer(sc) && b.layers != 1) val.fail_entry(root, "solid", i, "layers", label + one_layer);
  }
  if (eulerian && implicit_density(sc))
    val.fail(root["method"]["formulation"].node(), "method.formulation",
             "formulation = \"implicit_density\" moves the particles to hold their density; it has no eulerian "
             "description (use formulation = \"projection\" for fixed particles)");
  // Particles that move would carry a fixed pressure away.
  for (std::size_t i = 0; i < sc.fixed_pressure.size() && !eulerian; ++i)
    val.fail_entry(root, "fixed_pressure", i, "min",
                   "[[fixed_pressure]] #" + std::to_string(i) +
                       " needs [method] name = \"isph\" with description = \"eulerian\" (fixed particles)");
}

}  // namespace

MethodSpec isph_spec() {
  MethodSpec spec;
  spec.doc =
      "incompressible SPH: corrected ALE-ISPH with one layer of Neumann walls, density-based shifting and "
      "I-SPH(2) free surfaces (pressure equation solved as set in [solver]; docs/isph.md)";
  spec.keys = isph_keys();
  spec.owns = {"fixed_pressure"};
  // The ISPH paper's cubic spline with h = 1.2 d; in 3D the implicit density formulation takes
  // Wendland C2 with h = d, where a lattice under pressure is stable (with the cubic spline at
  // 1.2 d a 3D tank at rest grew to 7e-2 sqrt(g H); in 2D the cubic spline at 1.2 d is stable and
  // Wendland at d too narrow for the dam break's spray): docs/isph.md, "Which kernel holds a
  // lattice under pressure", tools/kernel_stability.py.
  spec.hooks.kernel = [](const Scene& sc) {
    return std::string(sc.dimension == 3 && implicit_density(sc) ? "wendland_c2" : "cubic_spline");
  };
  // The width follows the kernel (given or default): Wendland C2 at h = d under implicit density
  // in either dimension (1.2 d is unstable for it, tools/kernel_stability.py), 1.2 d otherwise.
  spec.hooks.smoothing_ratio = [](const Scene& sc) {
    return sc.kernel == "wendland_c2" && implicit_density(sc) ? 1.0 : 1.2;
  };
  spec.hooks.jacobi_weight = 2.0 / 3.0;
  spec.hooks.shifting = "density";
  spec.hooks.solves_pressure = true;
  spec.hooks.step_motion = 3.0;
  // Peak resident, 4 steps of the dam break (2026-11-29): 2D 1,550 bytes per particle between 34k
  // and 131k particles, 3D 2,825 between 34k and 199k (the matrix and its multigrid levels).
  spec.hooks.bytes_per_particle = [](int dimension) { return dimension == 2 ? 1700.0 : 3100.0; };
  spec.hooks.resolve = resolve;
  spec.hooks.wall_layers = wall_layers;
  spec.hooks.validate = validate;
  // The projection's free-surface rows take the Dirichlet value a system writes (surface
  // tension); the implicit density formulation and a confined fluid have no such rows.
  spec.hooks.provides = [](const Scene& sc) {
    return implicit_density(sc) || sc.method_params.flag("confined")
               ? std::vector<std::string>{}
               : std::vector<std::string>{"free_surface_pressure"};
  };
  return spec;
}

}  // namespace ryushi
