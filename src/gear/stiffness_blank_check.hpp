// Private helper of the mesh-stiffness methods: input checks of a ToothBlank, reported as
// InputProblems (a blank is built in code, so there is no file and no line).
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/gear/mesh_stiffness.hpp"

namespace tehl::internal {

// Every field of a blank that a tooth-stiffness method relies on: teeth, module, pressure
// angles, basic rack, tip radius above the root circle, face width, E, nu, bore radius.
// which: "pinion" or "wheel"; keys are named like the case file ("gear.pinion.teeth").
std::vector<InputProblem> CheckToothBlank(const ToothBlank& blank, const std::string& which);

// A problem with key "gear.mesh_stiffness": the blank is valid, the method does not apply.
InputProblem MethodRangeProblem(const std::string& value,
                                const std::string& rule,
                                const std::string& allowed);

// "%g" formatting of a number for InputProblem::value.
std::string FormatValue(double v);

}  // namespace tehl::internal
