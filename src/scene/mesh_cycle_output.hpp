// Writing a mesh-cycle result: the HDF5 file (layout in docs/results.md) and the CSV of the
// cycle table. Private to src/.
#pragma once

#include <string>

#include "base/schema.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl::internal {

// Writes `path` atomically (Hdf5Writer): /case, /cycle, /profiles (when `profiles`), /solver.
void WriteMeshCycleHdf5(const std::string& path, const Document& doc,
                        const std::string& case_path, const MeshCycleResult& r, bool profiles);

// The /cycle table as CSV, one row per step, same columns and units as /cycle.
void WriteMeshCycleCsv(const std::string& path, const MeshCycleResult& r);

}  // namespace tehl::internal
