// Potential-energy (cantilever beam) stiffness of a spur gear tooth pair, for symmetric and
// asymmetric external teeth and any pair of materials.
//
// Each tooth is a non-uniform cantilever on the gear body, loaded by the contact force F along
// the line of action of its drive flank (Yang & Lin 1987, ASME J. Mech. Trans. Autom. Des.
// 109:189-196; Tian 2004, MSc thesis, Univ. of Alberta; Chaari, Fakhfakh & Haddar 2009,
// Eur. J. Mech. A/Solids 28:461-468). With y along the tooth axis, a section at y spanning
// x in [-h_c(y), h_d(y)] (coast and drive flank), t = h_d + h_c, e = (h_d - h_c)/2,
// A = t L, I = t^3 L / 12, and the contact point (x_P, y_P) on the drive flank:
//   1/k_b = int [ (y_P - y) cos a1 - (x_P - e) sin a1 ]^2 / (E_e I) dy     (bending)
//   1/k_s = int 1.2 cos^2 a1 / (G A) dy                                   (shear)
//   1/k_a = int sin^2 a1 / (E_e A) dy                                     (axial compression)
// over y from the root circle to y_P (below its base circle a flank is taken as radial, Liang,
// Zuo & Pandey 2014, Mech. Mach. Theory 76:20-38). The classical choice of Yang & Lin and Tian,
// a beam clamped at the base circle when r_b > r_f, is Options::start_at_root_circle = false;
// it leaves the tooth between r_f and r_b rigid although the foundation term below starts at
// r_f, and makes the FZG-C pair ~40 % stiffer than ISO 6336-1 (docs/gear_stiffness.md).
// a1 is the angle between F and the normal to the tooth axis, a1 = alpha(r) - psi_d(r)
// (pressure angle at the contact minus the flank's polar angle). For symmetric teeth e = 0
// and these are the integrals of Tian (2004, ch. 2). For asymmetric teeth the loaded flank
// has its own base circle and pressure angle and the other flank bounds the section, so a
// 35 deg drive flank gives a thicker tooth base than a 20 deg one.
//
// Fillet foundation (gear body), Sainsot, Velex & Duverger (2004), ASME J. Mech. Des.
// 126:748-752:
//   1/k_f = cos^2 a1 / (E_e L) [ L* (u_f/S_f)^2 + M* (u_f/S_f) + P* (1 + Q* tan^2 a1) ]
//   X*(h_f, theta_f) = A/theta_f^2 + B h_f^2 + C h_f/theta_f + D/theta_f + E h_f + F,
// with the published coefficients (src/gear/stiffness_tooth_beam.cpp), h_f = r_f / r_int
// (ToothBlank::bore_radius_m; r_int = r_f / 2 when not given), theta_f the half angle of
// the tooth at the root circle, S_f = 2 r_f theta_f, u_f the distance from the root circle
// to where the line of action crosses the tooth axis.
//
// Hertzian contact of the pair, linearised (Yang & Sun 1985, ASME J. Mech. Trans. Autom.
// Des. 107:529-535): k_h = pi E L / (4 (1 - nu^2)) for equal materials. For two materials it
// is written with the reduced modulus of VALIDATION.md section 1, 2/E' = (1-nu1^2)/E1 +
// (1-nu2^2)/E2, as k_h = pi E' L / 4 (identical for equal materials; each body contributes
// its own half of the compliance 4/(pi E' L)).
//
// Pair: 1/k = 1/k_h + sum over both teeth (1/k_b + 1/k_s + 1/k_a + 1/k_f). L is the common
// face width min(b1, b2).
//
// Elastic constants: E_e = E in the bending, axial and foundation terms, as the cited sources
// write them (plane stress, the default); Options::plane_strain gives E_e = E / (1 - nu^2) for
// wide teeth (face width >> tooth thickness). G = E / (2 (1 + nu)) in both cases.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/gear/mesh_stiffness.hpp"

namespace tehl {

namespace internal {
class StiffnessToothBeam;
}

class PotentialEnergyStiffness : public PairStiffnessModel {
 public:
  struct Options {
    bool plane_strain = false;         // E_e = E / (1 - nu^2) (true) or E (false, as published) [-]
    bool start_at_root_circle = true;  // clamp the beam at r_f (true, Liang et al. 2014) or
                                       // at max(r_f, r_b) (false, Yang & Lin; Tian) [-]
    int quadrature_points = 24;        // Gauss-Legendre points per smooth piece of a tooth [-]
    std::vector<InputProblem> Validate() const;  // every violated rule; empty = valid
  };

  // Compliance of one tooth along its line of action [m/N].
  struct ToothCompliance {
    double bending = 0;     // 1/k_b [m/N]
    double shear = 0;       // 1/k_s [m/N]
    double axial = 0;       // 1/k_a [m/N]
    double foundation = 0;  // 1/k_f [m/N]
    double Total() const { return bending + shear + axial + foundation; }
  };

  // Throws InputError for an invalid blank or option, and (key "gear.mesh_stiffness") for a
  // ring gear or a pointed tooth.
  PotentialEnergyStiffness(const ToothBlank& pinion, const ToothBlank& wheel);
  PotentialEnergyStiffness(const ToothBlank& pinion,
                           const ToothBlank& wheel,
                           const Options& options);
  ~PotentialEnergyStiffness() override;

  // Every violated rule for one blank; which = "pinion" | "wheel". Empty = usable.
  static std::vector<InputProblem> Validate(const ToothBlank& blank, const std::string& which);

  // Contract for the radii below: LowestContactRadius(g) <= r <= tip radius (g = 1 pinion,
  // 2 wheel). Radii outside are clamped to that range (an assertion in debug builds).
  ToothCompliance PinionCompliance(double r1_m) const;
  ToothCompliance WheelCompliance(double r2_m) const;
  double LowestContactRadius(int gear) const;  // max(r_f, r_b of the drive flank) [m]

  double HertzStiffness() const { return hertz_stiffness_n_per_m_; }  // k_h [N/m]
  double PairStiffness(double r1_m, double r2_m) const override;      // [N/m]
  std::string Name() const override { return "potential_energy"; }

 private:
  std::unique_ptr<internal::StiffnessToothBeam> pinion_, wheel_;
  double hertz_stiffness_n_per_m_ = 0;
};

}  // namespace tehl
