#include "ehl/cross_film.hpp"

#include <vector>

namespace tehl::internal {
namespace {

// A value and its derivative with respect to the node pressure.
struct Dual {
  double v = 0, d = 0;
};
Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.d + b.d}; }
Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.d - b.d}; }
Dual operator*(double s, Dual a) { return {s * a.v, s * a.d}; }
Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }

// The running integrals over one cell [xi0, xi0 + delta] with the fluidity a = 1/eta and rho
// linear in the cell: the increments of A and B to the cell's middle and end (exact for the
// linear interpolant; A is quadratic and B cubic in the cell).
struct CellIntegrals {
  Dual a_mid, a_end, b_mid, b_end;
};
CellIntegrals Cell(double xi0, double delta, Dual a0, Dual a1) {
  const Dual da = a1 - a0;
  CellIntegrals c;
  c.a_mid = delta * (0.5 * a0 + 0.125 * da);
  c.a_end = delta * (0.5 * (a0 + a1));
  // int_0^t delta (xi0 + delta s)(a0 + da s) ds at t = 1/2 and t = 1.
  c.b_mid = delta * (0.5 * xi0 * a0 + 0.125 * (xi0 * da + delta * a0) + (delta / 24.0) * da);
  c.b_end = delta * (xi0 * a0 + 0.5 * (xi0 * da + delta * a0) + (delta / 3.0) * da);
  return c;
}

}  // namespace

CrossFilmCoefficients CrossFilmIntegrals(const double* eta, const double* deta,
                                         const double* rho, const double* drho, int nz,
                                         double u1, double u2) {
  // Piecewise-linear fluidity and density across the film; each cell's outer integrals by
  // Simpson's rule, exact for rho A (cubic) and for rho B when rho is constant in the cell.
  const double delta = 1.0 / (nz - 1);
  auto fluidity = [&](int j) {
    const double inv = 1.0 / eta[j];
    return Dual{inv, deta ? -deta[j] * inv * inv : 0.0};
  };
  auto density = [&](int j) { return Dual{rho[j], drho ? drho[j] : 0.0}; };
  Dual A, B, rho_e, rho1, rho2;
  Dual a0 = fluidity(0), r0 = density(0);
  for (int j = 0; j + 1 < nz; ++j) {
    const Dual a1 = fluidity(j + 1), r1 = density(j + 1);
    const CellIntegrals c = Cell(j * delta, delta, a0, a1);
    const Dual rm = 0.5 * (r0 + r1);
    const Dual am = A + c.a_mid, ae = A + c.a_end, bm = B + c.b_mid, be = B + c.b_end;
    const double w = delta / 6.0;
    rho_e = rho_e + w * (r0 + 4.0 * rm + r1);
    rho1 = rho1 + w * (r0 * A + 4.0 * (rm * am) + r1 * ae);
    rho2 = rho2 + w * (r0 * B + 4.0 * (rm * bm) + r1 * be);
    A = ae;
    B = be;
    a0 = a1;
    r0 = r1;
  }
  CrossFilmCoefficients c;
  c.i0 = A.v;
  c.i1 = B.v;
  // Phi = 12 (rho1 I1/I0 - rho2); F = rho1 (u2 - u1)/I0 + rho_e u1. The quotients'
  // derivatives are formed without I0^2, which underflows to 0 where the film is very viscous
  // (I0 ~ 1/eta below 1e-162: a 0/0 in the Jacobian, measured at a cold, highly loaded node of
  // a sliding thermal disc).
  const double ratio = B.v / A.v;
  const double dratio = (B.d - ratio * A.d) / A.v;
  c.phi = 12.0 * (rho1.v * ratio - rho2.v);
  c.dphi_dp = 12.0 * (rho1.d * ratio + rho1.v * dratio - rho2.d);
  const double du = u2 - u1;
  c.flux = rho1.v * du / A.v + rho_e.v * u1;
  c.dflux_dp = du * (rho1.d - (rho1.v / A.v) * A.d) / A.v + rho_e.d * u1;
  c.rho_e = rho_e.v;
  c.drho_e_dp = rho_e.d;
  return c;
}

void CrossFilmProfile(const double* eta, int nz, double h, double dpdx, double u1, double u2,
                      double* u, double* tau) {
  const double delta = 1.0 / (nz - 1);
  std::vector<double> A(nz, 0.0), B(nz, 0.0);
  for (int j = 1; j < nz; ++j) {
    const CellIntegrals c =
        Cell((j - 1) * delta, delta, Dual{1.0 / eta[j - 1], 0.0}, Dual{1.0 / eta[j], 0.0});
    A[j] = A[j - 1] + c.a_end.v;
    B[j] = B[j - 1] + c.b_end.v;
  }
  const double i0 = A[nz - 1], ratio = B[nz - 1] / i0;
  for (int j = 0; j < nz; ++j) {
    u[j] = u1 + (u2 - u1) * A[j] / i0 + h * h * dpdx * (B[j] - A[j] * ratio);
    tau[j] = (u2 - u1) / (h * i0) + h * dpdx * (j * delta - ratio);
  }
}

}  // namespace tehl::internal
