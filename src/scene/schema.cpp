#include "scene/schema.hpp"

#include <algorithm>
#include <sstream>

#include "scene/registered_keys.hpp"
#include "kernels/kernel.hpp"

namespace ryushi {

namespace {

using namespace keyspec;

// "Method: a = ...; b = ..." from the method registry (each method registers its own line).
std::string methods_doc() {
  std::string doc = "Method:";
  for (auto& name : method_spec_names()) doc += " " + name + " = " + find_method_spec(name)->doc + ";";
  doc.back() = '.';
  return doc;
}

// centre, radius and axis of the round shapes ([[fluid]] and [[solid]] `shape`), after `shape`.
void add_round_keys(SectionSpec& section, const std::string& centre_doc) {
  auto shape = std::find_if(section.keys.begin(), section.keys.end(), [](auto& k) { return k.key == "shape"; });
  section.keys.insert(shape + 1, {{"centre", KeyType::Vector, "m", "", centre_doc},
                                  positive("radius", "m", "", "cylinder, sphere: radius."),
                                  ranged({"axis", KeyType::Integer, "", "2", "3D cylinder: the axis (0, 1, 2) it runs along."}, 0, 2)});
}

std::vector<SectionSpec> build() {
  using K = KeyType;
  std::vector<SectionSpec> s;
  s.push_back({"scene", false, true, "What the scene is.",
               {ranged({"dimension", K::Integer, "", "", "Spatial dimension: 2 or 3.", true}, 2, 3),
                {"name", K::String, "", "(file name without .toml)", "Name used in logs and summary.json."},
                {"description", K::String, "", "\"\"", "Free text."}}});
  s.push_back({"domain", false, true,
               "The box that must contain every particle for the whole run (walls included). A "
               "particle leaving it is a numerical failure (exit code 3), unless outflow = \"remove\".",
               {{"min", K::Vector, "m", "", "Lower corner, one value per axis.", true},
                {"max", K::Vector, "m", "", "Upper corner, one value per axis.", true},
                {"periodic", K::BoolVector, "", "(false on every axis)",
                 "Per axis: wrap particles and neighbour search across the box. A periodic axis "
                 "must be at least three neighbour-search radii long: 3 (support + neighbour_skin spacings), plus the step's motion for mps and isph (2.5 and 3 cfl spacings)."},
                choice("outflow", "\"fail\"", "A fluid particle that leaves the box: fail (a numerical failure, exit code 3) or remove (erased between steps, counted as removed_particles and removed_mass in summary.json, the first one logged): spray over an open tank's walls, an open channel's end.", {"fail", "remove"})}});
  s.push_back(
      {"particles",
       false,
       true,
       "Particle lattice and kernel.",
       {positive("spacing", "m", "", "Initial particle spacing d (lattice step).", true),
        ranged({"smoothing_ratio", K::Float, "",
                "(1.5; method mps: 3.1 in 2D, 2.1 in 3D; isph: 1.2, with formulation = implicit_density and "
                "wendland_c2 1.0)",
                "Smoothing length h = smoothing_ratio * spacing; support radius 2h. 1.5 with Wendland C2 "
                "keeps the lattice first moment within 0.3% of the identity (1.3 gives 2.6%, which shows up "
                "as a 2.6% pressure error at rest). With the mps kernel h is the influence radius r_e (the "
                "BMG paper's 3.1 l0 / 2.1 l0)."},
               0.5, 4.0),
        choice("kernel",
               "(wendland_c2; method mps: mps; isph: cubic_spline, in 3D with formulation = implicit_density "
               "wendland_c2)",
               "Smoothing kernel (src/kernels/kernel.hpp). Support radius: 2h, except quintic_spline 3h and "
               "mps h (h = r_e). Method mps needs the mps weight.",
               kernel_names()),
        ranged({"disorder", K::Float, "spacings", "0.0",
                "Displace each fluid particle from its lattice point by a random amount, uniform in "
                "[-disorder d, disorder d] on each axis (a reproducible sequence per particle from `seed`): "
                "a start without the lattice's symmetry, for robustness checks. Below 0.5, so that no two "
                "particles meet."},
               0.0, 0.499),
        ranged({"seed", K::Integer, "", "1",
                "Seed of the `disorder` displacements (the same seed gives the same particles)."},
               0, std::nullopt),
        ranged({"reorder_interval", K::Integer, "steps", "25",
                "Reorder particles by cell every this many steps for cache locality (0: never). Ids are "
                "stable."},
               0, std::nullopt),
        ranged(
            {"neighbour_skin", K::Float, "spacings", "0.6",
             "The neighbour list is a Verlet list holding the pairs within the method's search radius plus "
             "this skin (in units of the spacing d) and is rebuilt only when a particle may have moved half "
             "the skin since the last build (or after a reordering); each step the list is filtered to the "
             "pairs within the search radius, so the result is the same as with 0 (rebuilt every step). "
             "WCSPH: 0.6 was fastest at 255k particles moving at 3 m/s (docs/benchmarks.md). MPS and ISPH "
             "(whose search radius already holds the step's own motion, so only the start of the step "
             "counts): over the a/d = 100 dam break to t = 0.3 s a build every 2.4 steps, the search 10.9 -> "
             "7.8 ms per step (MPS) and 7.2 -> 5.6 (ISPH); 1.2 and 2.0 gained little more. The candidates "
             "cost memory (kept in two bytes each): in 3D WCSPH at 1M particles the neighbour memory goes "
             "from 193 to 435 bytes per particle at 0.6 (peak resident 783 and 1,422 bytes per particle at 0 "
             "and 0.6), at 10M (more fluid, fewer walls) from 270 to 587 (peak resident 15.0 GiB at 0.6 "
             "against 9.0 at 0), in 2D at a/d = 100 MPS 397, ISPH 317, WCSPH 169 at 0.6; set 0 where memory "
             "is tighter than time (25% slower at 1M in 3D). isph with formulation = \"implicit_density\": "
             "not used, the list is rebuilt every step (its step moves the fastest particle 0.4 d)"},
            0.0, 3.0)}});
  s.push_back({"material", false, false, "Fluid properties.",
               {positive("density", "kg/m^3", "1000.0", "Reference density rho0."),
                non_negative("viscosity", "Pa s", "0.0",
                             "Dynamic viscosity mu. 0 leaves the laminar viscosity system (and its "
                             "per-particle `viscosity` column) out of the pipeline."),
                non_negative("sound_speed", "m/s", "0.0", "Artificial sound speed c0. 0: c0 = sound_speed_factor * sqrt(2 g H), H the height of the tallest fluid block."),
                positive("sound_speed_factor", "", "10.0", "Used when sound_speed = 0; 10 keeps density variations near 1%."),
                positive("gamma", "", "7.0", "Tait exponent."),
                choice("rheology", "\"newtonian\"", "wcsph: the fluid's viscosity model (src/materials/rheology.hpp; docs/multiphysics.md), the apparent viscosity mu(gamma_dot) at the shear rate gamma_dot = sqrt(D:D/2), D = grad v + grad v^T (seed 001 eqs. 3-5): newtonian mu = `viscosity`; power_law K gamma_dot^(n-1) (`consistency`, `power_index`); cross mu_inf + (mu_0 - mu_inf)/(1 + (lambda gamma_dot)^n) (`viscosity` = mu_inf, `zero_shear_viscosity`, `time_constant`, `power_index`); bingham mu_p + tau_0 (1 - exp(-m gamma_dot))/gamma_dot (Papanastasiou's regularisation: `viscosity` = mu_p, `yield_stress`, `regularisation` = m); herschel_bulkley K gamma_dot^(n-1) + the same yield term. Each particle's viscosity is recomputed every stage from its velocity gradient (and temperature, with `activation_energy`); the time step takes the viscous limit with the largest.", {"newtonian", "power_law", "cross", "bingham", "herschel_bulkley"}),
                positive("consistency", "Pa s^n", "(none)", "power_law, herschel_bulkley: K (required there)."),
                positive("power_index", "", "(none)", "power_law, herschel_bulkley, cross: n (required there) (power law: n < 1 shear-thinning, n > 1 shear-thickening)."),
                positive("yield_stress", "Pa", "(none)", "bingham, herschel_bulkley: tau_0 (required there)."),
                positive("regularisation", "s", "(none)", "bingham, herschel_bulkley: Papanastasiou's m (required there): below the yield stress the fluid flows with viscosity up to mu_p + tau_0 m; the larger m, the stiffer the unyielded plug and the smaller the time step (its viscous limit uses that viscosity)."),
                positive("zero_shear_viscosity", "Pa s", "(none)", "cross: mu_0 (required there)."),
                positive("time_constant", "s", "(none)", "cross: lambda (required there)."),
                positive("max_viscosity", "Pa s", "(none)", "Cap on the apparent viscosity (after the temperature factor). Required for a power_law or herschel_bulkley fluid with n < 1 (infinite viscosity at rest) and for one with an activation_energy; the viscous time-step limit follows it where it is reached."),
                {"activation_energy", K::Float, "J/mol", "0.0", "Arrhenius temperature dependence (seed 001 eqs. 7-8 in the usual form): the apparent viscosity is multiplied by exp(E/R (1/T - 1/T_ref)), R = 8.314 J/(mol K), T the particle's temperature; needs reference_temperature and a scene with temperatures. Negative thins the fluid as it cools. 0: none."},
                positive("reference_temperature", "K", "(none)", "T_ref of the Arrhenius factor: the model's parameters are those at T_ref."),
                non_negative("conductivity", "W/(m K)", "0.0", "wcsph: thermal conductivity k of the fluid (and of fixed-temperature walls); > 0 turns heat conduction on (Cleary-Monaghan's SPH Laplacian, seed 001 eq. 34): every fluid particle carries a temperature, written to the frames, and the time step takes the limit 0.125 h^2 rho0 c / k."),
                positive("heat_capacity", "J/(kg K)", "4186.0", "Specific heat capacity c of the fluid (with conductivity)."),
                positive("temperature", "K", "(none)", "Initial temperature of the fluid blocks that give none; needed with conductivity > 0 unless every [[fluid]] has a temperature.")}});
  s.push_back({"physics", false, false, "Body forces.",
               {{"gravity", K::Vector, "m/s^2", "(0, -9.81) in 2D; (0, 0, -9.81) in 3D",
                 "Gravitational acceleration. The last axis is 'up' for probes and hydrostatic initialisation."}}});
  s.push_back({"method", false, false, "The particle method. Its other keys are the chosen method's own (below): a key of another method is an error at the key. A scene run under several methods (--set method.name=...) keeps each method's settings in a [method.<name>] table, read only when that method is the scene's.",
               {choice("name", "\"wcsph\"", methods_doc(), method_spec_names())}});
  s.push_back({"shifting", false, false, "Particle shifting: isph with description = \"ale\" (docs/isph.md), and wcsph with model = \"fickian\", \"optimised\" or \"xsph\" (docs/wcsph.md).",
               {choice("model", "(density for isph; none for wcsph)", "none; density: density-based shifting (ISPH paper eqs. 19-25; isph only); fickian: dr = -A h |v| dt grad C (Lind et al. 2012, Skillen et al. 2013), tangential only on the flagged surface; optimised: the same with only the tangential part kept in the whole surface region, every particle with a surface particle inside its support (OPS, Khayyer et al. 2017); xsph: transport with the XSPH-smoothed velocity, dr = eps dt sum 2 m_j/(rho_i + rho_j) (v_j - v_i) W_ij (I-SPH(2) eq. 9).", {"none", "density", "fickian", "optimised", "xsph"}),
                ranged({"coefficient", K::Float, "", "0.005", "density model: C_shift of eq. 20, dr = C_shift h (dr_w + dr_dens)."}, 0.0, 1.0),
                ranged({"fickian_coefficient", K::Float, "", "2.0", "fickian and optimised models: A of dr = -A h |v| dt grad C (Skillen et al. 2013 recommend 1-6)."}, 0.0, 100.0),
                ranged({"anti_clumping", K::Float, "", "0.2", "fickian and optimised models: R of the anti-clumping term, grad C = sum V_j (1 + R (W_ij/W(d))^4) grad W_ij (Lind et al. 2012)."}, 0.0, 10.0),
                ranged({"max_shift", K::Float, "", "0.2", "fickian, optimised and xsph models: largest shift per step, in particle spacings."}, 0.0, 1.0),
                ranged({"xsph_epsilon", K::Float, "", "0.5", "xsph model: eps of the velocity smoothing (Monaghan 1989: 0.5)."}, 0.0, 1.0)}});
  s.push_back({"swe", false, false, "The shallow-water method ([method] name = \"swe\", 2D plan view: x and y horizontal, the water column along z; docs/swe.md). [physics] gravity must be left out (the water's weight acts along z: `gravity` below).",
               {positive("gravity", "m/s^2", "9.81", "g of the shallow-water equations (along -z)."),
                non_negative("manning", "s/m^(1/3)", "0.0", "Manning roughness n_M of the bed friction S_f = n_M^2 |u| u / h^(4/3) (eq. 3 with the hydraulic radius = depth, sheet flow); 0: frictionless."),
                ranged({"influence_ratio", K::Float, "", "1.3", "alpha_e of the influence radius r_e = alpha_e sqrt(A_max) (eq. 9), one radius for all particles, recomputed every step; the spiky kernel reaches 2 r_e."}, 0.5, 4.0),
                choice("walls", "\"slip\"", "Ghost particles mirrored across the [[wall]] sides (section 2(5)): slip keeps the tangential velocity, no_slip reverses it; the normal velocity is reversed in both.", {"slip", "no_slip"}),
                choice("momentum", "\"mps\"", "The pressure term of the momentum equation (docs/swe.md, \"Momentum\"). mps: -g times eq. 6's gradient of the surface z_s = h + z_b, plus the dry side's push where the neighbourhood is cut off (edge_correction); well balanced (a lake at rest over any bed stays at rest to round-off). sph: -g times the gradient of the depth sum of eq. 7 itself, sum_j V_j grad W_ij on a flat bed (written as sum_j A_j (z_s,j - z_s,i) grad W_ij + h_i sum_j A_j grad W_ij so that it takes a bed): the variational form, pairwise momentum-conserving on a flat bed, whose front runs out as eq. 7 says it thins (Ritter at d = 0.1 m with splitting: front-region error 0.15 against mps's 0.29, front 5.40 m against 5.18); not well balanced over relief (a lake over a 0.15 m hump moves at 0.1 m/s): for flat or gently sloping beds.", {"mps", "sph"}),
                {"edge_correction", K::Bool, "", "true", "momentum = \"mps\": add the dry side's push at a wet/dry edge: the gradient of eq. 6 sees only the particles present, so a front particle, whose SPH depth stays near the depth behind it, misses the drop to the dry bed beyond it (measured on Ritter's dam break: the front lags the analytic one by the same ~1.3 m at every resolution without it). The term -g D h_i sum_j x_ij w_ij / |x_ij|^2 / sum_j w_ij is the eq. 6 gradient's contribution of the missing neighbours at depth 0; it vanishes on any complete, symmetric neighbourhood (interior, walls with ghosts, a lake at rest). docs/swe.md."},
                {"ritter_dam_x", K::Float, "m", "(none)", "With ritter_depth: the scene is Ritter's dry-bed dam break (dam at x = ritter_dam_x, water on the lower-x side); summary.json gets the front-region depth error against the analytic solution (eq. 14) and the front position (docs/swe.md)."},
                positive("ritter_depth", "m", "(none)", "h0 of the Ritter reference.")}});
  s.push_back({"bed", false, false, "swe: the bed elevation z_b(x, y): the base (`elevation` or a `raster`), plus [[bed_hump]]s, plus [[bed_ramp]]s.",
               {{"elevation", K::Float, "m", "0.0", "Constant base elevation."},
                {"raster", K::String, "", "(none)", "ESRI ASCII grid (.asc; path relative to the scene file) replacing the constant base: bilinear between cell centres, clamped at the edges. Header keys ncols, nrows, xllcorner|xllcenter, yllcorner|yllcenter, cellsize, optional NODATA_value; then nrows rows of ncols values, north first. No-data cells are dry high ground: they read the raster's highest valid elevation (water runs up against them like against a bank) and no fluid particle starts on one. A missing key, a wrong cell count or a non-number is exit code 2 naming the raster's file and line."}}});
  s.push_back({"bed_hump", true, false, "swe: a Gaussian hump added to the bed, z += height exp(-|x - centre|^2 / width^2).",
               {{"centre", K::Vector, "m", "", "Centre (x, y).", true},
                {"height", K::Float, "m", "", "Height (negative: a hollow).", true},
                positive("width", "m", "", "e-folding width.", true)}});
  s.push_back({"bed_ramp", true, false, "swe: a plane added to the bed inside the box [min, max]: z += gradient . (x - origin) (a slope starting at origin; piecewise planes by several ramps).",
               {{"min", K::Vector, "m", "", "Lower corner of the ramp's box.", true},
                {"max", K::Vector, "m", "", "Upper corner.", true},
                {"origin", K::Vector, "m", "", "Point where the ramp adds nothing.", true},
                {"gradient", K::Vector, "", "", "dz/dx, dz/dy (0.1: a 10% slope rising along x).", true}}});
  s.push_back({"splitting", false, false, "swe: dynamic particle splitting (section 2(3), src/systems/splitting/).",
               {{"enabled", K::Bool, "", "true", "Split particles whose area grew past area_ratio * A0 (A0 = spacing^2)."},
                ranged({"area_ratio", K::Float, "", "1.5", "Split when A_i > area_ratio * A0 (the paper's 1.5)."}, 1.0, 100.0),
                choice("direction", "\"gap\"", "The split direction t_i, an eigenvector of the moment matrix C_i = sum_j x_ij x_ij^T w_ij: gap (the smallest eigenvalue's: across the largest gap between the neighbours) or spread (the largest eigenvalue's, eq. 11 as printed). At a thinning front the particles stand in rows across the flow and spread splits them along the row: on Ritter's dam break its front lags the unsplit one and does not converge with resolution, while gap reproduces the paper's front (docs/swe.md).", {"gap", "spread"}),
                ranged({"distance", K::Float, "", "0.7", "alpha_s: the children are alpha_s sqrt(A_i) apart (eq. 10)."}, 0.01, 2.0),
                ranged({"max_particles", K::Integer, "", "(20 x the initial count)", "Cap on the particle count: when a step's splits would pass it, splitting stops with one warning and the run goes on."}, 0, std::nullopt)}});
  s.push_back({"time", false, true, "Time control.",
               {positive("end", "s", "", "Simulated end time.", true),
                ranged({"cfl", K::Float, "", "(0.2; swe 0.5)", "CFL number for the adaptive step dt = cfl h / (c0 + |v|max), also bounded by force and viscous limits; isph: dt (|v|max + |g| dt) = cfl d, the particles' own speed and what gravity adds within the step, and at most 0.03 sqrt(d / g), the particle-scale surface wave (no sound speed, no free-fall floor; docs/isph.md, \"The step\"); mps: cfl l0 / max(|v|max, sqrt(2 g H)) (WCSPH's resting tank holds at a fixed step of 0.5 h / c0 with the leapfrog, h / c0 with the midpoint: tests/stability/time_step_test.cpp); swe: dt = cfl min sqrt(A_i) / (sqrt(g h_i) + |u_i|) (eq. 13)."}, 1e-6, 1.0),
                non_negative("dt", "s", "0.0", "Fixed time step; 0 = adaptive."),
                ranged({"max_steps", K::Integer, "", "0", "Stop after this many steps (0: no limit)."}, 0, std::nullopt),
                non_negative("dt_min", "s", "1e-9", "An adaptive step below this is a numerical failure (dt collapse)."),
                ranged({"steady_tolerance", K::Float, "", "0", "Stop once the flow is steady: the fluid's kinetic energy changed by at most this fraction of itself over steady_window (0: run to end). The run's status is then \"steady\" (exit 0) and its message says when; at least ten steps must lie in the window. One pass over the fluid a step (src/app/steady_stop.hpp)."}, 0.0, 1.0),
                non_negative("steady_window", "s", "0", "The time over which steady_tolerance is judged; 0: the last tenth of the time run so far (the kinetic energy changing less than 0.1% over the last 10% of the run: steady_tolerance = 1e-3)."),
                choice("step_rule", "\"cfl\"", "wcsph: the adaptive step. cfl: the smallest of cfl h / (c0 + |v|max), 0.25 sqrt(h / |a|max), 0.125 h^2 / nu_max and (with heat) 0.125 h^2 / alpha, the last two halved with the leapfrog integrator; seed001: seed 001 eq. 35, 0.1 min(h / (|v|max + c0), h^2 / (6 nu_max)) (cfl is not used), still bounded by the heat conduction limit.", {"cfl", "seed001"})}});
  s.push_back({"solver", false, false,
               "The linear solver of the pressure Poisson equation (implicit methods: mps, isph; isph's system is not symmetric and always uses bicgstab). Ignored by wcsph. Each step the pipeline runs `ppe_assembly`, then `multigrid_setup` (or `jacobi_setup`), then `linear_solve`, each timed on its own in profile.json. docs/solvers.md.",
               {choice("krylov", "\"cg\"", "Krylov method: cg (symmetric matrices, the MPS Laplacian) or bicgstab (non-symmetric). A non-symmetric system (ISPH) is always solved with bicgstab; summary.json names the method the solves used.", {"cg", "bicgstab"}),
                choice("preconditioner", "\"multigrid\"", "none, jacobi (diagonal scaling: DCG) or multigrid (bucket-based multigrid, BMG).", {"none", "jacobi", "multigrid"}),
                choice("cycle", "\"sw\"", "Multigrid cycle: v, w or sw (W with the scale correction A_c = P^T A P / 2 below level 1, BMG paper eq. 18).", {"v", "w", "sw"}),
                choice("precision", "\"mixed\"", "Multigrid hierarchy in float under a double Krylov method (mixed) or all double.", {"double", "mixed"}),
                positive("tolerance", "", "1e-8", "Stop when |b - A x| / |b| <= tolerance (BMG paper eq. 25)."),
                ranged({"max_iterations", K::Integer, "", "1000", "Iteration cap; reaching it is a numerical failure (exit code 3) naming the step and `linear_solve`."}, 1, std::nullopt),
                choice("initial_guess", "\"previous\"", "previous: start from the last step's pressure (fewer iterations); zero: start from 0 as in the paper.", {"previous", "zero"}),
                ranged({"pre_smoothing", K::Integer, "sweeps", "1", "Jacobi sweeps before restriction."}, 0, 16),
                ranged({"post_smoothing", K::Integer, "sweeps", "1", "Jacobi sweeps after prolongation."}, 0, 16),
                ranged({"bottom_smoothing", K::Integer, "sweeps", "2", "Jacobi sweeps on the coarsest level."}, 1, 64),
                ranged({"bottom_size", K::Integer, "rows", "64", "A level with at most this many rows is the coarsest. The BMG paper's 1024 suits a million unknowns; at the few thousand of a small scene it leaves a barely coarsened bottom that two Jacobi sweeps do not solve (2D dam break, 3,200 particles: 49 CG iterations per solve at 1024, 23 at 256, 17 at 64)."}, 1, std::nullopt),
                ranged({"jacobi_weight", K::Float, "", "(1; isph 2/3)", "Weight w of the multigrid's Jacobi sweeps z += w D^-1 (r - A z). mps: 1. Its matrix and every coarse matrix of it are weakly diagonally dominant with positive diagonals and negative off-diagonals, so the eigenvalues of D^-1 A lie in [0, 2] (Gershgorin) and a sweep with w = 1 amplifies no error mode; 2/3, the textbook value for the 5-point Laplacian, damps the upper half of the spectrum more slowly (3D dam break at 1M particles, max eig(D^-1 A) about 1.3: 15 CG iterations per solve at 2/3, 12 at 1; docs/solvers.md). isph: 2/3 (its corrected Laplacian is not always diagonally dominant). Above 2 / max eig(D^-1 A) the sweep amplifies errors and the solve fails."}, 1e-3, 1.5)}});
  s.push_back(
      {"health",
       false,
       false,
       "Physical checks after every step (src/app/health_monitor.hpp, docs/health.md): a run that "
       "breaks one stops with exit code 3, naming the step, the check, the particle and the likely "
       "cause, instead of completing with nonsense. Each bound can be set here; 0 turns a check off.",
       {choice("action", "\"stop\"",
               "stop: a broken check is a numerical failure (exit code 3). warn: one warning per check, "
               "recorded in summary.json (health.warnings), and the run goes on.",
               {"stop", "warn"}),
        ranged({"density_deviation", K::Float, "", "(wcsph: 2 (U / c0)^2 = 0.02; others 0: not checked)",
                "More than 2% of the fluid particles (and more than 10) farther than this from rho0 (|rho / "
                "rho0 - 1|) is a failure. WCSPH's default is twice what the flow's own pressure rho0 (g H + "
                "U^2 / 2) = rho0 U^2 (U = sqrt(2 g H)) does to a weakly compressible fluid, 2 (U / c0)^2 "
                "(without gravity and with a given sound_speed, U / c0 = 0.1). The bulk of the fluid, not "
                "its extremes: an impact's water hammer compresses the few particles at the wall by up to U "
                "/ c0 (the dam break's far corner 7-8%, a drifting block on an elastic plate 1.5% of its "
                "water beyond 2%), which is the flow. The dam break at a / d = 40 keeps all but 0.19% of its "
                "fluid within 2%; inviscid without delta-SPH it passed the bound at t = 0.33 s, at time.cfl "
                "= 0.5 and a / d = 20 at t = 0.09 s (docs/health.md)."},
               0.0, 1.0),
        non_negative("energy_rise", "", "0.05",
                     "Where nothing adds energy (no moving or prescribed-velocity solid, no elastic body, no "
                     "fixed-pressure box, no [[systems]], no periodic axis along gravity): the fluid's "
                     "kinetic plus potential energy may rise above its start by at most this fraction of the "
                     "energy scale, the start's kinetic energy plus the potential energy above its lowest "
                     "fluid particle. Viscosity and collisions only take energy away; the weakly "
                     "compressible fluid's elastic energy returns a little at impacts."),
        non_negative(
            "pressure_factor", "", "(0: not checked)",
            "A fluid particle's |p| at most this many times the scene's pressure scale, the largest of rho0 "
            "(|g| H + U^2 / 2) (H the fluid's height at the start, U the largest of its starting speed, the "
            "solids' speeds and sqrt(2 |g| H)), mu U / d and the largest starting |p| (fixed-pressure boxes "
            "included). Off by default: single particles of sound runs read spikes far beyond any such scale "
            "(a WCSPH drifting block on an elastic plate: 53 times, one particle 24.5% compressed, t = 0.375 "
            "s; ISPH's 3D dam break: 75 MPa, 8,000 times, at t = 0.384 s), and WCSPH's pressure follows its "
            "density, which density_deviation checks. 50 caught the inviscid dam break at t = 0.380 s."),
        {"wall_penetration", K::Bool, "", "true",
         "A fluid particle surrounded by the wall particles of a [[wall]] or static [[solid]] (its cell of "
         "one spacing and the cells beside it all hold wall particles: a spacing or more inside a wall of "
         "two or more layers) is a failure: the walls stopped holding the fluid (a step too long for the "
         "wall force, missing density diffusion). Walls of one layer (isph) cannot show it; the wall guard "
         "keeps those."}}});
  s.push_back({"output", false, false, "What is written to the output directory.",
               {non_negative("interval", "s", "(end / 20)", "Simulated time between frames (frame 0 is the initial state). The step that crosses a frame time is shortened to land on it, so frame k is at exactly k * interval."),
                {"fields", K::StringList, "", "[]",
                 "Extra per-particle fields to write besides position, velocity, pressure, density, kind, id (e.g. \"acceleration\", \"density_rate\", \"mass\"; \"vorticity\", computed when a frame is written: 2D dv/dx - du/dy, 3D the vector curl v, docs/output.md)."},
                non_negative("probe_interval", "s", "(interval / 10)", "Simulated time between probe samples in probes.csv."),
                non_negative("checkpoint_interval", "s", "0.0", "Simulated time between checkpoints (0: none): OUT/checkpoint.h5 holds the whole state, written atomically after the first step that reaches each multiple; `ryushi resume OUT` continues from it and gives the same result, bit for bit with the same thread count, as a run that was never stopped (docs/output.md). `ryushi run --checkpoint-interval T` overrides it.")}});
  s.push_back({"import", true, false,
               "Fluid particles read from a file, with or instead of [[fluid]] blocks (methods wcsph, mps, isph): a settled tank can start the next run. A ryushi frame (.h5: the fluid particles' position, velocity and pressure) or a CSV (.csv: a header naming x, y[, z] and any of u, v[, w] (velocity) and p (pressure), then one particle per line). Without a pressure the method starts its own (hydrostatic below the highest imported particle). Each particle gets the mass of a lattice cell, rho d^dim, so import particles spaced by [particles] spacing. A particle inside a [[solid]] (outside a container) is bad input (exit 2); one near its surface is not (a settled run's fluid lies closer to its walls than a generated block's).",
               {{"file", K::String, "", "", "The file, relative to the scene file.", true}}});
  s.push_back({"fluid", true, false, "A block of fluid on the lattice: particles at min + (k + 1/2) d (a scene needs at least one [[fluid]] or [[import]]).",
               {{"min", K::Vector, "m", "(shape box: required; round shapes: their bounding box)", "Lower corner."},
                {"max", K::Vector, "m", "(shape box: required; round shapes: their bounding box)", "Upper corner."},
                choice("shape", "\"box\"", "box: [min, max]; cylinder: the lattice points within `radius` of `centre` (2D a disc; 3D a cylinder along `axis` over [min, max] on that axis, required there); sphere: within `radius` of `centre` (3D; a disc in 2D). The lattice starts at min (default centre - radius).", {"box", "cylinder", "sphere"}),
                {"velocity", K::FieldVector, "m/s", "(at rest)", "Initial velocity of the block's particles, one entry per axis: a number, or an expression of the particle's x, y, z as a string (muparser syntax: + - * / ^, sin, cos, tan, exp, log, sqrt, abs, min, max, pi, e, `c ? a : b`), e.g. [\"sin(2*pi*x)*cos(2*pi*y)\", \"-cos(2*pi*x)*sin(2*pi*y)\"]. A bad expression is an error at the key with the parser's message; a value that is not finite at some particle is an error naming the particle's place."},
                {"mesh", K::String, "", "(the whole box)", "3D: fill only the lattice points of [min, max] inside this closed [[mesh]] (by name)."},
                {"pressure", K::FieldValue, "Pa", "(hydrostatic)", "Initial pressure of the block's particles: a number or an expression of x, y, z (as for `velocity`), in place of the hydrostatic start (methods wcsph, mps, isph). WCSPH gives each particle the density that its equation of state maps to this pressure; MPS and ISPH take it as the first pressure solve's guess and for output."},
                {"angular_velocity", K::Float, "1/s", "0.0", "2D: initial rigid rotation about the block's centre, v = (omega (y - yc), -omega (x - xc)) (clockwise for omega > 0; the rotating square patch), added to `velocity`."},
                positive("depth", "m", "(none)", "swe: the water depth of the block (one of depth and surface_elevation is required)."),
                {"surface_elevation", K::Float, "m", "(none)", "swe: the water surface of the block; depth = surface_elevation - bed, and lattice points where that is not positive are dry (no particle): a lake over a bumpy bed."},
                positive("temperature", "K", "([material] temperature)", "wcsph with heat: the block's initial temperature.")}});
  add_round_keys(s.back(), "cylinder, sphere: centre.");
  s.push_back({"wall", true, false, "A rigid container: `layers` of wall particles outside the box [min, max]. swe: the box's sides are mirror lines for ghost particles (layers only has to keep the domain large enough; open_top is ignored, a plan view has no top; open_ends opens an axis).",
               {{"min", K::Vector, "m", "", "Inner lower corner.", true},
                {"max", K::Vector, "m", "", "Inner upper corner.", true},
                ranged({"layers", K::Integer, "", "(ceil(support radius / spacing))", "Wall thickness in particle layers; layers * spacing must cover the support radius."}, 1, 16),
                {"open_top", K::Bool, "", "true", "Leave the upper side (last axis) open."},
                {"open_ends", K::BoolVector, "", "(false on every axis)", "Per axis: no wall at either end of that axis (a channel's inlet and outlet, e.g. [true, false])."},
                positive("temperature", "K", "(adiabatic)", "wcsph with heat: the wall holds this temperature (Dirichlet); without temperature and heat_flux it is adiabatic (no heat through it)."),
                {"heat_flux", K::Float, "W/m^2", "(adiabatic)", "wcsph with heat: heat entering the fluid through the wall per unit area (Neumann; negative: leaving it). Not with temperature."}}});
  s.push_back({"mesh", true, false,
               "3D: a triangle surface from an STL file (ASCII or binary, read by CGAL), placed by scale, rotate and translate (in that order). A closed mesh can be filled with fluid ([[fluid]] `mesh`) or made a solid body ([[solid]] shape = \"mesh\"); an open one only a solid surface: the fluid is on the side its faces' normals point to, and the particle layers lie behind it (wind a tank's faces towards the water). The file is read when the scene loads: a missing or unreadable file is an error there.",
               {{"name", K::String, "", "", "Name, for [[fluid]] and [[solid]] `mesh`.", true},
                {"file", K::String, "", "", "The STL file, relative to the scene file.", true},
                positive("scale", "", "1.0", "Factor from the file's units to metres (0.001 for a file in millimetres)."),
                {"rotate", K::Vector, "degrees", "[0.0, 0.0, 0.0]", "Rotations about x, then y, then z (right-handed), after scaling."},
                {"translate", K::Vector, "m", "[0.0, 0.0, 0.0]", "Translation, last."}}});
  s.push_back({"solid", true, false,
               "A solid body of wall particles: an obstacle in the flow, a plate, a lid (methods wcsph, mps, isph). The particles fill the shape's outer `layers` (its inside never meets the fluid); fluid lattice points within half a spacing of the shape are cut out of the [[fluid]] blocks (a block with an obstacle in it). With `velocity` the body moves the fluid next to it (no-slip walls with viscosity) while its particles stay put: a lid or a sliding plate. The pressure and viscous force of the fluid on it are `force` probes.",
               {{"name", K::String, "", "(solid<N>)", "Name, for `force` probes."},
                choice("shape", "", "mesh: the closed or open surface of the [[mesh]] named by `mesh` (3D; lattice points on the inner side within `layers` spacings of it, normals along the shortest way to the surface); box: [min, max]; cylinder: a disc of `radius` about `centre` in 2D, in 3D a circular cylinder along `axis` through the whole domain; sphere: a ball (3D; a disc in 2D). Box particles sit on the lattice min + (k + 1/2) d; a disc's and a sphere's on rings and spherical shells at depths (k - 1/2) d, each spaced by about d, so that every wall particle is a spacing from the fluid and has the exact normal.", {"box", "cylinder", "sphere", "mesh"}, true),
                {"mesh", K::String, "", "", "shape = \"mesh\": the [[mesh]]'s name."},
                {"min", K::Vector, "m", "", "box: lower corner."},
                {"max", K::Vector, "m", "", "box: upper corner."},
                {"velocity", K::Vector, "m/s", "(at rest)", "Prescribed constant velocity of the body's surface (its particles do not move): the lid of a cavity, the moving plate of a Couette flow."},
                {"displacement", K::FieldVector, "m", "(none)", "Prescribed motion: per axis the displacement from the rest position as a formula of t and the particle's rest position x, y, z (as for [[fluid]] velocity), e.g. [\"0.02*sin(2*pi*t)\", \"0\"] for a piston wave maker; a rotation by angle a(t) about (xc, yc) is [\"(x-xc)*(cos(a)-1) - (y-yc)*sin(a)\", \"(x-xc)*sin(a) + (y-yc)*(cos(a)-1)\"]. The particles move with it at the start of every step and carry its time derivative as their velocity. Not with `velocity`."},
                {"displacement_table", K::String, "", "(none)", "Prescribed motion from a CSV (relative to the scene file): a header, then rows t, dx, dy[, dz] with increasing t; linear between rows (the row's slope is the velocity), the first row's displacement before it, the last one's after. Instead of `displacement`."},
                ranged({"layers", K::Integer, "", "(as [[wall]]: ceil(support / spacing); isph 1)", "Thickness in particle layers, inward from the surface (outward for a container)."}, 1, 16),
                {"container", K::Bool, "", "false", "The walls lie outside the shape and the fluid inside it: a round tank (a disc in 2D, a ball, a pipe: a 3D cylinder, open at its ends, through the domain along its axis), a box tank closed on every side, or a closed mesh (a vessel from CAD). Fluid lattice points outside the shape or within half a spacing of its surface are cut out of the [[fluid]] blocks, so a block may overfill it. The layers are the fluid's lattice (the first [[fluid]] block's) within `layers` spacings outside the shape, so fluid and wall partition it; normals point out of the fluid (exactly radial for round shapes). Method isph: a round container's one layer is rings at R + d/2 instead, the fluid cut a quarter spacing inside; in 3D isph takes round containers only with description = \"eulerian\" (a full pipe; with `confined`) and mesh containers not at all. A container is a body like any other: it can move (a sloshing tank, a rotating drum) and have a `force` probe. Other bodies must lie inside it."},
                positive("temperature", "K", "(adiabatic)", "wcsph with heat: the body holds this temperature (Dirichlet); without temperature and heat_flux it is adiabatic."),
                {"heat_flux", K::Float, "W/m^2", "(adiabatic)", "wcsph with heat: heat entering the fluid through the body's surface per unit area (Neumann). Not with temperature."}}});
  add_round_keys(s.back(), "cylinder, sphere: centre (3D cylinder: any point on its axis).");
  s.push_back({"elastic", true, false, "wcsph: a linear-elastic solid body (seed 002 section 2.2; docs/multiphysics.md): particles on the lattice min + (k + 1/2) d inside [min, max], in the total Lagrangian form (its sums over each particle's neighbours in the rest configuration, corrected kernel gradients, the deformation gradient, Hooke's law as St Venant-Kirchhoff), with the seed's artificial viscosity. The fluid sees it as moving wall particles and pushes on it; walls and other bodies closer than a spacing push it back (contact). Fluid lattice points inside the box are cut out. Give bulk_modulus and shear_modulus, or youngs_modulus and poisson_ratio.",
               {{"name", K::String, "", "(elastic #N)", "Name, for probes."},
                {"min", K::Vector, "m", "", "Lower corner.", true},
                {"max", K::Vector, "m", "", "Upper corner.", true},
                positive("density", "kg/m^3", "", "Rest density rho0 of the solid.", true),
                positive("bulk_modulus", "Pa", "(from youngs_modulus)", "K (seed 002 eq. 5): the Lame lambda = K - 2G/3."),
                positive("shear_modulus", "Pa", "(from youngs_modulus)", "G of Hooke's law (seed 002 eq. 7)."),
                positive("youngs_modulus", "Pa", "(none)", "E, with poisson_ratio in place of K and G: K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu))."),
                {"poisson_ratio", K::Float, "", "(none)", "nu, with youngs_modulus; in (-1, 0.5)."},
                {"velocity", K::FieldVector, "m/s", "(at rest)", "Initial velocity, per axis a number or a formula of x, y, z (as [[fluid]] velocity)."},
                {"clamp_min", K::Vector, "m", "(none)", "With clamp_max: the particles inside this box are clamped (held in place, zero velocity); their stress still follows their neighbours. The box must hold some of the body's particles (at min + (k + 1/2) spacing) and not all (exit 2). Without a clamp, a body under gravity needs something to rest on: fluid, a [[wall]], a [[solid]], a mesh or a clamped body (exit 2 otherwise)."},
                {"clamp_max", K::Vector, "m", "(none)", "Upper corner of the clamped box."}}});
  s.push_back({"fixed_pressure", true, false,
               "isph, description = \"eulerian\": the fluid particles inside the box [min, max] hold the pressure p = pressure + gradient . x (a Dirichlet value: a channel's inlet or outlet). Make it at least a support radius long along the flow, so that the particles next to it have a full support. docs/isph.md.",
               {{"min", K::Vector, "m", "", "Lower corner.", true},
                {"max", K::Vector, "m", "", "Upper corner.", true},
                {"pressure", K::Float, "Pa", "", "Pressure at x = 0 (plus gradient . x).", true},
                {"gradient", K::Vector, "Pa/m", "(zero)", "Pressure gradient across the box, so that a linear pressure drop continues into it."}}});
  s.push_back(probe_section());
  s.push_back({"metric", true, false,
               "A run's error against a reference that ships with ryushi, written under \"metrics\" in summary.json and printed at the end (src/metrics/metrics.hpp; `ryushi sweep` collects them).",
               {{"name", K::String, "", "", "Name in summary.json.", true},
                choice("type", "", "dam_break_front: the surge_front probe as Z = x/a against T = n t sqrt(g/a) (n^2 = `height_ratio`: t sqrt(2g/a) for the n^2 = 2 column) and a reference table (Martin & Moyce 1952, n^2 = 2, a = 2.25 in, by default; tools/reference/ also has their a = 1.125 in series and their square column, martin_moyce_1952_square.csv), the largest relative error for T <= t_max after one fitted time-origin shift in [0, max_shift] (NAME_shift and NAME_unshifted beside it); hydrostatic_pressure: the fluid pressure against rho0 g (surface - z) at the end, relative L2 error; poiseuille_profile: the x velocity across the column of fluid particles nearest position[0] at the end against the start-up series of Morris, Fox & Zhu (1997, eq. 21) for walls `width` apart from y = position[1] under the body force `force`, L2 over the column relative to the series' centreline speed; ritter_depth: method swe, the depth at the end against Ritter's dry-bed dam break (h0 = `depth`, the dam at x = position[0]), sum |h - h_R| / sum h_R over the particles downstream of the dam (NAME_whole over every particle, NAME_front the front's relative lag behind 2 sqrt(g h0) t beside it); rotating_square_pressure: the first sample after t = 0 of a pressure probe (default: the first one) against Colagrossi's series for a square of side `width` centred at `position` rotating at the first fluid block's angular_velocity, at the probe's place in the square's frame, |p / p_series - 1|; probe_csv: a probe against a CSV time series (time, value), RMS difference over RMS reference.",
                       {"dam_break_front", "hydrostatic_pressure", "poiseuille_profile", "ritter_depth", "rotating_square_pressure", "probe_csv"}, true),
                {"probe", K::String, "", "(dam_break_front: the first surge_front probe; rotating_square_pressure: the first pressure probe)", "The [[probe]] the metric reads (dam_break_front, probe_csv, rotating_square_pressure: the first pressure probe)."},
                {"reference", K::String, "", "(dam_break_front: tools/reference/martin_moyce_1952_n2_2.csv)", "CSV of the reference: '#' comment lines, a header line, then two numbers per line (dam_break_front: T, Z; probe_csv: time, value). Path relative to the scene file."},
                non_negative("width", "m", "(the first fluid block's width)", "dam_break_front: the column width a; rotating_square_pressure: the side; poiseuille_profile: the channel width l (required)."),
                non_negative("height_ratio", "", "(the first fluid block's height / width)", "dam_break_front: n^2, the column's height over its width a; Martin & Moyce's time is T = n t sqrt(g/a) (t sqrt(2g/a) for their n^2 = 2 column, t sqrt(g/a) for the square one)."),
                {"force", K::Float, "m/s^2", "", "poiseuille_profile: the driving body force per unit mass F (for a pressure drop dp over a length L: dp / (rho L)); required."},
                {"depth", K::Float, "m", "(the first fluid block's depth)", "ritter_depth: the depth h0 behind the dam."},
                {"position", K::Vector, "m", "(see type)", "poiseuille_profile: (x of the column, y of the wall the profile starts from; default the first fluid block's middle and 0); ritter_depth: (x of the dam, y; default the first fluid block's max); rotating_square_pressure: the centre (default the first fluid block's)."},
                {"surface", K::Float, "m", "(the top of the tallest fluid block)", "hydrostatic_pressure: the free-surface elevation."},
                ranged({"max_shift", K::Float, "", "0.3", "dam_break_front: the largest time-origin shift fitted (T units)."}, 0.0, 10.0),
                positive("t_max", "", "2.5", "dam_break_front: the error is taken over T <= t_max.")}});
  s.push_back({"plugins", false, false,
               "Plugin libraries the scene needs (docs/extending.md), loaded before its keys are checked, as "
               "`ryushi run --plugin` loads them.",
               {{"libraries", K::StringList, "", "[]",
                 "Shared libraries built against this ryushi (find_package(ryushi CONFIG), "
                 "ryushi_add_plugin), paths relative to the scene file. Their methods and systems register as "
                 "built-in ones do; a missing file, a library that is not a ryushi plugin or was built against "
                 "another version, or a name already registered is exit 2 naming the library."}}});
  s.push_back({"systems", true, false,
               "Registered systems added to the method's pipeline; the scheduler places them by their declared access. Keys besides `name` are the system's parameters (see below).",
               {{"name", K::String, "", "", "Registered system name.", true}}});
  return s;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    prev.swap(cur);
  }
  return prev[b.size()];
}

}  // namespace

const std::vector<SectionSpec>& scene_schema() {
  // Rebuilt when a method or system registers (a plugin): [method] name lists the methods.
  static std::vector<SectionSpec> schema;
  static unsigned long built_for = ~0UL;
  if (built_for != registered_keys_generation()) {
    schema = build();
    built_for = registered_keys_generation();
  }
  return schema;
}

const SectionSpec* find_section(const std::string& name) {
  for (auto& s : scene_schema())
    if (s.name == name) return &s;
  return nullptr;
}

const KeySpec* find_key(const std::vector<KeySpec>& keys, const std::string& key) {
  for (auto& k : keys)
    if (k.key == key) return &k;
  return nullptr;
}

std::string type_name(KeyType t) {
  switch (t) {
    case KeyType::Integer: return "integer";
    case KeyType::Float: return "number";
    case KeyType::Bool: return "boolean";
    case KeyType::String: return "string";
    case KeyType::Vector: return "array of numbers (one per axis)";
    case KeyType::BoolVector: return "array of booleans (one per axis)";
    case KeyType::StringList: return "array of strings";
    case KeyType::FieldVector: return "array of numbers or expressions (one per axis)";
    case KeyType::FieldValue: return "number or expression";
  }
  return "?";
}

std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = word.size() / 2 + 2;  // beyond this a suggestion is noise
  for (auto& c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

}  // namespace ryushi
