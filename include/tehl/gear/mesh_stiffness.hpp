// Mesh stiffness of spur gear tooth pairs: the common description of one gear blank, the
// interface of a single-pair stiffness method, the factory, and ISO 6336-1 method B.
//
// Methods (docs/gear_stiffness.md compares them):
//  - "kuang_yang": empirical fit of Kuang & Yang (1992), seed 000 eqs 4.3-4.8
//    (include/tehl/gear/kuang_yang_stiffness.hpp).
//  - "potential_energy": Hertz + bending + shear + axial compression energies with the fillet
//    foundation correction of Sainsot, Velex & Duverger (2004)
//    (include/tehl/gear/potential_energy_stiffness.hpp).
//  - IsoMethodB(): ISO 6336-1:2006 method B, c' and c_gamma_alpha (VALIDATION.md section 5).
#pragma once

#include <memory>
#include <string>

namespace tehl {

// What a stiffness method needs of one gear.
struct ToothBlank {
  int teeth = 0;                          // z [-]; for a ring gear the (positive) tooth count
  double module_m = 0;                    // m [m]
  double drive_pressure_angle_rad = 0;    // pressure angle of the loaded (drive) flank [rad]
  double coast_pressure_angle_rad = 0;    // of the other flank; = drive for symmetric teeth [rad]
  double profile_shift = 0;               // x [-]
  double addendum_coefficient = 1.0;      // h_aP/m [-]
  double dedendum_coefficient = 1.25;     // h_fP/m [-]
  double root_fillet_coefficient = 0.38;  // rho_fP/m [-]
  double tip_radius_m = 0;                // r_a [m]
  double face_width_m = 0;                // b [m]
  double youngs_modulus_pa = 0;           // E [Pa]
  double poisson_ratio = 0;               // nu [-]
  bool internal = false;                  // ring gear
  // Radius where the gear body is held (bore or shaft seat), r_int [m]. Used only by the
  // fillet-foundation term of "potential_energy" (Sainsot et al. 2004, h_f = r_f / r_int).
  // 0 = not given: r_int = r_f / 2 is taken (a solid disc on a shaft of half the root
  // diameter; docs/gear_stiffness.md shows the sensitivity).
  double bore_radius_m = 0;
};

// Stiffness of one pair of teeth in contact. Pure and thread-safe.
class PairStiffnessModel {
 public:
  virtual ~PairStiffnessModel() = default;
  // Stiffness of ONE tooth pair in contact [N/m] (force along the line of action per unit
  // approach), contact at radius r1 on the pinion and r2 on the wheel.
  virtual double PairStiffness(double r1_m, double r2_m) const = 0;
  virtual std::string Name() const = 0;
};

// method: "potential_energy" | "kuang_yang". Throws InputError (include/tehl/error.hpp) with
// key "gear.mesh_stiffness" for an unknown method, or when a blank lies outside the method's
// validity range.
std::unique_ptr<PairStiffnessModel> MakePairStiffnessModel(const std::string& method,
                                                           const ToothBlank& pinion,
                                                           const ToothBlank& wheel);

// ISO 6336-1:2006 method B (VALIDATION.md section 5). Units as in the standard.
struct IsoStiffness {
  double c_prime_n_per_mm_um = 0;        // single stiffness c' = c'_th C_M C_R C_B cos(beta)
                                         // (E/E_st) [N/(mm um)]
  double c_gamma_alpha_n_per_mm_um = 0;  // mesh stiffness c' (0.75 eps_alpha + 0.25) [N/(mm um)]
  double c_prime_th_n_per_mm_um = 0;     // theoretical single stiffness 1/q' [N/(mm um)]
  double q_prime_mm_um_per_n = 0;        // minimum flexibility q' [mm um / N]
};

// Formulas and sources in src/gear/iso_stiffness.cpp. Uses of each blank: teeth,
// profile_shift, dedendum_coefficient and drive_pressure_angle_rad (C_B from the basic rack),
// youngs_modulus_pa (material factor E/E_st, 1 for steel/steel), internal (an internal wheel
// has zn2 = infinity). eps_alpha: transverse contact ratio [-]; helix_angle_rad: beta [rad]
// (0 for spur gears). Throws InputError (key "gear.mesh_stiffness" for range problems) for
// an invalid blank, eps_alpha < 1, or x1 + x2 outside [-0.5, 2.0] of an external pair.
IsoStiffness IsoMethodB(const ToothBlank& pinion,
                        const ToothBlank& wheel,
                        double eps_alpha,
                        double helix_angle_rad = 0);

}  // namespace tehl
