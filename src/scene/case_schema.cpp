#include "tehl/scene/case_schema.hpp"

#include "base/schema.hpp"
#include "drive/motor_schema.hpp"
#include "scene/automatic_grid.hpp"

namespace tehl {
namespace {
using namespace internal;

SectionSpec GearSection() {
  return {
      "gear",
      "the spur gear pair (omit for a plain [contact] case)",
      false,
      {
          Required(Positive("module_m", "m", "", "module m (transverse for spur gears)"), "0.002"),
          Required(Positive("face_width_m", "m", "", "face width b"), "0.025"),
          Real("pressure_angle_deg", "deg", "20.0", "standard pressure angle (drive flank)", 5.0,
               45.0),
          Real("coast_pressure_angle_deg", "deg", "",
               "coast-flank pressure angle; absent = symmetric", 5.0, 45.0),
          Real("helix_angle_deg", "deg", "0.0",
               "helix angle, for contact ratios only (the film model is spur)", 0.0, 45.0, true,
               false),
          Positive("center_distance_m", "m", "",
                   "working centre distance; absent = from the shifts"),
          Flag("internal", "false", "true for an internal pair (the wheel is a ring gear)"),
          Real("addendum_coefficient", "-", "1.0", "basic rack addendum h_aP / m", 0.5, 1.5),
          Real("dedendum_coefficient", "-", "1.25", "basic rack dedendum h_fP / m", 0.8, 1.8),
          Real("root_fillet_coefficient", "-", "0.38", "basic rack root radius rho_fP / m", 0.0,
               0.6),
          Flag("allow_undercut", "false", "accept undercut teeth instead of rejecting them"),
          Text("mesh_stiffness", "\"potential_energy\"", "mesh stiffness method",
               {"potential_energy", "kuang_yang", "iso"}),
          Text("load_sharing", "\"stiffness\"",
               "how the load is split between tooth pairs (loaded: stiffness, with the corner "
               "contact of loaded teeth beyond A and E)",
               {"stiffness", "linear", "loaded"}),
          Text("tip_relief_shape", "\"linear\"",
               "shape of the tip reliefs of [gear.pinion] and [gear.wheel] along the line of "
               "action (ISO 21771), unless a gear gives its own",
               {"linear", "parabolic"}),
      }};
}

SectionSpec GearMember(const std::string& name, const std::string& what, const char* z) {
  return {
      "gear." + name,
      what,
      false,
      {
          Required(Integer("teeth", "-", "", "number of teeth", 3.0, 10000.0), z),
          Real("profile_shift", "-", "0.0", "profile shift coefficient x", -1.5, 1.5),
          Positive("tip_radius_m", "m", "", "tip radius; absent = from module, addendum and shift"),
          Modulus("youngs_modulus_pa", "206e9", "Young's modulus E (default: steel)"),
          Real("poisson_ratio", "-", "0.3", "Poisson's ratio nu", 0.0, 0.5, true, false),
          SolidDensity("density_kg_m3", "7850.0", "density, for surface temperatures"),
          SolidConductivity("conductivity_w_mk", "46.0", "thermal conductivity"),
          SolidHeatCapacity("heat_capacity_j_kgk", "470.0", "specific heat capacity"),
          Real("tip_relief_m", "m", "0.0", "tip relief amount C_a at this gear's tip (0 = none)",
               0.0, 1e-3),
          Positive("tip_relief_length_m", "m", "",
                   "length of the tip relief along the line of action, from the end of the path "
                   "this tip touches (needed with tip_relief_m > 0)"),
          Text("tip_relief_shape", "",
               "shape of this gear's tip relief; absent = [gear] tip_relief_shape",
               {"linear", "parabolic"}),
      }};
}

SectionSpec OperatingSection() {
  return {"operating", "load and speed of a gear pair (exactly one speed and one load key)",
          false, {
    Positive("pinion_speed_rpm", "rpm", "", "pinion speed"),
    Positive("pinion_speed_rad_s", "rad/s", "", "pinion speed (alternative to _rpm)"),
    Positive("power_w", "W", "", "transmitted power"),
    Positive("pinion_torque_nm", "N m", "", "pinion torque (alternative to power_w)"),
  }};
}

SectionSpec ContactSection() {
  return {
      "contact",
      "a plain line contact of two discs or rollers (instead of [gear])",
      false,
      {
          Required(Real("radius_1_m", "m", "", "radius of body 1", 1e-6, 100.0), "0.02"),
          Real("radius_2_m", "m", "", "radius of body 2; absent = a flat plane", 1e-6, 100.0),
          Required(Real("speed_1_m_s", "m/s", "", "surface speed of body 1", -100.0, 100.0), "1.0"),
          Required(Real("speed_2_m_s", "m/s", "", "surface speed of body 2", -100.0, 100.0), "1.0"),
          Required(Positive("load_n_per_m", "N/m", "", "load per unit face width w"), "1e5"),
          Modulus("youngs_modulus_1_pa", "206e9", "Young's modulus of body 1"),
          Real("poisson_ratio_1", "-", "0.3", "Poisson's ratio of body 1", 0.0, 0.5, true, false),
          Modulus("youngs_modulus_2_pa", "206e9", "Young's modulus of body 2"),
          Real("poisson_ratio_2", "-", "0.3", "Poisson's ratio of body 2", 0.0, 0.5, true, false),
          SolidDensity("density_1_kg_m3", "7850.0", "density of body 1"),
          SolidDensity("density_2_kg_m3", "7850.0", "density of body 2"),
          SolidConductivity("conductivity_1_w_mk", "46.0", "thermal conductivity of body 1"),
          SolidConductivity("conductivity_2_w_mk", "46.0", "thermal conductivity of body 2"),
          SolidHeatCapacity("heat_capacity_1_j_kgk", "470.0", "heat capacity of body 1"),
          SolidHeatCapacity("heat_capacity_2_j_kgk", "470.0", "heat capacity of body 2"),
          Reals("time_s", "s", "", "times of the load/speed tables (transient runs)", 0.0),
          Reals("load_table_n_per_m", "N/m", "", "load at each time_s", 0.0),
          Reals("speed_1_table_m_s", "m/s", "", "speed of body 1 at each time_s", -100.0, 100.0),
          Reals("speed_2_table_m_s", "m/s", "", "speed of body 2 at each time_s", -100.0, 100.0),
          Integer("steps", "-", "0", "time steps over the tables; 0 = steady solve only", 0.0, 1e7),
      }};
}

SectionSpec LubricantSection() {
  return {"lubricant", "the oil", true, {
    Required(Text("name", "", "a file in lubricants/ without .toml (sae40, sae90, "
                  "reference_z068) or a path to a lubricant file"), "\"sae40\""),
    Temperature("inlet_temperature_k", "", "inlet (bulk) temperature T0; absent = the "
                "lubricant file's reference temperature"),
  }};
}

SectionSpec SurfaceSection(const std::string& name, const std::string& what) {
  return {
      "surfaces." + name,
      what,
      false,
      {
          Text("roughness", "\"smooth\"", "surface form", {"smooth", "sinusoidal", "profile"}),
          Real("amplitude_m", "m", "0.0", "amplitude of sinusoidal waviness", 0.0, 1e-4),
          Positive("wavelength_m", "m", "", "wavelength of sinusoidal waviness"),
          Real("phase_rad", "rad", "0.0", "phase of the waviness at t = 0", -100.0, 100.0),
          Text("profile_file", "\"\"", "two-column file (x [m], height [m]) of a measured profile"),
      }};
}

SectionSpec EffectsSection() {
  return {
      "effects",
      "which physics a run includes; an effect that is off costs nothing",
      false,
      {
          Flag("elastic", "true", "elastic deflection of the surfaces (DC-FFT)"),
          Flag("piezoviscous", "true", "viscosity rises with pressure"),
          Flag("compressible", "true", "density follows Dowson-Higginson"),
          Flag("transient", "true", "squeeze term d(rho h)/dt between steps"),
          Flag("thermal", "false", "energy equation across the film and surface temperatures"),
          Flag("roughness", "false", "moving surface roughness of [surfaces]"),
          Flag("dynamic_load", "false", "tooth load from the torsional dynamics"),
          Flag("non_newtonian", "false", "Ree-Eyring shear thinning (parameters in the lubricant)"),
          Flag("finite_peclet", "false",
               "surface temperatures with heat conducted along the solids (Jaeger's moving line "
               "source at any Peclet number; needs thermal)"),
      }};
}

SectionSpec NumericsSection() {
  return {
      "numerics",
      "grid, time stepping and solver settings",
      false,
      {
          Integer("grid_points", "-", "0",
                  "nodes across the contact; 0 = automatic: from 513 up to what the narrowest "
                  "Hertzian edge of the run needs (docs/case_format.md)",
                  0.0, kMaxGridPoints),
          Real("x_start_b", "-", "-4.5",
               "inlet end of the grid in Hertz half-widths b (rigid and light, nearly "
               "isoviscous films: longer units, docs/case_format.md)",
               -100.0, -1.0),
          Real("x_end_b", "-", "1.5", "outlet end of the grid in the same units", 1.0, 50.0),
          Integer("steps", "-", "0", "time steps from A to E; 0 = automatic", 0.0, 1e7),
          Integer("upwind_order", "-", "2", "order of the Couette (wedge) term upwinding", 1.0,
                  2.0),
          Text("time_scheme", "\"bdf2\"", "time discretization of d(rho h)/dt", {"bdf1", "bdf2"}),
          Real("time_tolerance", "-", "0",
               "largest estimated local time error of rho h per substep, relative (thermal runs: "
               "and of the film temperature, relative to its rise); > 0: each step is taken in "
               "substeps sized by it (docs/theory.md), at least 1e-7; 0 = one piece, substeps "
               "only where a step does not converge",
               0.0, 1.0),
          Text("linear_solver", "\"auto\"", "Newton linear solver",
               {"auto", "dense", "newton_krylov", "reused_lu"}),
          Real("newton_tolerance", "-", "1e-8",
               "relative residual at which Newton stops (below 1e-14 rounding decides)", 1e-14, 1.0,
               true, false),
          Integer("max_newton_iterations", "-", "100", "Newton iterations per solve", 1.0, 10000.0),
          Integer("film_nodes", "-", "11", "nodes across the film for the energy equation", 3.0,
                  201.0),
          Text(
              "failed_step", "\"steady_restart\"",
              "a time step that does not converge: stop the run there, or solve the steady film at "
              "its time and march on from it (the step is flagged in the results); "
              "steady_restart_or_skip: where the steady film fails too, leave that step failed "
              "and march on from the last converged film",
              {"stop", "steady_restart", "steady_restart_or_skip"}),
      }};
}

SectionSpec OutputSection() {
  return {"output", "what a run writes", false, {
    Text("directory", "\"results\"", "folder for result files (created if missing)"),
    Text("name", "\"\"", "base name of the result files; empty = the case file's name"),
    Flag("profiles", "true", "write p and h (and T) over step x position"),
    Flag("temperature_field", "false", "write the full T(x, z) at every step (large)"),
    Flag("csv", "true", "write a CSV of the cycle table beside the HDF5 file"),
  }};
}

SectionSpec DynamicsSection() {
  return {
      "dynamics",
      "torsional dynamics of a gear pair (tehl dynamics; [effects] dynamic_load)",
      false,
      {
          Real("damping_ratio", "-", "0.05",
               "mesh damping ratio zeta, c = 2 zeta sqrt(k_mean m_e) (seed 000: 0.03 to 0.17; "
               "an undamped mesh has no periodic response to solve for)",
               0.0, 1.0, false, false),
          Real("backlash_m", "m", "",
               "backlash along the line of action; absent = from the centre distance", 0.0),
          Flag("corner_contact", "true",
               "loaded pairs mesh beyond A and E where the approach closes the corner's separation "
               "(false: the stiffness steps there, seed 000)"),
          Text("friction", "\"buckingham\"", "tooth friction law (buckingham: seed 000 eq. 4.10)",
               {"none", "constant", "buckingham"}),
          Real("friction_coefficient", "-", "0.05",
               "friction coefficient of friction = \"constant\"", 0.0, 1.0, true, false),
          Positive("pinion_inertia_kg_m2", "kg m^2", "",
                   "pinion polar moment of inertia; absent = solid disc of the pitch diameter"),
          Positive("wheel_inertia_kg_m2", "kg m^2", "",
                   "wheel polar moment of inertia; absent = solid disc of the pitch diameter"),
          Real("relative_tolerance", "-", "1e-8", "relative error tolerance of the integrator", 0.0,
               1e-3, false, true),
          Real("periodic_tolerance", "-", "1e-6",
               "periodic when the state repeats after a mesh period to this (relative)", 0.0, 1.0,
               false, false),
          Integer("max_periods", "-", "5000", "mesh periods integrated at most", 2.0, 1e7),
          Integer("output_samples", "-", "400", "samples of the periodic response per mesh period",
                  8.0, 1e6),
      }};
}

SectionSpec MotorSection() {
  return {"motor", "a DC motor driving the pinion (seed 001 section 3; docs/trains.md): the "
          "pinion speed is its operating point against [operating] pinion_torque_nm",
          false, CaseMotorKeys()};
}

Schema BuildCaseSchema() {
  Schema s;
  s.kind = "case";
  s.sections = {
      GearSection(),
      GearMember("pinion", "the pinion (gear 1, the driver)", "35"),
      GearMember("wheel", "the wheel (gear 2)", "105"),
      OperatingSection(),
      ContactSection(),
      LubricantSection(),
      SectionSpec{"surfaces", "surface roughness of the two bodies", false, {}},
      SurfaceSection("surface1", "surface of body 1 (the pinion)"),
      SurfaceSection("surface2", "surface of body 2 (the wheel)"),
      EffectsSection(),
      NumericsSection(),
      OutputSection(),
      DynamicsSection(),
      MotorSection(),
  };
  return s;
}

}  // namespace

const internal::Schema& CaseSchema() {
  static const internal::Schema schema = BuildCaseSchema();
  return schema;
}

std::string CaseDefaultsText() { return CaseSchema().PrintDefaults(); }

}  // namespace tehl
