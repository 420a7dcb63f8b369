// The ToothBlank of each gear of a pair, as the mesh stiffness methods need it
// (mesh_stiffness.hpp), and the pair stiffness as a PairStiffnessFn (load_sharing.hpp).
#pragma once

#include "tehl/gear/gear_pair.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/mesh_stiffness.hpp"

namespace tehl {

// The blank of the pinion or the wheel: teeth, normal module and pressure
// angles, shift, basic rack, tip radius as built, face width, material; bore not known
// (bore_radius_m = 0, the method's default).
ToothBlank PinionBlank(const GearPair& pair);
ToothBlank WheelBlank(const GearPair& pair);

// Wraps a model (not owned; it must outlive the returned function) as a PairStiffnessFn.
PairStiffnessFn AsPairStiffnessFn(const PairStiffnessModel& model);

}  // namespace tehl
