#include "tehl/scene/study_run.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>

#include "tehl/scene/contact_scene.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl {

SceneRow RunStudyScene(const Study& study, const StudyScene& scene, bool resume) {
  const std::string result = study.ResultPath(scene);
  std::error_code ec;
  if (resume && std::filesystem::is_regular_file(result, ec)) {
    // Results are renamed to their final name only when complete: the file is the scene.
    try {
      SceneRow r = ReadSceneRow(study, scene);
      r.computed = false;
      return r;
    } catch (const std::exception&) {
      // Unreadable: run the scene again below.
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  try {
    // The row of a finished scene comes from its result file alone (wall time included: the
    // HDF5 wall_time of a mesh cycle, the sum of the steps' wall_time_s of a contact case), so
    // --resume rebuilds exactly the row written here.
    if (study.gear) {
      MeshCycleRunOptions o;
      o.quiet = true;
      o.output_dir = study.ScenesDir();
      RunMeshCycle(scene.case_path, o);
    } else {
      ContactRunOptions o;
      o.quiet = true;
      o.output_dir = study.ScenesDir();
      RunContactCase(scene.case_path, o);
    }
    return ReadSceneRow(study, scene);
  } catch (const std::exception& e) {
    // No result file: the time spent until the failure.
    SceneRow r = FailedSceneRow(scene, e.what());
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }
}

std::vector<SceneRow> RunStudyScenes(const Study& study,
                                     const std::vector<int>& ids,
                                     const SweepOptions& options) {
  std::vector<SceneRow> rows(ids.size());
  int threads = options.threads > 0 ? options.threads
                                    : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min<int>(threads, static_cast<int>(ids.size())));
  std::atomic<size_t> next{0};
  std::mutex report;
  int done = 0;
  auto work = [&] {
    for (size_t i; (i = next.fetch_add(1)) < ids.size();) {
      rows[i] = RunStudyScene(study, study.scenes.at(ids[i]), options.resume);
      std::lock_guard<std::mutex> lock(report);
      ++done;
      if (options.on_scene) options.on_scene(rows[i], done, static_cast<int>(ids.size()));
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  return rows;
}

}  // namespace tehl
