// Design checks of a train file that need more than its kinematics: the planet rules of
// every carrier (seed 001 section 2.3) for the simple sun-planet-ring set and for every
// other planet gear (compound planets). Private to src/.
#pragma once

#include <string>
#include <vector>

#include "base/schema.hpp"
#include "drive/train_reader.hpp"

namespace tehl::internal {

// Fills file->planetary and reports the broken rules to `doc` at the keys concerned:
// [carrier.NAME] planets (count), the planet's teeth (simple set), and the mesh of a planet
// shaft whose centre distance differs from the shaft's other meshes.
void CheckPlanets(Document& doc, TrainFile* file);

// The smallest z_ring - z_pinion of an internal pair of standard 20 deg full-depth teeth
// (h_a* = 1, no profile shift) without trochoid interference, the pinion's tips fouling the
// ring's on leaving the mesh: SDP/SI, "Elements of Metric Gear Technology" (D785), section
// 5.2 (b): "trochoid interference is avoided if the difference of the number of teeth is
// larger than 9" (the same in KHK's Gear Technical Reference). Textbooks give 12 for
// 14.5 deg teeth and 7 for 20 deg stub teeth.
inline constexpr int kMinInternalToothDifference = 10;

// A note (not an error) per internal mesh of `spec` whose ring has fewer than
// kMinInternalToothDifference teeth more than the gear inside it.
void NoteCloseInternalPairs(const GearTrainSpec& spec, std::vector<std::string>* notes);

// A planet-count limit for messages: "6" when the limit is an integer up to round-off,
// else 4 significant digits ("3.441").
std::string PlanetLimitText(double limit);

}  // namespace tehl::internal
