// The solids' heat history through the line-contact solver (docs/theory.md, "The solids' heat
// history"): each transient step hands its speeds, travels and the earlier levels on in the
// film state, so that the next step integrates the flux history in time. The kernels
// themselves are tested in tests/unit/ehl/solid_heat_history_test.cpp.
// Case: the steel disc of thermal_disc_case.hpp in pure rolling at L_T = 1 (SAE 40, p_H =
// 0.8 GPa), 129 nodes; steady, then steps whose surface speeds change.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "verification/thermal_disc_case.hpp"

namespace tehl {
namespace {

using testing::Sae40;
using testing::ThermalDisc;

TEST(ThermalSolidHistory, StepsHandTheirSpeedsTravelsAndEarlierLevelsOn) {
  ThermalDisc d;
  d.um_m_s = testing::SpeedForLoading(Sae40(), 1.0);
  FilmEffects e;
  e.transient = true;
  e.thermal = true;
  const UniformGrid g = UniformGrid::AroundHertz(d.half_width_m(), 129);
  LineContactSolver solver(g, d.e_prime_pa, Sae40(), e, LineContactSolver::Options{});
  const ContactConditions c0 = d.Conditions(Sae40());
  FilmState st;
  ASSERT_TRUE(solver.SolveSteady(c0, &st).usable());
  // A steady level: its flux had always acted.
  EXPECT_TRUE(std::isinf(st.temperature.travel1_m));
  EXPECT_TRUE(st.temperature.earlier.empty());
  EXPECT_EQ(st.temperature.speed1_m_s, c0.u1_m_s);
  solver.BeginTransient(c0, st);
  // Two steps of 1/20 of a transit of the grid, the surfaces slowing by 10 % and 20 %.
  const double length = g.x(g.size() - 1) - g.x(0), dt = 0.05 * length / d.um_m_s;
  const Eigen::VectorXd q_steady = st.temperature.q1_w_m2;
  ContactConditions c = c0;
  for (double slow : {0.9, 0.8}) {
    c.u1_m_s = slow * c0.u1_m_s;
    c.u2_m_s = slow * c0.u2_m_s;
    const LineContactSolver::Summary s = solver.Step(c, dt, &st);
    ASSERT_TRUE(s.usable()) << s.BriefReport();
    EXPECT_EQ(st.temperature.speed1_m_s, c.u1_m_s);
    EXPECT_EQ(st.temperature.speed2_m_s, c.u2_m_s);
    EXPECT_DOUBLE_EQ(st.temperature.travel1_m, c.u1_m_s * dt);
  }
  // Newest first: the 0.9 step, then the steady level, with their own speeds and fluxes.
  ASSERT_EQ(st.temperature.earlier.size(), 2u);
  const SolidFluxLevel &newer = st.temperature.earlier[0], &older = st.temperature.earlier[1];
  EXPECT_EQ(newer.speed1_m_s, 0.9 * c0.u1_m_s);
  EXPECT_DOUBLE_EQ(newer.travel1_m, 0.9 * c0.u1_m_s * dt);
  EXPECT_EQ(older.speed1_m_s, c0.u1_m_s);
  EXPECT_TRUE(std::isinf(older.travel1_m));
  EXPECT_EQ(older.q1_w_m2, q_steady);
  // A steady solve forgets the history.
  ASSERT_TRUE(solver.SolveSteady(c, &st).usable());
  EXPECT_TRUE(st.temperature.earlier.empty());
  EXPECT_TRUE(std::isinf(st.temperature.travel2_m));
}

}  // namespace
}  // namespace tehl
