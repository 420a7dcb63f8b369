#include "tehl/ehl/film_thickness_formulas.hpp"

#include <cmath>

#include "tehl/units.hpp"

namespace tehl {

double MoesCentralFilm(double M, double L) {
  // VALIDATION.md section 3 (Moes 1992; Venner & Lubrecht 2000).
  const double h_ri = 3.0 * std::pow(M, -1.0);
  const double h_ei = 2.621 * std::pow(M, -0.2);
  const double h_rp = 1.287 * std::pow(L, 2.0 / 3.0);
  const double h_ep = 1.311 * std::pow(M, -0.125) * std::pow(L, 0.75);
  const double s = 1.5 * (1.0 + std::exp(-1.2 * h_ei / h_ri));
  const double a = std::pow(std::pow(h_ri, 7.0 / 3.0) + std::pow(h_ei, 7.0 / 3.0), 3.0 * s / 7.0);
  const double b = std::pow(std::pow(h_rp, -3.5) + std::pow(h_ep, -3.5), -2.0 * s / 7.0);
  return std::pow(a + b, 1.0 / s);
}

double MoesCentralFilmM(double U, double G, double W, double r) {
  const double M = W * std::pow(2.0 * U, -0.5);
  const double L = G * std::pow(2.0 * U, 0.25);
  return MoesCentralFilm(M, L) * r * std::sqrt(2.0 * U);
}

double PanHamrockCentralFilmM(double U, double G, double W, double r) {
  return 2.922 * std::pow(W, -0.166) * std::pow(U, 0.692) * std::pow(G, 0.470) * r;
}

double PanHamrockMinimumFilmM(double U, double G, double W, double r) {
  return 1.714 * std::pow(W, -0.128) * std::pow(U, 0.694) * std::pow(G, 0.568) * r;
}

double MartinRigidFilmM(double eta0, double um, double r, double w) {
  return 4.896 * eta0 * um * r / w;
}

double EstimatedCentralFilmM(
    double eta0, double alpha, double um, double w, double r, double e_prime, bool elastic) {
  if (!elastic && alpha == 0.0) return MartinRigidFilmM(eta0, um, r, w);
  const DimensionlessGroups g = LineContactGroups(eta0, alpha, um, w, r, e_prime);
  return MoesCentralFilmM(g.U, g.G, g.W, r);
}

}  // namespace tehl
