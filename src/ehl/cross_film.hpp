// Flow across a thin film whose viscosity and density vary across it (thermal and
// non-Newtonian runs): the cross-film integrals of the generalized Reynolds equation
// (Yang & Wen 1990, "A generalized Reynolds equation for non-Newtonian thermal
// elastohydrodynamic lubrication", J. Tribol. 112:631-636), the velocity profile and the shear
// stress (docs/theory.md, "Generalized Reynolds equation").
//
// With xi = z/h in [0, 1] (xi = 0 on surface 1 moving at u1, xi = 1 on surface 2 at u2) and
//   A(xi) = int_0^xi dxi'/eta,  B(xi) = int_0^xi xi' dxi'/eta,  I0 = A(1),  I1 = B(1),
//   rho_e = int rho dxi,  rho'_e = int rho A dxi,  rho''_e = int rho B dxi,
// the mass flow per unit width is q = F h - Phi h^3/12 dp/dx with
//   Phi = (rho/eta)_e = 12 (rho'_e I1/I0 - rho''_e),   F = rho*u_e = rho'_e (u2 - u1)/I0 + rho_e u1,
// the velocity u(xi) = u1 + (u2 - u1) A/I0 + h^2 dp/dx (B - A I1/I0) and the shear stress
// tau(xi) = eta du/dz = (u2 - u1)/(h I0) + h dp/dx (xi - I1/I0), linear in xi as the momentum
// balance d tau/dz = dp/dx requires. With uniform eta and rho: Phi = rho/eta and
// F = rho (u1 + u2)/2, the classical Reynolds equation. The fluidity 1/eta and rho are taken
// piecewise linear between nz uniform nodes; A and B are integrated exactly for that
// interpolant and the outer integrals by Simpson's rule per cell (exact for rho A; for rho B
// exact when rho is uniform), so the classical limit is reproduced to rounding and the
// coefficients converge at fourth order in nz.
#pragma once

namespace tehl::internal {

// Per-node coefficients of the generalized Reynolds equation and their derivative with
// respect to the node's pressure (eta_j and rho_j depend on p through the laws).
struct CrossFilmCoefficients {
  double phi = 0, dphi_dp = 0;        // (rho/eta)_e [kg/(m^3 Pa s)] and d/dp
  double flux = 0, dflux_dp = 0;      // F = rho* u_e [kg/(m^2 s)] and d/dp
  double rho_e = 0, drho_e_dp = 0;    // mean density [kg/m^3] and d/dp
  double i0 = 0, i1 = 0;              // I0, I1 [1/(Pa s)]
};

// eta[j], rho[j] at xi_j = j/(nz-1) and their pressure derivatives (deta, drho may be null
// when only values are needed). nz >= 2.
CrossFilmCoefficients CrossFilmIntegrals(const double* eta, const double* deta,
                                         const double* rho, const double* drho, int nz,
                                         double u1_m_s, double u2_m_s);

// Velocity u(xi_j) [m/s] and shear stress tau(xi_j) [Pa] at one node, from the same
// quadrature (u and tau of size nz).
void CrossFilmProfile(const double* eta, int nz, double h_m, double dpdx_pa_m, double u1_m_s,
                      double u2_m_s, double* u, double* tau);

}  // namespace tehl::internal
