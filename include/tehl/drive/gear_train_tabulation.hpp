// The tabulation method for epicyclic trains (seed 001 section 2.2, Examples 2.9 and 2.10;
// seed 002): per carrier (arm), the motion of every member of its epicyclic group split into
//   "arm fixed, +1 turn of R"       the ratios relative to the arm (Willis values),
//   "whole train locked to the arm" every member turns with the arm at w_arm,
//   "arm fixed, R turned w_R-w_arm" the ratios times the reference gear's relative speed,
//   "absolute"                      the sum of the two rows above = the solved speeds
//                                   (empty for a bevel planet: its axis is not the arm's).
// The group of a carrier: the carrier, the gears riding on it and the gears meshing with
// those. The reference gear R: the first gear of the group on a fixed axis that is driven or
// held, else the first gear of the group on a fixed axis, else its first gear.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tehl/drive/gear_train.hpp"

namespace tehl {

struct TabulationRow {
  std::string label;
  std::vector<std::optional<double>> values;  // per column; empty when not determined
                                              // (row 1 [-], rows 2-4 [rad/s])
};

struct TabulationTable {
  std::string carrier;               // the arm
  std::string reference;             // the reference gear R
  std::vector<std::string> columns;  // member names, in the order of the spec
  std::vector<TabulationRow> rows;   // the four rows described above
};

// One table per carrier that has gears riding on it. `solution` is SolveGearTrain(spec).
std::vector<TabulationTable> TabulateEpicyclic(const GearTrainSpec& spec,
                                               const TrainSolution& solution);

}  // namespace tehl
