// How much film a truncated inlet costs: an estimate from one solved film.
//
// The grid starts at x0 (x_start_b Hertz half-widths upstream) with p(x0) = 0. On an unbounded
// inlet the pressure there would already be p_in > 0: far upstream the film is thick, the
// lubricant is at its inlet state and Reynolds gives dp/dx = 12 eta0 um (h - h*)/h^3 with
// h* = q/(rho um) the film of the (constant) mass flow, so
//   p_in = int_{-inf}^{x0} 12 eta0 um (h - h*)/h^3 dx,
// with h continued upstream of x0 by the dry Hertz separation of the film's own contact (or
// the rigid parabola x^2/2R when the film is rigid). Grubin's inlet argument (Grubin 1949, the
// analysis behind H = 1.95 (G U)^(8/11) W^(-1/11)) makes the film that of the reduced
// pressure the inlet must build, h ~ (1/alpha - q_r(p_in))^(-8/11)
// with q_r = (1 - exp(-alpha p))/alpha, so the truncated inlet, which builds all of 1/alpha
// from p = 0, gives
//   h_truncated / h_unbounded = exp(-(8/11) alpha p_in),
// alpha = d ln(eta)/dp at the inlet state. Measured against longer inlets (isothermal steel
// discs, SAE 40, 0.4-1.2 GPa, 0.2-5 m/s; tests/verification/inlet_truncation_disc_test.cpp,
// docs/results.md "The inlet note"): the estimate of the h_c deficit is 0.96-1.17 times the
// measured one (films with alpha p_max >= 8). p_in falls like |x0|^-3, and so does the
// deficit.
//
// Grubin's argument needs a piezoviscous film, whose pressure reaches several 1/alpha: below
// alpha p_max = kGrubinMinAlphaP there is no estimate. Such a film (light load, nearly
// isoviscous) builds its pressure far upstream, as a rigid isoviscous one (Martin) does over
// tens of sqrt(2 R h_M), h_M = 4.896 eta0 um R / w: its inlet needs
//   l_iso = min(kIsoviscousInletLengths sqrt(2 R h_M) min(1, h_M R / b^2), R / 2),
// the weight fading as elasticity takes over (h_M R / b^2 ~ 1/M^2, Moes' load parameter M);
// beyond R/2 the gap is no longer the parabola x^2/(2R) (7 % off there) and a real inlet is
// wherever the oil meets the gap, which a flooded inlet does not describe,
// and `short_isoviscous_inlet` says when the grid starts downstream of -l_iso / 2. (The automatic
// grid of case files starts there: scene/film_case.cpp.)
#pragma once

#include <Eigen/Core>

namespace tehl {

struct InletTruncationInputs {
  double x_start_m = 0;                  // x0, the first node (upstream of the contact) [m]
  double dx_m = 0;                       // node spacing [m]
  double reduced_radius_m = 0;           // R [m]
  double half_width_m = 0;               // Hertz half-width b of this film; 0 = rigid film [m]
  double um_m_s = 0;                     // entrainment speed (u1 + u2)/2 [m/s]
  double inlet_viscosity_pa_s = 0;       // eta at p = 0 and the inlet temperature [Pa s]
  double pressure_viscosity_per_pa = 0;  // alpha = d ln(eta)/dp there [1/Pa]
  double load_n_per_m = 0;               // w, for the isoviscous inlet length; 0 = unknown
                                         //   [N/m]
};

struct InletTruncation {
  bool estimated = false;          // false: no estimate (isoviscous film, x0 inside the Hertz
                                   //   zone, reverse or no entrainment, a non-finite film)
  double missing_pressure_pa = 0;  // p_in, the pressure at x0 on an unbounded inlet [Pa]
  double film_deficit = 0;         // 1 - h_truncated / h_unbounded [-]
  double alpha_p_max = 0;          // alpha p_max of the film: no estimate below
                                   //   kGrubinMinAlphaP [-]
  double isoviscous_inlet_m = 0;   // l_iso (above); 0 when unknown [m]
  bool short_isoviscous_inlet = false;  // alpha p_max < kGrubinMinAlphaP and -x0 below
                                        //   kShortIsoviscousInlet l_iso
  // A nearly rigid film (h_M R / b^2 >= 1) whose flooded inlet would reach beyond the R/2 cap
  // of l_iso: 1 - RigidInletFilmRatio(x0 / sqrt(2 R h_M)), what the inlet at x0 costs it
  // against Martin's unbounded one; 0 otherwise [-].
  double rigid_film_deficit = 0;
  // The inlet x0' (same units as x0) at which the deficit would be `target`: p_in ~ |x0|^-3.
  double InletFor(double x0, double target) const;
};

// The estimate for a film p(x), h(x) on a uniform grid (entrainment toward +x).
InletTruncation EstimateInletTruncation(const Eigen::VectorXd& p_pa,
                                        const Eigen::VectorXd& h_m,
                                        const InletTruncationInputs& in);

// The same estimate before the film is solved (to size a grid's inlet): the film taken flat
// at `central_film_m` over the Hertz zone, h* = h_c, the dry Hertz separation upstream, and
// alpha p_H in place of alpha p_max. Needs b > 0 and w > 0; dx_m is not used.
InletTruncation PredictInletTruncation(const InletTruncationInputs& in, double central_film_m);

// Martin's rigid isoviscous film with its inlet at x0 = x0_over_l l_M (< 0), l_M =
// sqrt(2 R h_M) with Martin's film h_M = 4.896 eta0 um R / w: its thickness at that load over
// h_M (the exact solution of the truncated problem, closed form up to two roots) [-]. 0.907
// at x0 = -4.7 l_M, 0.9997 at -40 l_M.
double RigidInletFilmRatio(double x0_over_l);

// Grubin's exponent of the film on alpha eta0 um (H ~ (G U)^(8/11)) [-].
constexpr double kGrubinExponent = 8.0 / 11.0;
// The smallest alpha p_max for which the estimate is given [-].
constexpr double kGrubinMinAlphaP = 5.0;
// The inlet of a rigid isoviscous film in sqrt(2 R h_M) (Martin): at -40 of them the dry gap
// is 1600 h_M [-].
constexpr double kIsoviscousInletLengths = 40.0;
// ... and at most this many R [-].
constexpr double kIsoviscousInletMaxRadii = 0.5;
// An inlet shorter than this part of l_iso is noted as short [-].
constexpr double kShortIsoviscousInlet = 0.5;

// l_iso above for a film of half-width b (0: rigid) [m]; 0 when an input is not positive.
double IsoviscousInletLength(double reduced_radius_m,
                             double half_width_m,
                             double um_m_s,
                             double inlet_viscosity_pa_s,
                             double load_n_per_m);

}  // namespace tehl
