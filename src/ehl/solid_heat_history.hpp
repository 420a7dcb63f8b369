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

// The history of a step of dt_s (> 0) at the surface speeds u1_m_s, u2_m_s (> 0) from the
// level `previous` (its fluxes, travels, speeds and earlier levels; n values each). Inactive
// when both reaches u dt cover the grid (x_(n-1) - x_0): the step's own flux is then all a
// surface point saw.
StepHistory HistoryOfStep(const UniformGrid& grid,
                          const FilmTemperature& previous,
                          double dt_s,
                          double u1_m_s,
                          double u2_m_s);

// Sets the travels, speeds and earlier levels of t, the level a step of dt_s at the speeds
// u1_m_s, u2_m_s from `previous` solved: the
// previous level, then its earlier ones, as far back as a surface point on the grid can
// remember (lags below x_(n-1) - x_0); at most kMaxSolidFluxLevels, the oldest two merged
// (travel-weighted mean flux) beyond that.
void RememberLevels(const UniformGrid& grid,
                    const FilmTemperature& previous,
                    double dt_s,
                    double u1_m_s,
                    double u2_m_s,
                    FilmTemperature* t);

// A steady level at the surface speeds u1_m_s, u2_m_s: infinite travels, no earlier levels.
void ForgetLevels(double u1_m_s, double u2_m_s, FilmTemperature* t);

}  // namespace tehl::internal
