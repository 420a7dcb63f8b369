// External torques on a frictionless gear train by virtual work (seed 001 section 2 gives the
// speeds; the torques follow from them). Let C be the train's kinematic relations only
// (meshes and shafts, gear_train.hpp) and v any motion they allow (C v = 0). With no friction
// and no inertia the external torques tau do no work in any such motion:
//     sum_j tau_j v_j = 0   for every v in the null space of C,
// where tau is zero on every member but the driven input (tau_in given), the output (the
// load's torque) and the held members (the frame's reaction). With tau_in given this is a
// small linear system for tau_out and the held reactions. Consequences: the torques sum to
// zero over a coaxial train (v = every member turning together), and T_in w_in +
// T_out w_out = 0 (v = the solved speeds: held members do not move).
// Sign: each torque is the one applied TO the member from outside (by the driver, the load,
// the frame), positive counter-clockwise like the speeds; the output's is negative when
// the load resists the motion. A rack carries a force [N], positive like its speed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tehl/drive/gear_train.hpp"

namespace tehl {

struct TrainTorques {
  bool solved = false;
  std::string message;  // why there are no torques when !solved; "" otherwise
  int input = -1;       // member the input torque is applied to (the driven one)
  int output = -1;      // the output member
  std::vector<std::optional<double>> torque;  // per member; absent = no external torque
                                              // [N m] (rack: [N])
  double power_residual = 0;                  // |sum tau_j w_j| / |tau_in w_in| [-]
};

// `solution` = SolveGearTrain(spec). The torques exist for a train with exactly one driven
// member (speed != 0) and an output that is neither that member nor held, when the system
// above has exactly one solution; otherwise `message` says why. `input_torque` is tau_in
// [N m] (rack input: [N]).
TrainTorques SolveTrainTorques(const GearTrainSpec& spec,
                               const TrainSolution& solution,
                               double input_torque = 1.0);

}  // namespace tehl
