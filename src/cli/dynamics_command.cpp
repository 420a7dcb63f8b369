// tehl dynamics CASE [--speeds FROM:TO:STEP [--sweep-start static|up|down]] [-o DIR]
//                    [--threads N] [--no-plot]
// Torsional dynamics of the gear pair of a case (docs/dynamics.md): frequencies, the periodic
// response at the case's speed (mesh force over a period, the tracked pair's dynamic load
// along the path) and, with --speeds, the dynamic load factor against the pinion speed as a
// CSV and a PNG (scripts/plot_dynamics.py).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/number_format.hpp"
#include "cli/python_script.hpp"
#include "io/csv_table.hpp"
#include "scene/case_reader.hpp"
#include "scene/dynamic_load.hpp"
#include "scene/gear_case.hpp"
#include "tehl/drive/dynamic_sweep.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {
namespace {
namespace fs = std::filesystem;

// "from:to:step" in rpm -> the speeds; throws InputError naming --speeds.
std::vector<double> ParseSpeeds(const std::string& text) {
  double a = 0, b = 0, h = 0;
  char c1 = 0, c2 = 0, extra = 0;
  std::istringstream in(text);
  const bool parsed =
      static_cast<bool>(in >> a >> c1 >> b >> c2 >> h) && c1 == ':' && c2 == ':' && !(in >> extra);
  const double count = parsed && h > 0 ? std::floor((b - a) / h + 1e-9) + 1 : 0;
  // 1e6 rpm: beyond every gear drive (turbine gears run up to about 1e5 rpm).
  if (!parsed || !(a > 0) || !(b >= a) || !(b <= 1e6) || !(h > 0) || count > 100000)
    throw InputError(InputProblem{"", 0, "--speeds", "\"" + text + "\"",
                                  "must be FROM:TO:STEP in rpm with 0 < FROM <= TO <= 1e6, "
                                  "STEP > 0 and at most 100000 speeds",
                                  "e.g. 500:20000:100"});
  std::vector<double> v;
  for (int i = 0; i < static_cast<int>(count); ++i) v.push_back(a + i * h);
  return v;
}

// The sweep's fastest speed within the pitch-line speeds a case accepts (kMaxPitchLineSpeed,
// src/scene/gear_case.hpp): the same limit for both ways of giving a speed.
void CheckSweepPitchLineSpeed(const std::string& text,
                              const std::vector<double>& speeds_rpm,
                              double pitch_radius_m) {
  if (speeds_rpm.empty()) return;
  const double top = *std::max_element(speeds_rpm.begin(), speeds_rpm.end());
  const double per_rpm = RpmToRadPerS(1.0) * pitch_radius_m;
  if (top * per_rpm <= internal::kMaxPitchLineSpeed) return;
  throw InputError(InputProblem{
      "", 0, "--speeds", "\"" + text + "\"",
      "its fastest speed, " + cli::Fmt("%.0f", top) + " rpm, is a pitch-line speed of " +
          cli::Fmt("%.1f", top * per_rpm) + " m/s, beyond the " +
          cli::Fmt("%.0f", internal::kMaxPitchLineSpeed) + " m/s of gear drives",
      "speeds up to " + cli::Fmt("%.0f", std::floor(internal::kMaxPitchLineSpeed / per_rpm)) +
          " rpm for this pinion (the limit of [operating] pinion_speed_rpm)"});
}

int RunPlot(const std::string& csv, const std::string& png, const std::string& title) {
  return RunPythonScript("tehl dynamics", "plot_dynamics.py", {csv, "-o", png, "--labels", title});
}

void Report(std::ostream& o,
            const internal::GearCase& c,
            const internal::DynamicsCase& d,
            const TorsionalModel& m,
            const DynamicResponse& r) {
  const TorsionalMesh& mesh = m.mesh();
  const TorsionalParameters& p = d.params;
  char buf[2048];
  const double nr = 60.0 * m.natural_frequency_hz() / mesh.pinion_teeth();
  std::snprintf(buf, sizeof buf,
                "Torsional model (seed 000 eqs. 4.1-4.2, SI):\n"
                "  J1 = %.6g kg m^2 (%s), J2 = %.6g kg m^2 (%s)\n"
                "  r_b1 = %.4f mm, r_b2 = %.4f mm, equivalent mass m_e = %.6g kg\n"
                "  mesh stiffness (%s): mean %.4g, min %.4g, max %.4g N/m\n"
                "  damping ratio %.4g -> c = %.6g N s/m; backlash %.4g um (%s); friction %s\n"
                "  static mesh force F_s = T1 / r_b1 = %.4f N\n"
                "  natural frequency f_n = %.2f Hz; resonance where f_mesh = f_n at %.1f rpm "
                "(f_n/2: %.1f rpm, f_n/3: %.1f rpm)\n",
                p.pinion_inertia_kg_m2, d.inertia_from_blanks[0] ? "solid disc" : "given",
                p.wheel_inertia_kg_m2, d.inertia_from_blanks[1] ? "solid disc" : "given",
                mesh.pinion_base_radius_m() * 1e3, mesh.wheel_base_radius_m() * 1e3,
                m.equivalent_mass_kg(), c.mesh_stiffness.c_str(), mesh.mean_stiffness_n_per_m(),
                mesh.min_stiffness_n_per_m(), mesh.max_stiffness_n_per_m(), p.damping_ratio,
                m.damping_n_s_per_m(), p.backlash_m * 1e6,
                d.backlash_from_geometry ? "from the centre distance" : "given",
                (ToString(p.friction) + (p.friction == FrictionLaw::kConstant
                                             ? " mu = " + std::to_string(p.friction_coefficient)
                                             : std::string()))
                    .c_str(),
                m.static_force_n(), m.natural_frequency_hz(), nr, nr / 2, nr / 3);
  o << buf;
  if (mesh.corner_contact()) {
    // Under F_s the pairs touch beyond A and E: the loaded mesh is stiffer than the nominal
    // mean, and the resonance lies higher. Mean of F_s / x_s over 400 phases.
    double k_loaded = 0;
    const double pb = mesh.base_pitch_m(), fs = m.static_force_n();
    for (int i = 0; i < 400; ++i)
      k_loaded += fs / mesh.StaticApproachAt(pb * (i + 0.5) / 400, false, fs) / 400;
    const double f_loaded = std::sqrt(k_loaded / m.equivalent_mass_kg()) / (2 * kPi);
    std::snprintf(buf, sizeof buf,
                  "  corner contact: pairs mesh beyond A and E where the approach exceeds the "
                  "separation of their tip corner (followed %.3f mm before A and %.3f mm after "
                  "E); under F_s the mean mesh stiffness is %.4g N/m (f_n %.2f Hz, resonance "
                  "near %.1f rpm)\n",
                  mesh.corner_before_m() * 1e3, mesh.corner_after_m() * 1e3, k_loaded, f_loaded,
                  60.0 * f_loaded / mesh.pinion_teeth());
    o << buf;
  }
  if (const TorsionalMesh* back = mesh.back_flanks()) {
    std::snprintf(buf, sizeof buf,
                  "  back flanks (the coast flanks, %.1f deg): base circles K = %.4f times the "
                  "drive flanks', mesh stiffness mean %.4g, min %.4g, max %.4g N/m, contact "
                  "ratio %.4f, c = %.6g N s/m on their closure; their contacts run from E to A, "
                  "at s_c / p_bc = %.4f - phi / p_b\n",
                  RadToDeg(c.spec.coast_pressure_angle_rad), mesh.back_ratio(),
                  back->mean_stiffness_n_per_m(), back->min_stiffness_n_per_m(),
                  back->max_stiffness_n_per_m(), back->contact_ratio(), m.back_damping_n_s_per_m(),
                  mesh.back_phase_offset());
    o << buf;
  }
  const TipRelief& relief = mesh.relief();
  if (relief.Active()) {
    std::snprintf(buf, sizeof buf,
                  "  tip relief on both flanks: pinion %.2f um over %.3f mm (%s), wheel "
                  "%.2f um over %.3f mm (%s); each pair carries k (x - e), e its relief gap\n",
                  relief.pinion_amount_m * 1e6, relief.pinion_length_m * 1e3,
                  ToString(relief.pinion_shape).c_str(), relief.wheel_amount_m * 1e6,
                  relief.wheel_length_m * 1e3, ToString(relief.wheel_shape).c_str());
    o << buf;
  }
  std::snprintf(buf, sizeof buf,
                "At the case's speed %.2f rpm: mesh frequency f_mesh = %.2f Hz (f_mesh/f_n = "
                "%.4f)\n"
                "  %s; integrator: %ld steps (%ld rejected), %ld contact events\n"
                "  dynamic load factor (peak F / F_s) = %.4f; min F = %.4f N; separated %.1f %% "
                "and back flank %.1f %% of the period\n",
                RadPerSToRpm(p.pinion_speed_rad_s), r.mesh_frequency_hz,
                r.mesh_frequency_hz / r.natural_frequency_hz, r.message.c_str(),
                r.integrator.accepted_steps, r.integrator.rejected_steps, r.integrator.state_events,
                r.dynamic_load_factor, r.min_force_n, 100 * r.separated_fraction,
                100 * r.back_flank_fraction);
  o << buf;
}

// The period and path tables of the response at the case's speed.
void WritePeriodTables(std::ostringstream& o,
                       const fs::path& dir,
                       const std::string& name,
                       const internal::GearCase& c,
                       const DynamicResponse& r) {
  std::vector<internal::CsvColumn> period(7);
  const char* ph[] = {"phase_m", "t_s", "x_m", "v_m_s", "force_n", "k_mesh_n_per_m", "state"};
  for (int i = 0; i < 7; ++i) period[i].header = ph[i];
  for (const DynamicSample& s : r.samples) {
    const double v[] = {s.phase_m,
                        s.time_s,
                        s.x_m,
                        s.v_m_s,
                        s.force_n,
                        s.stiffness_n_per_m,
                        static_cast<double>(s.state)};
    for (int i = 0; i < 7; ++i) period[i].values.push_back(v[i]);
  }
  const std::string period_csv = (dir / (name + "_dynamics_period.csv")).string();
  internal::WriteCsvTable(period_csv, period);
  std::vector<internal::CsvColumn> path(4);
  const char* pa[] = {"s_m", "share", "w_static_n_per_m", "w_dynamic_n_per_m"};
  for (int i = 0; i < 4; ++i) path[i].header = pa[i];
  for (const PairLoadPoint& q : TrackedPairLoad(r, c.spec.face_width_m, 201)) {
    const double v[] = {q.s_m, q.share, q.static_n_per_m, q.dynamic_n_per_m};
    for (int i = 0; i < 4; ++i) path[i].values.push_back(v[i]);
  }
  const std::string path_csv = (dir / (name + "_dynamics_path.csv")).string();
  internal::WriteCsvTable(path_csv, path);
  o << "wrote " << period_csv << "\nwrote " << path_csv << "\n";
  std::cout << o.str() << std::flush;
}

}  // namespace

Command AddDynamicsCommand(CLI::App& app) {
  struct Args {
    std::string case_file, speeds, output_dir, sweep_start = "static";
    int threads = 1;
    bool no_plot = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "dynamics",
      "Torsional dynamics of the gear pair of a case: natural and mesh frequencies, dynamic "
      "mesh force and tooth load, dynamic load factor against speed");
  sub->add_option("CASE", args->case_file, "Case file with [gear] and [operating]")->required();
  CLI::Option* speeds_option =
      sub->add_option("--speeds", args->speeds,
                      "Pinion speed sweep FROM:TO:STEP [rpm], e.g. 500:20000:100: writes "
                      "NAME_dynamics_sweep.csv and NAME_dynamics.png");
  sub->add_option("--sweep-start", args->sweep_start,
                  "How each speed of the sweep starts: static (from the static deflection, "
                  "speeds in parallel), up or down (continuation: from FROM up or from TO down, "
                  "each speed from the periodic response of the one before, following a branch "
                  "through a jump)")
      ->check(CLI::IsMember({"static", "up", "down"}))
      ->needs(speeds_option);
  sub->add_option("-o,--output-dir", args->output_dir,
                  "Folder for the files (default: [output] directory of the case)");
  sub->add_option("--threads", args->threads, "Threads for the sweep")->check(CLI::Range(1, 256));
  sub->add_flag("--no-plot", args->no_plot, "Write the CSV files only");
  return {
      sub, [args, speeds_option]() {
        std::vector<double> speeds;
        if (!args->speeds.empty() || speeds_option->count() > 0) speeds = ParseSpeeds(args->speeds);
        internal::Document doc = internal::ReadCaseDocument(args->case_file);
        // The films' dynamic load (effect dynamic_load) is not this command's: its model runs
        // at any speed, also where the drive flanks unload.
        std::optional<internal::GearCase> c = internal::ReadGearCase(doc, false);
        doc.ThrowIfProblems();
        if (!c || !c->pair || !c->pair_stiffness) {
          doc.Problem("gear", "", "the gear pair could not be built", "a valid gear pair");
          doc.ThrowIfProblems();
        }
        const internal::DynamicsCase d = internal::ReadDynamicsCase(doc, *c);
        doc.ThrowIfProblems();
        CheckSweepPitchLineSpeed(args->speeds, speeds, c->pair->pinion().pitch_radius_m);
        const std::unique_ptr<TorsionalMesh> mesh = internal::MakeTorsionalMesh(*c, d);
        TorsionalModel model(*mesh, d.params);
        const DynamicResponse r = SolvePeriodicResponse(model, d.options);

        const fs::path dir = args->output_dir.empty() ? fs::path(doc.String("output", "directory"))
                                                      : fs::path(args->output_dir);
        std::string name = doc.String("output", "name");
        if (name.empty()) name = fs::path(args->case_file).stem().string();
        fs::create_directories(dir);
        std::ostringstream o;
        o << "tehl dynamics: " << args->case_file << "\n";
        Report(o, *c, d, model, r);
        // No response at the case's speed: no period or path table, exit 1; a sweep asked for
        // still runs (its speeds are other runs).
        const bool failed = !r.integrator.usable() || r.steps.empty() || r.diverged;
        if (failed) {
          std::cout << o.str() << std::flush;
          if (r.diverged)
            std::fprintf(stderr, "tehl dynamics: at the case's speed %s\n", r.message.c_str());
          else
            std::fprintf(stderr, "tehl dynamics: the integration failed: %s\n", r.message.c_str());
          if (speeds.empty()) return kExitNotConverged;
          std::fprintf(stderr, "tehl dynamics: no period or path table; the sweep goes on\n");
        }
        if (!failed) WritePeriodTables(o, dir, name, *c, r);
        if (speeds.empty()) return kExitOk;

        const bool continuation = args->sweep_start != "static";
        if (args->sweep_start == "down") std::reverse(speeds.begin(), speeds.end());
        const std::vector<SweepPoint> sweep =
            SweepSpeeds(*mesh, d.params, speeds, d.options, args->threads,
                        continuation ? SweepStart::kContinuation : SweepStart::kStatic);
        // The sweep holds the case's pinion torque (the power grows with the speed).
        std::vector<internal::CsvColumn> t(13);
        const char* th[] = {
            "pinion_speed_rpm", "mesh_frequency_hz",    "dynamic_load_factor", "pair_load_factor",
            "min_force_n",      "separated_fraction",   "back_flank_fraction", "periodic",
            "periods",          "natural_frequency_hz", "resonance_rpm",       "pinion_torque_nm",
            "diverged"};
        for (int i = 0; i < 13; ++i) t[i].header = th[i];
        for (int i : {7, 8, 12}) t[i].integer = true;  // periodic, periods, diverged
        int not_periodic = 0, diverged = 0;
        for (const SweepPoint& s : sweep) {
          const double v[] = {s.pinion_speed_rpm,
                              s.mesh_frequency_hz,
                              s.dynamic_load_factor,
                              s.pair_load_factor,
                              s.min_force_n,
                              s.separated_fraction,
                              s.back_flank_fraction,
                              s.periodic ? 1.0 : 0.0,
                              static_cast<double>(s.periods),
                              r.natural_frequency_hz,
                              60.0 * r.natural_frequency_hz / mesh->pinion_teeth(),
                              d.params.pinion_torque_nm,
                              s.diverged ? 1.0 : 0.0};
          for (int i = 0; i < 13; ++i) t[i].values.push_back(v[i]);
          not_periodic += !s.periodic;
          diverged += s.diverged;
        }
        // Continuation sweeps keep their own files: up and down are compared with each other.
        const std::string tag = continuation ? "_" + args->sweep_start : "";
        const std::string sweep_csv = (dir / (name + "_dynamics_sweep" + tag + ".csv")).string();
        internal::WriteCsvTable(sweep_csv, t);
        // The largest factor of the responses that stay bounded: one that grows without bound
        // has none (a bounded response that is not periodic keeps its last period's).
        size_t peak = sweep.size();
        for (size_t i = 0; i < sweep.size(); ++i)
          if (!sweep[i].diverged && (peak == sweep.size() || sweep[i].dynamic_load_factor >
                                                                 sweep[peak].dynamic_load_factor))
            peak = i;
        const std::string largest =
            peak < sweep.size()
                ? "largest dynamic load factor " + Fmt("%.4f", sweep[peak].dynamic_load_factor) +
                      " at " + Fmt("%.1f", sweep[peak].pinion_speed_rpm) + " rpm"
                : std::string("no bounded response");
        std::printf("sweep%s: %zu speeds, %s; %d not periodic in one mesh period\nwrote %s\n",
                    continuation ? (" (continuation " + args->sweep_start + ")").c_str() : "",
                    sweep.size(), largest.c_str(), not_periodic, sweep_csv.c_str());
        if (diverged > 0) {
          size_t first = 0;
          while (!sweep[first].diverged) ++first;
          std::printf(
              "note: at %d speeds (the first %.1f rpm) the response grows without bound: "
              "the mesh's stiffness variation pumps it (parametric instability; "
              "docs/dynamics.md \"Back flanks\"); [dynamics] corner_contact = true or a "
              "larger damping_ratio bounds it; the CSV's diverged column marks them\n",
              diverged, sweep[first].pinion_speed_rpm);
        }
        if (args->no_plot) return failed ? kExitNotConverged : kExitOk;
        const std::string png = (dir / (name + "_dynamics" + tag + ".png")).string();
        const std::string label =
            continuation ? name + " (continuation " + args->sweep_start + ")" : name;
        const int rc = RunPlot(sweep_csv, png, label);
        if (rc == kExitOk) std::printf("wrote %s\n", png.c_str());
        return failed && rc == kExitOk ? kExitNotConverged : rc;
      }};
}

}  // namespace tehl::cli
