// Design checks of a train file that need more than its kinematics: the planet rules of
// every carrier (seed 001 section 2.3) for the simple sun-planet-ring set and for every
// other planet gear (compound planets). Private to src/.
#pragma once

#include "base/schema.hpp"
#include "drive/train_reader.hpp"

namespace tehl::internal {

// Fills file->planetary and reports the broken rules to `doc` at the keys concerned:
// [carrier.NAME] planets (count), the planet's teeth (simple set), and the mesh of a planet
// shaft whose centre distance differs from the shaft's other meshes.
void CheckPlanets(Document& doc, TrainFile* file);

// A planet-count limit for messages: "6" when the limit is an integer up to round-off,
// else 4 significant digits ("3.441").
std::string PlanetLimitText(double limit);

}  // namespace tehl::internal
