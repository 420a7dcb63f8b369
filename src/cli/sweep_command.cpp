// tehl sweep STUDY [-j N] [--resume] [--dry-run] [-q] [-o DIR]: expands a study file into
// scenes and runs them on a pool of threads, over MPI ranks when started by mpirun (static
// round-robin: scene i on rank i mod K); rank 0 writes the index once every rank is done.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/sweep_mpi.hpp"
#include "scene/automatic_grid.hpp"
#include "tehl/ehl/flash_temperature.hpp"
#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/error.hpp"
#include "tehl/scene/study.hpp"
#include "tehl/scene/study_index.hpp"
#include "tehl/scene/study_run.hpp"

namespace tehl::cli {
namespace {

struct SweepArgs {
  std::string study;
  std::string output_dir;
  int threads = 0;
  bool resume = false;
  bool dry_run = false;
  bool quiet = false;
};

// Runs `step` on this rank, then agrees with the other ranks on how it went before any of them
// makes the next collective call. Returns kExitOk when the step succeeded on every rank; else
// the exit code of the sweep (the highest of the ranks'), and the lowest rank that had it
// prints its error: a study with bad input, read alike by every rank, is reported once.
template <class Step>
int OnEveryRank(const SweepMpi& mpi, Step&& step) {
  std::exception_ptr error;
  try {
    step();
  } catch (...) {
    error = std::current_exception();
  }
  const CommandError mine = error ? DescribeCommandError(error) : CommandError{kExitOk, ""};
  const SweepMpi::Outcome all = mpi.Agree(mine.exit_code);
  if (all.exit_code != kExitOk && all.rank == mpi.rank()) {
    std::fprintf(stderr, "%s\n", mine.message.c_str());
    if (mpi.size() > 1)
      std::fprintf(stderr, "tehl sweep: stopped on rank %d of %d; every rank stops with it\n",
                   mpi.rank(), mpi.size());
  }
  return all.exit_code;
}

// The steps of every rank: read the study, write the scene files (rank 0), run this rank's
// scenes and gather the rows on rank 0 (`all_rows`). Returns the exit code of the sweep so far.
int RunOnEveryRank(const SweepArgs& a, const SweepMpi& mpi, Study* study, std::string* all_rows) {
  // The scene threads run while the main thread makes the MPI calls.
  if (const int code = OnEveryRank(mpi, [&] {
        if (!mpi.threads_allowed() && !a.dry_run && a.threads != 1)
          throw InputError(InputProblem{
              "", 0, "-j/--threads", a.threads > 0 ? std::to_string(a.threads) : "all cores",
              "this MPI library lets no other thread run beside its calls (its thread level is "
              "below MPI_THREAD_FUNNELED)",
              "-j 1, or an MPI built with thread support"});
      }))
    return code;
  if (const int code = OnEveryRank(mpi, [&] {
        StudyReadOptions ro;
        ro.output_dir = a.output_dir;
        *study = ReadStudy(a.study, ro);
      }))
    return code;
  // Agreed: the scene files are written before any rank runs a scene.
  if (const int code = OnEveryRank(mpi, [&] {
        if (mpi.rank() == 0) WriteSceneFiles(*study);
      }))
    return code;
  if (a.dry_run) return kExitOk;

  std::vector<int> mine;
  for (int i = mpi.rank(); i < static_cast<int>(study->scenes.size()); i += mpi.size())
    mine.push_back(i);
  SweepOptions so;
  so.threads = a.threads;
  so.resume = a.resume;
  if (!a.quiet)
    so.on_scene = [&](const SceneRow& r, int done, int total) {
      const std::string restarts =
          r.steady_restarts > 0 ? ", " + std::to_string(static_cast<int>(r.steady_restarts)) +
                                      " step(s) restarted from the steady film"
                                : "";
      std::fprintf(stderr, "%s[%d/%d] %s %s%s%s (%.1f s)\n",
                   mpi.size() > 1 ? ("rank " + std::to_string(mpi.rank()) + " ").c_str() : "", done,
                   total, study->scenes[r.scene].name.c_str(), r.status.c_str(), restarts.c_str(),
                   r.computed ? "" : ", resumed", r.wall_time_s);
    };
  std::string rows;
  if (const int code =
          OnEveryRank(mpi, [&] { rows = SceneRowsToText(RunStudyScenes(*study, mine, so)); }))
    return code;
  *all_rows = mpi.GatherToRoot(rows);
  return kExitOk;
}

void PrintDryRun(const SweepArgs& a, const Study& study) {
  std::printf("%s: %zu scene%s (%s of %zu parameter%s), base %s\n", a.study.c_str(),
              study.scenes.size(), study.scenes.size() == 1 ? "" : "s", study.mode.c_str(),
              study.parameters.size(), study.parameters.size() == 1 ? "" : "s",
              study.base_case_path.c_str());
  for (const auto& sc : study.scenes) {
    std::printf("%s", sc.case_path.c_str());
    for (size_t i = 0; i < study.parameters.size(); ++i)
      std::printf("  %s = %s", study.parameters[i].label.c_str(),
                  study.parameters[i].values_toml[sc.value_index[i]].c_str());
    std::printf("\n");
  }
}

int RunSweep(const SweepArgs& a) {
  const SweepMpi mpi;
  Study study;
  std::string all;
  int code = kExitOk;
  try {
    code = RunOnEveryRank(a, mpi, &study, &all);
  } catch (...) {
    // An error outside the agreed steps: the other ranks may be waiting for this one in a
    // collective call, so all of them end here.
    if (mpi.size() == 1) throw;
    const CommandError e = DescribeCommandError(std::current_exception());
    std::fprintf(stderr, "%s\ntehl sweep: stopped on rank %d of %d; ending every rank\n",
                 e.message.c_str(), mpi.rank(), mpi.size());
    mpi.Abort(e.exit_code);
  }
  // The ranks are done with each other: rank 0 reports and writes the index.
  if (code != kExitOk || mpi.rank() != 0) return code;
  if (a.dry_run) {
    PrintDryRun(a, study);
    return kExitOk;
  }
  const std::vector<SceneRow> gathered = SceneRowsFromText(all);
  const auto paths = WriteStudyIndex(study, gathered);
  int ok = 0, not_converged = 0, failed = 0, resumed = 0, restarted = 0, unresolved_edge = 0,
      short_inlet = 0, unphysical_mu = 0;
  double fewest_nodes = 0, most_nodes = 0;  // over the scenes whose result has a grid
  for (const auto& r : gathered) {
    if (r.grid_points > 0) {
      fewest_nodes = fewest_nodes > 0 ? std::min(fewest_nodes, r.grid_points) : r.grid_points;
      most_nodes = std::max(most_nodes, r.grid_points);
    }
    ok += r.status == "ok";
    restarted += r.steady_restarts > 0;
    unresolved_edge += r.edge_cells_min >= 0 && r.edge_cells_min < kEdgeResolvedCells;
    short_inlet += r.inlet_deficit_max > internal::kInletNoteDeficit;
    unphysical_mu += r.unphysical_mu_films > 0;
    not_converged += r.status == "not_converged";
    failed += r.status.rfind("failed", 0) == 0;
    resumed += !r.computed;
  }
  std::printf("%zu scenes: %d ok, %d not converged, %d failed (%d read back by --resume)\n",
              gathered.size(), ok, not_converged, failed, resumed);
  if (restarted > 0)
    std::printf(
        "note: %d scene(s) have time steps that did not converge and were replaced by the "
        "steady film at their time (index column steady_restarts; [numerics] failed_step)\n",
        restarted);
  if (unresolved_edge > 0)
    std::printf(
        "note: %d scene(s) have films whose Hertzian edge spans fewer than %.0f grid cells "
        "(index column edge_cells_min): their h_c is likely more than 1 %% too thin; more "
        "[numerics] grid_points resolve it (docs/results.md, \"The edge note\")\n",
        unresolved_edge, kEdgeResolvedCells);
  if (short_inlet > 0)
    std::printf(
        "note: %d scene(s) have films that the inlet at x_start_b thins by more than %.1f %% "
        "(index column inlet_deficit_max): a longer inlet ([numerics] x_start_b with "
        "grid_points raised in proportion, or the automatic grid) removes it (docs/results.md, "
        "\"The inlet note\")\n",
        short_inlet, 100 * internal::kInletNoteDeficit);
  if (unphysical_mu > 0)
    std::printf(
        "note: %d scene(s) have Newtonian films whose friction coefficient exceeds %.1f (index "
        "column unphysical_mu_films): a full film carries at most about 0.1 of its pressure "
        "as shear stress, so that mu and a flash temperature from it are not physical (their "
        "flash rises are left out of dT_flash_blok_max_k); [effects] non_newtonian = true "
        "bounds the shear stress (docs/results.md, \"The friction note\")\n",
        unphysical_mu, kPhysicalFrictionLimit);
  if (most_nodes > fewest_nodes)
    std::printf(
        "note: the scenes ran on grids of %.0f to %.0f nodes (index column grid_points; the "
        "automatic grid follows each scene's films, docs/case_format.md): their wall times "
        "differ by that too\n",
        fewest_nodes, most_nodes);
  std::printf("wrote %s and %s\n", paths[0].c_str(), paths[1].c_str());
  return ok == static_cast<int>(gathered.size()) ? kExitOk : kExitNotConverged;
}

}  // namespace

Command AddSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* sub = app.add_subcommand(
      "sweep", "Run a study: a base case expanded into scenes (docs/studies.md)");
  sub->add_option("STUDY", args->study, "Study file (.toml)")->required();
  sub->add_option("-j,--threads", args->threads, "Scenes run at once per process (default: all "
                  "cores)")
      ->check(CLI::Range(1, 4096));
  sub->add_flag("--resume", args->resume,
                "Read back the scenes whose result file is complete; run only the others");
  sub->add_flag("--dry-run", args->dry_run,
                "Expand, check and write the scene files; run nothing");
  sub->add_flag("-q,--quiet", args->quiet, "No line per finished scene");
  sub->add_option("-o,--output-dir", args->output_dir, "Folder of the study ([study] output)");
  return {sub, [args]() { return RunSweep(*args); }};
}

}  // namespace tehl::cli
