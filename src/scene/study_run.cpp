#include "tehl/scene/study_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>

#include "scene/case_inputs.hpp"
#include "scene/mesh_cycle_checkpoint.hpp"
#include "tehl/scene/contact_scene.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl {

namespace {

// The fingerprint of a scene's case file, kept beside its result as RESULT.case: --resume
// reuses a result only when the scene it was made from is the scene asked for (a folder of
// another study, or of an edited one, holds results of other scenes under the same names,
// and an edited lubricant file changes every scene that reads it).
// The lubricant file and measured profiles the scene reads are part of it.
std::string SceneFingerprint(const StudyScene& scene) {
  return std::to_string(internal::CaseFingerprint(internal::CaseWithInputsText(scene.case_path)));
}

std::string FingerprintPath(const std::string& result) { return result + ".case"; }

bool SameScene(const std::string& result, const StudyScene& scene) {
  std::ifstream in(FingerprintPath(result));
  std::string stored;
  return std::getline(in, stored) && stored == SceneFingerprint(scene);
}

// A fingerprint that cannot be kept costs nothing but a rerun of the scene by --resume; its
// temporary file goes either way (a folder in its way is not ours to remove).
void KeepFingerprint(const std::string& result, const StudyScene& scene) {
  namespace fs = std::filesystem;
  const std::string path = FingerprintPath(result), part = path + ".part";
  std::error_code ec;
  bool written = false;
  {
    std::ofstream out(part);
    out << SceneFingerprint(scene) << "\n";
    out.close();
    written = static_cast<bool>(out);
  }
  if (written) fs::rename(part, path, ec);
  if ((!written || ec) && fs::is_regular_file(part, ec)) fs::remove(part, ec);
}

}  // namespace

SceneRow RunStudyScene(const Study& study, const StudyScene& scene, bool resume) {
  const std::string result = study.ResultPath(scene);
  std::error_code ec;
  if (resume && std::filesystem::is_regular_file(result, ec) && SameScene(result, scene)) {
    // Results are renamed to their final name only when complete: the file is the scene.
    try {
      SceneRow r = ReadSceneRow(study, scene);
      r.computed = false;
      return r;
    } catch (const std::exception&) {
      // Unreadable: run the scene again below.
    }
  }
  // The scene is (re)run: a result of another scene under its name goes first, and the
  // fingerprint is kept before the run, so that a result that appears belongs to it (a sweep
  // killed at any moment leaves either no result or this scene's).
  std::filesystem::remove(result, ec);
  KeepFingerprint(result, scene);
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
  // The first exception of any thread (a scene's own failure is a row, not an exception):
  // the threads take no further scene, and it is rethrown once all of them are joined.
  std::exception_ptr error;
  auto work = [&] {
    for (size_t i; (i = next.fetch_add(1)) < ids.size();) {
      try {
        rows[i] = RunStudyScene(study, study.scenes.at(ids[i]), options.resume);
        std::lock_guard<std::mutex> lock(report);
        ++done;
        if (options.on_scene) options.on_scene(rows[i], done, static_cast<int>(ids.size()));
      } catch (...) {
        std::lock_guard<std::mutex> lock(report);
        if (!error) error = std::current_exception();
        next = ids.size();
      }
    }
  };
  std::vector<std::thread> pool;
  try {
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  } catch (const std::system_error&) {
    // No more threads to be had: the ones started (and this one) run all the scenes.
  }
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return rows;
}

}  // namespace tehl
