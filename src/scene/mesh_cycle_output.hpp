// Writing a mesh-cycle result: the HDF5 file (layout in docs/results.md) and the CSV of the
// cycle table. Private to src/.
#pragma once

#include <memory>
#include <string>

#include "base/schema.hpp"
#include "tehl/io/hdf5_writer.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl::internal {

// Opens `path` for writing (as `path`.part, Hdf5Writer) before the run and writes the root
// attributes that are known then and /case.
std::unique_ptr<Hdf5Writer> BeginMeshCycleHdf5(const std::string& path,
                                               const Document& doc,
                                               const std::string& case_path);
// Writes /cycle, /profiles (p and h when `profiles`), /solver and commits the file.
void FinishMeshCycleHdf5(Hdf5Writer& h5, const MeshCycleResult& r, bool profiles);

// The /cycle table as CSV, one row per step, same columns and units as /cycle.
void WriteMeshCycleCsv(const std::string& path, const MeshCycleResult& r);

}  // namespace tehl::internal
