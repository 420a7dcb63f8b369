// An 8-scene reduced study (the isothermal seed 004 SAE 40 cycle at 129 nodes and 40 steps,
// power from 4 to 18 kW) on 1 and on 2 threads in one run; the 2-thread case reports the speed-up
// against the 1-thread time of the same run (counter `speedup`).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "tehl/scene/study.hpp"
#include "tehl/scene/study_run.hpp"

namespace {
namespace fs = std::filesystem;

tehl::Study ReducedStudy() {
  const fs::path dir = fs::temp_directory_path() / ("tehl_sweep_bench_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "study.toml").string();
  std::ofstream(path) << "[study]\nbase = \"" TEHL_SOURCE_DIR "/cases/seed004_sae40.toml\"\n"
                      << "output = \"" << (dir / "out").string() << "\"\n"
                      << "[[vary]]\nkey = \"operating.power_w\"\n"
                      << "values = [4000.0, 6000.0, 8000.0, 10000.0, 12000.0, 14000.0, 16000.0, "
                         "18000.0]\n"
                      << "[[vary]]\nkey = \"numerics.grid_points\"\nvalues = [129]\n"
                      << "[[vary]]\nkey = \"numerics.steps\"\nvalues = [40]\n"
                      << "[[vary]]\nkey = \"effects.thermal\"\nvalues = [false]\n";
  tehl::Study s = tehl::ReadStudy(path);
  tehl::WriteSceneFiles(s);
  return s;
}

double one_thread_s = 0;

void BM_ReducedStudy(benchmark::State& state) {
  static const tehl::Study study = ReducedStudy();
  std::vector<int> ids(study.scenes.size());
  std::iota(ids.begin(), ids.end(), 0);
  tehl::SweepOptions o;
  o.threads = static_cast<int>(state.range(0));
  double seconds = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto rows = tehl::RunStudyScenes(study, ids, o);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const auto& r : rows)
      if (r.status != "ok") state.SkipWithError(("scene not ok: " + r.status).c_str());
  }
  state.counters["scenes"] = static_cast<double>(ids.size());
  if (o.threads == 1) one_thread_s = seconds;
  if (o.threads > 1 && one_thread_s > 0) state.counters["speedup"] = one_thread_s / seconds;
}
BENCHMARK(BM_ReducedStudy)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
