// Running the scenes of a study on a pool of threads (docs/studies.md). Each scene runs its
// case (the mesh cycle of a gear case, or the contact case) with its progress line off and
// writes its own result into Study::ScenesDir(); a scene that fails (an exception) or does
// not converge is recorded in its row and the others go on.
//
// Thread safety: the scene path shares no mutable state except the FFTW planner and the
// HDF5 library, each behind one process-wide lock (src/ehl/fftw_planner.hpp,
// src/io/hdf5_lock.hpp).
#pragma once

#include <functional>
#include <vector>

#include "tehl/scene/study.hpp"
#include "tehl/scene/study_index.hpp"

namespace tehl {

struct SweepOptions {
  int threads = 0;      // worker threads; 0 = std::thread::hardware_concurrency() [-]
  bool resume = false;  // a scene whose result file exists is read back, not run
  // Called after each scene (from its worker thread, one call at a time): its row, the
  // number of scenes done so far and the number to do.
  std::function<void(const SceneRow&, int done, int total)> on_scene;
};

// Runs (or, with resume, reads back) one scene. Never throws for a scene's own failure.
SceneRow RunStudyScene(const Study& study, const StudyScene& scene, bool resume);

// Runs the scenes `ids` (indices into study.scenes) on options.threads threads; the rows
// come back in the order of `ids`. The scene files must exist (WriteSceneFiles). Any other
// exception (an id out of range, one thrown by on_scene) stops the pool: no further scene
// starts, and the first is rethrown once every thread has finished.
std::vector<SceneRow> RunStudyScenes(const Study& study,
                                     const std::vector<int>& ids,
                                     const SweepOptions& options);

}  // namespace tehl
