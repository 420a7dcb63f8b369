// The schema of a lubricant file (lubricants/*.toml; docs/case_format.md). Private to src/.
#pragma once

#include "base/schema.hpp"

namespace tehl::internal {

// Built once, immutable, thread-safe to read.
const Schema& LubricantSchema();

// A limiting shear stress tau_L = tau_L0 + Lambda p with tau_L0 = 0 vanishes at ambient
// pressure, where the inlet builds the film: the film then depends on how small tau_L0 is and
// the coupling does not settle (docs/thermal.md, "Ree-Eyring film"). Shared by the file reader
// (at the line of the slope) and the Lubricant constructor.
inline constexpr const char* kSlopeNeedsStressRule =
    "needs limiting_stress_pa > 0: with tau_L0 = 0 the limit tau_L0 + Lambda p vanishes at "
    "ambient pressure, where the inlet builds the film, and the film could carry no shear stress "
    "there";
inline constexpr const char* kSlopeNeedsStressAllowed =
    "0 (no pressure-dependent limit), or a slope >= 0 with limiting_stress_pa > 0 [Pa]";

}  // namespace tehl::internal
