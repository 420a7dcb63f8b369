// The Hertzian edge of an EHL film, and how many grid cells resolve it.
//
// Outside the Hertz zone of a line contact the dry gap opens as
//   g(xi) = (b^2 / 2R) [xi sqrt(xi^2 - 1) - ln(xi + sqrt(xi^2 - 1))],  xi = x / b
// (K.L. Johnson, Contact Mechanics, 1985, section 5.6), which is (2 sqrt(2) / 3) (b^2 / R)
// eps^(3/2) at xi = 1 + eps. An EHL film of central thickness h_c leaves the Hertzian shape
// where that gap reaches h_c, over a width
//   delta = b (3 R h_c / (2 sqrt(2) b^2))^(2/3)
// at the inlet, and the outlet constriction has the same scale. At high load parameters M
// this width is a small fraction of b (R h_c / b^2 = pi H_c / (8 M) in Moes' groups), and a
// grid that spans it with few cells gives a film that is too thin: on the Moes points of
// docs/validation.md section 3.1 (M = 20 ... 1000, L = 1 ... 10) the central film's deficit
// against the grid-converged one is C / N^2 with N = delta / dx from the computed film and
// C = 0.36 ... 1.09 from N = 2 on (0.09 ... 0.23 below one cell, where the film is
// unresolved). A run reports N so that a thin film from a grid that does not resolve its
// edge is not taken as converged.
#pragma once

namespace tehl {

struct HertzEdge {
  double width_m = 0;       // delta [m]; 0 when h_c or b is not positive
  double width_cells = 0;   // delta / dx [-]
  double film_deficit = 0;  // estimated relative deficit of h_c: kEdgeDeficitConstant / N^2 [-]
  bool resolved() const;    // width_cells >= kEdgeResolvedCells
};

// The largest C of the measured series (M = 20, L = 10), so the estimate bounds the deficits
// measured on all of them [-].
constexpr double kEdgeDeficitConstant = 1.1;

// The width from which the estimated deficit is about 1 % (1.1 / 10^2) [cells].
constexpr double kEdgeResolvedCells = 10.0;

// The edge of a film with central thickness h_c on a grid of spacing dx, for a contact of
// reduced radius R and Hertz half-width b (elastic films only).
HertzEdge EstimateHertzEdge(double reduced_radius_m,
                            double half_width_m,
                            double central_film_m,
                            double dx_m);

// The fewest nodes n = 2^k + 1 >= min_nodes at which a uniform grid over span_m puts at least
// kEdgeResolvedCells cells across an edge of width edge_width_m (capped at max_nodes; min_nodes
// when the width is not positive) [-].
int NodesSpanningEdge(double span_m, double edge_width_m, int min_nodes, int max_nodes);

// The dry gap of a Hertzian line contact at x = xi b, |xi| >= 1 (Johnson's formula above;
// 0 inside the contact) [m].
double HertzGap(double reduced_radius_m, double half_width_m, double xi);

}  // namespace tehl
