// The solids' heat history of a transient energy step (docs/theory.md, "The solids' heat
// history"): the earlier levels' part of the moving-heat-source integral, and the levels a
// solved step hands on. Private to the film energy solver (src/ehl/film_energy.cpp).
#pragma once

#include <Eigen/Core>
#include <limits>

#include "tehl/ehl/film_energy.hpp"

namespace tehl::internal {

// What a step from `previous` needs: the lags its own flux covers and the known rest.
struct StepHistory {
  bool active = false;  // false: quasi-steady (whole kernel, no history term)
  double reach1_m = std::numeric_limits<double>::infinity();  // u1 dt [m]
  double reach2_m = std::numeric_limits<double>::infinity();  // u2 dt [m]
  Eigen::VectorXd history1, history2;                         // H_i of solids 1, 2 [W/m^2 m^(1/2)]
};

// The history of a step over the travels reach1_m = u1 dt, reach2_m = u2 dt (> 0) from the
// level `previous` (its fluxes, travels and earlier levels; n values each). Inactive when
// both reaches cover the grid (x_(n-1) - x_0): the step's own flux is then all a surface
// point saw.
StepHistory HistoryOfStep(const UniformGrid& grid,
                          const FilmTemperature& previous,
                          double reach1_m,
                          double reach2_m);

// Sets the travels and earlier levels of t, the level a step from `previous` solved: the
// previous level, then its earlier ones, as far back as a surface point on the grid can
// remember (lags below x_(n-1) - x_0); at most kMaxSolidFluxLevels, the oldest two merged
// (travel-weighted mean flux) beyond that.
void RememberLevels(const UniformGrid& grid,
                    const FilmTemperature& previous,
                    double reach1_m,
                    double reach2_m,
                    FilmTemperature* t);

// A steady level: infinite travels, no earlier levels.
void ForgetLevels(FilmTemperature* t);

}  // namespace tehl::internal
