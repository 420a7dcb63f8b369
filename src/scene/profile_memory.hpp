// What a run's per-step profiles cost: a mesh cycle or a [contact] table keeps p and h (and,
// thermal, the mid-film and both wall temperatures, and with [output] temperature_field the
// whole T(x, z)) at every step in memory, in its checkpoint journal and, with [output]
// profiles, in the result file. Private to src/.
#pragma once

#include <string>
#include <vector>

#include "base/schema.hpp"
#include "scene/film_case.hpp"

namespace tehl::internal {

// Profiles above this size are noted by the plan (`case --check`, the run's notes) [bytes].
inline constexpr double kProfileNoteBytes = 1.0 * (1 << 30);

// Bytes of the profiles a run of `rows` recorded steps on `nodes` grid nodes keeps [bytes]:
// 8 per double, p and h, and with `thermal` the mid-film and both wall temperatures plus,
// with `field`, film_nodes temperatures per node.
double ProfileBytes(long long nodes, long long rows, bool thermal, int film_nodes, bool field);

// Adds a note to `notes` when the profiles of the plan exceed kProfileNoteBytes, and reports a
// problem when they would not fit in this machine's physical memory: at [output]
// temperature_field when the field is most of it, else at [numerics] grid_points when the
// case sets it, else at the step count's key `steps_key` of `steps_section`. `journal`: the run
// keeps a checkpoint journal of them (the mesh cycle).
void CheckProfileMemory(Document& doc,
                        const FilmCase& film,
                        long long nodes,
                        long long rows,
                        bool journal,
                        const std::string& steps_section,
                        const std::string& steps_key,
                        std::vector<std::string>& notes);

}  // namespace tehl::internal
