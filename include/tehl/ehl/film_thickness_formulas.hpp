// Published fits for the central and minimum film thickness of an isothermal EHL line
// contact (VALIDATION.md section 3). Used for initial guesses and validation reports; the
// solver is never tuned toward them.
//
// Domain: Hamrock's U = eta0 um/(E' R), W = w/(E' R) and R finite and > 0, G = alpha E' >= 0
// (tehl/units.hpp, LineContactGroups); Moes' M > 0, L >= 0. The fits are plain formulas and do
// not check it: outside it (a contact at rest, no load) they return 0, inf or NaN.
#pragma once

namespace tehl {

// Moes / Venner-Lubrecht central film H_M = (h_c/R)(2U)^-1/2 from M and L.
double MoesCentralFilm(double M, double L);
// Dimensional Moes central film [m] for Hamrock U, G, W and R [m].
double MoesCentralFilmM(double U, double G, double W, double reduced_radius_m);
// Pan & Hamrock 1989: H_c = 2.922 W^-0.166 U^0.692 G^0.470, H_min = 1.714 W^-0.128 U^0.694
// G^0.568; returned dimensional [m].
double PanHamrockCentralFilmM(double U, double G, double W, double reduced_radius_m);
double PanHamrockMinimumFilmM(double U, double G, double W, double reduced_radius_m);
// Martin (1916) rigid-isoviscous load w = 4.896 eta0 um R / h0: the h0 [m] for a load.
double MartinRigidFilmM(double eta0_pa_s, double um_m_s, double reduced_radius_m,
                        double load_n_per_m);

// The central film a solve starts from, before anything is solved [m]: Martin's for a rigid
// isoviscous film (elastic = false, alpha = 0), otherwise Moes' with the inlet viscosity eta0
// and the pressure-viscosity coefficient alpha (0 for an isoviscous film).
double EstimatedCentralFilmM(double eta0_pa_s,
                             double alpha_per_pa,
                             double um_m_s,
                             double load_n_per_m,
                             double reduced_radius_m,
                             double e_prime_pa,
                             bool elastic);

}  // namespace tehl
