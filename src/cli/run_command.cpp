// tehl run CASE: runs a case. A [gear] case runs the mesh cycle from A to E (HDF5 result and
// CSV of the cycle table); a [contact] case runs the plain line contact (CSV files).
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/number_format.hpp"
#include "cli/run_notes.hpp"
#include "scene/case_reader.hpp"
#include "tehl/scene/contact_scene.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"
#include "tehl/scene/path_point_case.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {
namespace {

// Which film law the friction and temperatures come from; the Newtonian one overestimates
// both wherever the film slides (docs/thermal.md).
const char* FilmModelText(bool non_newtonian) {
  return non_newtonian ? "Ree-Eyring film"
                       : "Newtonian film (overestimates friction where it slides; "
                         "non_newtonian = true for Ree-Eyring)";
}

struct RunArgs {
  std::string case_path;
  std::string output_dir;
  bool quiet = false;
  bool resume = false;
  int checkpoint_every = 10;
  std::string at;  // --at: the steady film at this point of a gear's path
};

int RunGear(const RunArgs& a) {
  MeshCycleRunOptions o;
  o.quiet = a.quiet;
  o.output_dir = a.output_dir;
  o.resume = a.resume;
  o.checkpoint_every = a.checkpoint_every;
  // The resume tests (tests/regression/mesh_cycle_runs.hpp) set TEHL_STOP_AFTER_CHECKPOINT:
  // the process stops itself once its first checkpoint is on disk, so that the test kills it
  // at a known step. The library has no such hook; `tehl sweep` never installs it.
  if (std::getenv("TEHL_STOP_AFTER_CHECKPOINT") != nullptr)
    o.after_checkpoint = [](int) { raise(SIGSTOP); };
  const MeshCycleResult r = RunMeshCycle(a.case_path, o);
  if (r.already_complete) {
    std::printf("%s is complete: nothing to resume\n", r.hdf5_path.c_str());
    return kExitOk;
  }
  if (r.resumed_from_step > 0)
    std::printf("resumed from the checkpoint at step %d\n", r.resumed_from_step);
  // A cycle reports only its converged steps (not the failed one where it stopped, nor failed
  // steps it left behind: failed_step = "steady_restart_or_skip").
  const size_t ok = UsableSteps(r);
  std::printf("mesh cycle A..E: %zu of %d steps (%s), grid %zu nodes (%s), %.1f s\n",
              r.steps.size() - 1, r.planned_steps, r.step_rule.c_str(), r.x_m.size(),
              r.grid_rule.c_str(), r.wall_time_s);
  if (r.begin_m > 0 || r.end_m < r.length_m)
    std::printf(
        "tip relief: the tracked pair carries under 1 %% of F_bt before s = %.4g mm and "
        "after %.4g mm (A..E = 0..%.4g mm); the films are solved in between\n",
        r.begin_m * 1e3, r.end_m * 1e3, r.length_m * 1e3);
  const size_t pitch_step = static_cast<size_t>(r.PitchStep());
  const bool passed_pitch = !r.steps.empty() && r.steps.back().s_m >= r.s_c_m;
  if (pitch_step < r.steps.size() && Usable(r, pitch_step) &&
      (passed_pitch || r.steps.size() == static_cast<size_t>(r.planned_steps) + 1)) {
    const MeshCycleStep& pitch = r.steps[pitch_step];
    // The step nearest C, which lies between steps unless the step rule puts one on it.
    const std::string where =
        std::abs(pitch.s_m - r.s_c_m) <= 1e-9 * r.length_m
            ? "at the pitch point (s = " + Fmt("%.4g", pitch.s_m * 1e3) + " mm)"
            : "at the step nearest the pitch point (s = " + Fmt("%.4g", pitch.s_m * 1e3) +
                  " mm; C at " + Fmt("%.4g", r.s_c_m * 1e3) + " mm)";
    std::printf(
        "%s: h_c = %.6g m, h_min = %.6g m, p_max = %.6g Pa (Hertz p_H = %.4g Pa at that "
        "step)\n",
        where.c_str(), pitch.h_c_m, pitch.h_min_m, pitch.p_max_pa,
        LineContactHertz(pitch.load_n_per_m, pitch.reduced_radius_m, r.e_prime_pa).max_pressure_pa);
  } else if (passed_pitch) {
    std::printf("the step at the pitch point (s = %.4g mm) did not converge\n", r.s_c_m * 1e3);
  } else {
    std::printf("the cycle stopped before the pitch point (s = %.4g mm)\n", r.s_c_m * 1e3);
  }
  if (r.thermal && ok > 0) {  // the hottest converged step and the mean friction along the path
    size_t hottest = 0;
    double mu = 0;
    for (size_t k = 0; k < r.steps.size(); ++k) {
      if (!Usable(r, k)) continue;
      if (r.steps[k].t_max_k > r.steps[hottest].t_max_k) hottest = k;
      mu += r.steps[k].friction_coefficient;
    }
    const MeshCycleStep& h = r.steps[hottest];
    std::printf("thermal: T_max = %.5g K at s = %.4g mm (SRR %+.3f), mean mu = %.4g%s, %s\n",
                h.t_max_k, h.s_m * 1e3, h.srr, mu / static_cast<double>(ok),
                ok == r.steps.size() ? "" : " (converged steps)", FilmModelText(r.non_newtonian));
  }
  PrintCycleFlash(r);
  NoteNewtonianFriction(r, [](size_t k, const MeshCycleStep& s) {
    return Where("step %zu, s = %.4g mm", k, s.s_m * 1e3);
  });
  NoteCyclePeclet(r);
  NoteCycleSpikes(r);
  NoteCycleEdges(r);
  NoteCycleInlet(r);
  for (const std::string& n : r.input_notes) std::printf("note: %s\n", n.c_str());
  NoteRestarts(r.steps, [](size_t k, const MeshCycleStep& s) {
    return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
  });
  NoteSplitSteps(r.steps, r.time_tolerance, [](size_t k, const MeshCycleStep& s) {
    return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
  });
  NoteTimeError(r.steps, [](size_t k, const MeshCycleStep& s) {
    return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
  });
  NoteThinFilms(r.steps, [](size_t k, const MeshCycleStep& s) {
    return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
  });
  NoteCutOutlets(r.steps, [](size_t k, const MeshCycleStep& s) {
    return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
  });
  if (r.thermal)
    NoteHotFilms(r.steps, !r.non_newtonian, [](size_t k, const MeshCycleStep& s) {
      return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
    });
  std::printf("wrote %s%s%s\n", r.hdf5_path.c_str(), r.csv_path.empty() ? "" : " and ",
              r.csv_path.c_str());
  if (!r.converged()) {
    ReportFailedSteps(r.steps, [](size_t k, const MeshCycleStep& s) {
      return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
    });
    return kExitNotConverged;
  }
  return kExitOk;
}

int RunContact(const RunArgs& a) {
  ContactRunOptions o;
  o.quiet = a.quiet;
  o.output_dir = a.output_dir;
  std::string case_path = a.case_path;
  if (!a.at.empty()) {  // the point's [contact] case, written beside its results
    const PathPointCase p = WriteContactCaseAtPoint(a.case_path, a.at, a.output_dir);
    std::printf(
        "steady film at %s: s = %.4g mm from A (A..E = %.4g mm), %d pair(s) in contact\n"
        "  R = %.6g m, u1 = %.6g m/s, u2 = %.6g m/s (SRR %+.4f), w = %.6g N/m (%.4f F_bt/b)\n"
        "  case: %s\n",
        p.label.c_str(), p.s_m * 1e3, p.path_length_m * 1e3, p.pairs_in_contact, p.reduced_radius_m,
        p.u1_m_s, p.u2_m_s, p.srr, p.load_n_per_m, p.load_share, p.case_path.c_str());
    std::fflush(stdout);  // before the solve's progress lines on stderr
    case_path = p.case_path;
    o.output_dir.clear();  // the written case names its folder
  }
  const ContactRunResult r = RunContactCase(case_path, o);
  const auto& last = r.steps.back();
  std::printf("grid %d nodes (%s)\n", r.grid_points, r.grid_rule.c_str());
  if (!last.summary.usable())
    std::printf("NOT CONVERGED (%s): the film below is the solver's best iterate, not a result\n",
                ToString(last.summary.termination).c_str());
  std::printf("h_min = %.6g m, h_c = %.6g m, p_max = %.6g Pa", last.h_min_m, last.h_c_m,
              last.p_max_pa);
  if (last.half_width_m > 0)  // elastic: the Hertz pressure beside the film's peak
    std::printf(" (Hertz p_H = %.4g Pa)", 2.0 * last.load_n_per_m / (kPi * last.half_width_m));
  std::printf("\n");
  if (last.summary.usable() && r.thermal)
    std::printf("thermal: T_max = %.5g K (rise %.3g K), %s\n", last.t_max_k,
                last.t_max_k - r.inlet_temperature_k, FilmModelText(r.non_newtonian));
  const bool unphysical_mu =  // the friction note says why; no flash temperature from it
      !r.non_newtonian && last.friction_coefficient > kNewtonianFrictionNote;
  if (last.summary.usable() && last.flash_rise_blok_k > 0 && unphysical_mu) {
    std::printf("mu = %.4g (%s, not physical: note below); no flash temperature from it\n",
                last.friction_coefficient, FilmModelText(r.non_newtonian));
  } else if (last.summary.usable() && last.flash_rise_blok_k > 0) {  // sliding, elastic
    std::printf("mu = %.4g (%s); flash temperature (Blok%s, with this mu): rise %.3g K",
                last.friction_coefficient, FilmModelText(r.non_newtonian),
                r.finite_peclet ? ", finite Peclet" : "", last.flash_rise_blok_k);
    if (last.t_max_k > r.inlet_temperature_k)  // thermal: the film's own surfaces beside it
      std::printf("; the film's surfaces: max rise %.3g K (body 1), %.3g K (body 2)",
                  last.t1_max_k - r.inlet_temperature_k, last.t2_max_k - r.inlet_temperature_k);
    std::printf("\n");
  }
  if (last.summary.usable()) {
    NoteContactSpike(last.outlet_spike);
    NoteContactEdge(last.hertz_edge);
    NoteContactInlet(last.inlet, r.x_start_b, {r.x_start_m, r.x_end_m, r.grid_points});
  }
  for (const std::string& n : r.input_notes) std::printf("note: %s\n", n.c_str());
  NoteContactPeclet(r);
  NoteNewtonianFriction(r, [](size_t k, const ContactStepRecord& s) {
    return Where("step %zu, t = %.4g s", k, s.time_s);
  });
  NoteRestarts(r.steps, [](size_t k, const ContactStepRecord& s) {
    return Where("step %zu (t = %.4g s)", k, s.time_s);
  });
  NoteSplitSteps(r.steps, r.time_tolerance, [](size_t k, const ContactStepRecord& s) {
    return Where("step %zu, t = %.4g s", k, s.time_s);
  });
  NoteTimeError(r.steps, [](size_t k, const ContactStepRecord& s) {
    return Where("step %zu (t = %.4g s)", k, s.time_s);
  });
  NoteThinFilms(r.steps, [](size_t k, const ContactStepRecord& s) {
    return Where("step %zu (t = %.4g s)", k, s.time_s);
  });
  NoteCutOutlets(r.steps, [](size_t k, const ContactStepRecord& s) {
    return Where("step %zu (t = %.4g s)", k, s.time_s);
  });
  if (r.thermal)
    NoteHotFilms(r.steps, !r.non_newtonian, [](size_t k, const ContactStepRecord& s) {
      return Where("step %zu (t = %.4g s)", k, s.time_s);
    });
  if (r.profile_csv.empty())
    std::printf("wrote %s\n", r.history_csv.c_str());
  else
    std::printf("wrote %s and %s\n", r.profile_csv.c_str(), r.history_csv.c_str());
  if (!r.converged()) {
    ReportFailedSteps(r.steps, [](size_t k, const ContactStepRecord& s) {
      return Where("step %zu (t = %.4g s)", k, s.time_s);
    });
    return kExitNotConverged;
  }
  return kExitOk;
}

// --at P1,P2,...: each point in turn (every point is checked before any is solved); the exit
// code is the worst.
int RunPoints(const RunArgs& a) {
  std::vector<std::string> points;
  std::string item;
  for (char ch : a.at + ",") {
    if (ch != ',') {
      item += ch;
    } else if (!item.empty()) {
      points.push_back(item);
      item.clear();
    }
  }
  // Every point is checked (exit 2 on a bad one) before any is solved.
  if (points.size() > 1)
    for (const std::string& p : points) (void)ContactCaseAtPoint(a.case_path, p, a.output_dir);
  int worst = kExitOk;
  for (size_t i = 0; i < points.size(); ++i) {
    if (i > 0) std::printf("\n");
    RunArgs one = a;
    one.at = points[i];
    worst = std::max(worst, RunContact(one));
  }
  return worst;
}

}  // namespace

Command AddRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* sub = app.add_subcommand(
      "run", "Run a case: the mesh cycle of a [gear] case, or a [contact] line contact");
  sub->add_option("CASE", args->case_path, "Case file (.toml)")->required();
  sub->add_option("-o,--output-dir", args->output_dir, "Folder for the results ([output])");
  sub->add_flag("-q,--quiet", args->quiet, "No progress line on stderr");
  sub->add_flag("--resume", args->resume,
                "Mesh cycle: leave a complete result alone, else continue from its checkpoint");
  sub->add_option("--checkpoint-every", args->checkpoint_every,
                  "Mesh cycle: write a checkpoint every N steps (0 = never)")
      ->check(CLI::Range(0, 10000000));
  sub->add_option("--at", args->at,
                  "Gear case: the steady film at points of the path instead of the cycle: A, "
                  "B, C, D, E or a distance from A (2.5mm), several separated by commas "
                  "(A,C,E); writes NAME_at_POINT.toml, the [contact] case of each point, beside "
                  "its results")
      ->excludes("--resume");
  return {sub, [args]() {
            if (!args->at.empty()) return RunPoints(*args);
            // The scene is chosen by the section the file has; each scene reports every
            // problem of its own (a file with neither section is reported by the contact
            // scene, which names both).
            const internal::Document doc = internal::ReadCaseDocument(args->case_path);
            const bool gear = doc.HasSection("gear") || doc.HasSection("gear.pinion") ||
                              doc.HasSection("gear.wheel");
            return gear && !doc.HasSection("contact") ? RunGear(*args) : RunContact(*args);
          }};
}

}  // namespace tehl::cli
