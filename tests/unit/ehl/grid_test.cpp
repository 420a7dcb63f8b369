// The uniform film grid: its nodes, and what it refuses, at the argument that is wrong.
#include "tehl/ehl/grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "tehl/error.hpp"

namespace tehl {
namespace {

std::string KeyOfTheOnlyProblem(void (*make)()) {
  try {
    make();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems().size(), 1u) << e.what();
    return e.problems()[0].key;
  }
  return "(accepted)";
}

TEST(UniformGrid, NodesSpanTheEndsEvenly) {
  const UniformGrid g(-4.5e-4, 1.5e-4, 7);
  EXPECT_DOUBLE_EQ(g.dx_m(), 1e-4);
  EXPECT_DOUBLE_EQ(g.x(0), -4.5e-4);
  EXPECT_NEAR(g.x_end_m(), 1.5e-4, 1e-18);
  EXPECT_EQ(g.NearestNode(0.6e-4), 5);  // the node at 0.5e-4
  EXPECT_EQ(g.NearestNode(-1.0), 0);    // clamped
  // -4.5 b .. 1.5 b around b = 1e-4 m.
  const UniformGrid h = UniformGrid::AroundHertz(1e-4, 7);
  EXPECT_DOUBLE_EQ(h.x_start_m(), g.x_start_m());
  EXPECT_DOUBLE_EQ(h.dx_m(), g.dx_m());
}

TEST(UniformGrid, RefusesWhatIsNoGridAtItsArgument) {
  EXPECT_EQ(KeyOfTheOnlyProblem([] { UniformGrid(0.0, 1.0, 4); }), "UniformGrid::n");
  EXPECT_EQ(KeyOfTheOnlyProblem([] { UniformGrid(1.0, 0.0, 5); }), "UniformGrid::x_end_m");
  // A half-width that is not a length is named as such, not as the grid ends it makes.
  EXPECT_EQ(KeyOfTheOnlyProblem([] { UniformGrid::AroundHertz(-1e-4, 513); }),
            "UniformGrid::AroundHertz half_width_m");
  EXPECT_EQ(KeyOfTheOnlyProblem([] { UniformGrid::AroundHertz(std::nan(""), 513); }),
            "UniformGrid::AroundHertz half_width_m");
  EXPECT_EQ(KeyOfTheOnlyProblem([] { UniformGrid::AroundHertz(1e-4, 513, 1.5, -4.5); }),
            "UniformGrid::AroundHertz end_b");
}

}  // namespace
}  // namespace tehl
