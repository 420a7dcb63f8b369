// The pressure spike near the outlet of an EHL film, and how many grid cells resolve it.
//
// The spike's height converges slowly with the grid (docs/accuracy.md): on the 0.8 GPa steel
// disc of docs/thermal.md ("Open points") the isothermal spike is 23 % below its 32769-node
// height when it spans 2.6 cells at half its prominence (513 nodes), 6 % at 10.6 cells and
// 1 % at 34 cells. A run reports the width so that a p_max (and a thermal T_max, which sits
// on the spike in rolling) from a grid that does not resolve it is not taken as converged.
#pragma once

#include <Eigen/Core>

namespace tehl {

struct OutletSpike {
  bool found = false;        // a local maximum near the outlet with a dip upstream of it
  int node = -1;             // grid index of the peak [-]
  double x_m = 0;            // position of the peak [m]
  double pressure_pa = 0;    // peak pressure [Pa]
  double prominence_pa = 0;  // peak minus the lowest pressure between it and the hump [Pa]
  double width_cells = 0;    // width at half the prominence, in grid cells [-]
  bool resolved() const;     // width_cells >= kSpikeResolvedCells (or no spike)
};

// The width at half prominence from which the spike's height is within about 2 % of its
// converged value (measured: 2.6 % low at 18 cells, 1 % at 34; header comment) [cells].
constexpr double kSpikeResolvedCells = 20.0;

// The outlet-most local maximum of p (entrainment toward +x: the outlet is the last node
// with p > 1e-6 max p, above the round-off a linear solve leaves on cavitated nodes), if a dip
// separates it from the pressure upstream and its prominence is at least min_relative_prominence of
// max p. Width by linear interpolation of the half level.
OutletSpike FindOutletSpike(const Eigen::VectorXd& p_pa,
                            double x_start_m,
                            double dx_m,
                            double min_relative_prominence = 0.02);

}  // namespace tehl
