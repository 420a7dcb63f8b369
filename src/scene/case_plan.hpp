// What a run of a case would do, checked as the run checks it before solving: the gear pair
// and its mesh cycle plan (steps, grid, roughness and memory rules), or a [contact] film's
// scale and grid. `tehl case --check` prints it; a study checks each scene with it, so that a
// scene no run would accept is bad input of the study, not a failed scene. Private to src/.
#pragma once

#include <string>

#include "base/schema.hpp"

namespace tehl::internal {

// The plan as text ("mesh cycle of N steps (...) on M nodes (...)" and its notes, each on its
// own line starting "\n  note: "); "" when `doc` already has problems or is neither kind.
// Problems found go to `doc`.
std::string CheckCasePlan(Document& doc);

}  // namespace tehl::internal
