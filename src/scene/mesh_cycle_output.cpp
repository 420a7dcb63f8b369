#include "scene/mesh_cycle_output.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "io/csv_table.hpp"
#include "scene/case_reader.hpp"

namespace tehl::internal {
namespace {

// One column of /cycle: name, unit, meaning and how to read it from a step.
struct CycleColumn {
  const char* name;
  const char* unit;
  const char* meaning;
  std::function<double(const MeshCycleStep&)> get;
  bool thermal = false;  // written only by thermal runs
};

const std::vector<CycleColumn>& CycleColumns() {
  static const std::vector<CycleColumn> cols = {
      {"s", "m", "distance of the contact from A along the line of action",
       [](const MeshCycleStep& k) { return k.s_m; }},
      {"t", "s", "time since A, t = s / (r_b1 w1)",
       [](const MeshCycleStep& k) { return k.time_s; }},
      {"R", "m", "reduced radius of curvature, 1/R = 1/rho1 + 1/rho2",
       [](const MeshCycleStep& k) { return k.reduced_radius_m; }},
      {"u1", "m/s", "pinion surface speed", [](const MeshCycleStep& k) { return k.u1_m_s; }},
      {"u2", "m/s", "wheel surface speed", [](const MeshCycleStep& k) { return k.u2_m_s; }},
      {"um", "m/s", "entrainment speed (u1 + u2)/2",
       [](const MeshCycleStep& k) { return k.um_m_s; }},
      {"SRR", "-", "slide-to-roll ratio (u1 - u2)/um",
       [](const MeshCycleStep& k) { return k.srr; }},
      {"w", "N/m", "load per unit face width on the tracked pair",
       [](const MeshCycleStep& k) { return k.load_n_per_m; }},
      {"w_static", "N/m", "load of the tracked pair by the static load sharing (= w unless "
       "dynamic_load is on)", [](const MeshCycleStep& k) { return k.static_load_n_per_m; }},
      {"h_min", "m", "minimum film thickness", [](const MeshCycleStep& k) { return k.h_min_m; }},
      {"h_c", "m", "central film thickness (x = 0)",
       [](const MeshCycleStep& k) { return k.h_c_m; }},
      {"p_max", "Pa", "maximum film pressure", [](const MeshCycleStep& k) { return k.p_max_pa; }},
      {"mu", "-", "friction coefficient, mean traction of both surfaces / w (seed 004 eq. 16)",
       [](const MeshCycleStep& k) { return k.friction_coefficient; }},
      {"T_max", "K", "hottest film temperature",
       [](const MeshCycleStep& k) { return k.t_max_k; }, true},
      {"T_mid", "K", "hottest mid-film temperature",
       [](const MeshCycleStep& k) { return k.t_mid_max_k; }, true},
      {"T1_max", "K", "hottest pinion surface temperature",
       [](const MeshCycleStep& k) { return k.t1_max_k; }, true},
      {"T2_max", "K", "hottest wheel surface temperature",
       [](const MeshCycleStep& k) { return k.t2_max_k; }, true},
      {"C_RT", "-", "R / R0, R0 at the pitch point (seed 004 Fig. 3)",
       [](const MeshCycleStep& k) { return k.c_rt; }},
      {"C_UT", "-", "um / u0, u0 at the pitch point (seed 004 Fig. 3)",
       [](const MeshCycleStep& k) { return k.c_ut; }},
      {"C_WT", "-", "w / w0, w0 at the pitch point (seed 004 Fig. 3)",
       [](const MeshCycleStep& k) { return k.c_wt; }},
  };
  return cols;
}

constexpr const char* kBlokMeaning =
    "Blok flash temperature rise with this step's mu, w, speeds and Hertz half-width: the "
    "friction heat released over the Hertz zone, both surfaces at the same peak rise, at high "
    "Peclet number or, with effects.finite_peclet, Jaeger's kernel (docs/thermal.md \"Flash "
    "temperature\"; -1: rigid solids)";

std::vector<double> Column(const MeshCycleResult& r, const CycleColumn& c) {
  std::vector<double> v;
  for (const auto& k : r.steps) v.push_back(c.get(k));
  return v;
}

std::vector<double> Flatten(const std::vector<std::vector<double>>& rows) {
  std::vector<double> out;
  for (const auto& row : rows) out.insert(out.end(), row.begin(), row.end());
  return out;
}

}  // namespace

std::unique_ptr<Hdf5Writer> BeginMeshCycleHdf5(const std::string& path,
                                               const Document& doc,
                                               const std::string& case_path) {
  auto h5 = std::make_unique<Hdf5Writer>(path);
  h5->SetAttribute("/", "program", "tehl 0.1.0");
  {
    std::error_code ec;  // absolute, as lubricant_file: the file is read from anywhere
    const std::filesystem::path full = std::filesystem::absolute(case_path, ec);
    h5->SetAttribute("/", "case_file", ec ? case_path : full.lexically_normal().string());
  }
  h5->WriteText("/case", doc.ToToml(), "the case as run, defaults filled (TOML)");
  // The lubricant file as read, so that the result file alone reproduces the run.
  const std::string lubricant = ResolveLubricantPath(doc.String("lubricant", "name"), doc.path());
  if (!lubricant.empty()) {
    std::error_code ec;
    const std::filesystem::path full = std::filesystem::absolute(lubricant, ec);
    h5->SetAttribute("/", "lubricant_file", ec ? lubricant : full.lexically_normal().string());
    std::ifstream in(lubricant, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    h5->WriteText("/lubricant", text.str(), "the lubricant file as read (TOML)");
  }
  return h5;
}

void FinishMeshCycleHdf5(Hdf5Writer& h5, const MeshCycleResult& r, bool profiles) {
  h5.SetAttribute("/", "converged", r.converged() ? "true" : "false");
  h5.SetAttribute("/", "step_rule", r.step_rule);
  h5.SetAttribute("/", "grid_rule", r.grid_rule);
  h5.SetAttribute("/", "wall_time", r.wall_time_s, "s");
  h5.SetIntAttribute("/", "resumed_from_step", r.resumed_from_step);
  h5.SetIntAttribute("/", "steady_restarts", r.Restarts());

  for (const auto& c : CycleColumns())
    if (!c.thermal || r.thermal)
      h5.WriteVector(std::string("/cycle/") + c.name, Column(r, c), c.unit, c.meaning);
  std::vector<int> pairs;
  std::vector<std::string> zones;
  for (const auto& k : r.steps) {
    pairs.push_back(k.pairs_in_contact);
    zones.push_back(k.zone);
  }
  h5.WriteInts("/cycle/pairs_in_contact", pairs, "tooth pairs sharing the load");
  // The outlet spike's width at half prominence (FindOutletSpike; docs/results.md): under
  // kSpikeResolvedCells the step's p_max is not grid-converged.
  if (r.p_pa.size() == r.steps.size()) {
    std::vector<double> cells;
    for (const OutletSpike& spike : r.OutletSpikes())
      cells.push_back(spike.found ? spike.width_cells : -1.0);
    h5.WriteVector("/cycle/spike_cells", cells, "-",
                   "width of the outlet pressure spike at half its prominence, in grid cells "
                   "(-1: no spike); below 20 the step's p_max is not grid-converged");
  }
  // The Hertzian edge's width (EstimateHertzEdge; docs/results.md): under kEdgeResolvedCells
  // the step's film is likely too thin.
  {
    std::vector<double> cells;
    for (const HertzEdge& e : r.HertzEdges()) cells.push_back(e.width_m > 0 ? e.width_cells : -1.0);
    if (cells.size() == r.steps.size())
      h5.WriteVector("/cycle/edge_cells", cells, "-",
                     "width of the film's Hertzian edge b (3 R h_c / (2 sqrt(2) b^2))^(2/3) in "
                     "grid cells (-1: rigid solids or no film); below 10 h_c is likely too thin "
                     "by more than 1 %");
  }
  // What the truncated inlet costs the film (EstimateInletTruncation; docs/results.md).
  if (r.p_pa.size() == r.steps.size() && r.h_m.size() == r.steps.size()) {
    std::vector<double> deficit;
    for (const InletTruncation& t : r.InletTruncations())
      deficit.push_back(t.estimated ? t.film_deficit : -1.0);
    h5.WriteVector("/cycle/inlet_deficit", deficit, "-",
                   "estimated film deficit of the truncated inlet, 1 - h/h(unbounded inlet) "
                   "(-1: no estimate, e.g. an isoviscous film)");
  }
  h5.WriteVector("/cycle/dT_flash_blok", r.BlokFlashRises(), "K", kBlokMeaning);
  h5.WriteStrings("/cycle/zone", zones, "segment of the path: A-B, B-D or D-E");
  h5.SetAttribute("/cycle", "length", r.length_m, "m");
  h5.SetAttribute("/cycle", "s_begin", r.begin_m, "m");  // A' (0 = A)
  h5.SetAttribute("/cycle", "s_end", r.end_m, "m");      // E' (length = E)
  h5.SetAttribute("/cycle", "s_B", r.s_b_m, "m");
  h5.SetAttribute("/cycle", "s_C", r.s_c_m, "m");
  h5.SetAttribute("/cycle", "s_D", r.s_d_m, "m");
  h5.SetAttribute("/cycle", "R0", r.r0_m, "m");
  h5.SetAttribute("/cycle", "u0", r.u0_m_s, "m/s");
  h5.SetAttribute("/cycle", "w0", r.w0_n_per_m, "N/m");
  h5.SetAttribute("/cycle", "T0", r.inlet_temperature_k, "K");
  h5.SetIntAttribute("/cycle", "planned_steps", r.planned_steps);

  h5.WriteVector("/profiles/x", r.x_m, "m", "grid nodes, x = 0 at the contact point");
  h5.SetAttribute("/profiles", "b_max", r.max_half_width_m, "m");
  if (profiles) {
    const int rows = static_cast<int>(r.p_pa.size());
    const int cols = static_cast<int>(r.x_m.size());
    h5.WriteMatrix("/profiles/p", Flatten(r.p_pa), rows, cols, "Pa",
                   "film pressure over (step, x)");
    h5.WriteMatrix("/profiles/h", Flatten(r.h_m), rows, cols, "m", "film thickness over (step, x)");
    if (r.thermal && r.t_mid_k.size() == r.p_pa.size()) {
      h5.WriteMatrix("/profiles/T_mid", Flatten(r.t_mid_k), rows, cols, "K",
                     "mid-film temperature over (step, x)");
      h5.WriteMatrix("/profiles/T1", Flatten(r.t1_k), rows, cols, "K",
                     "pinion surface temperature over (step, x)");
      h5.WriteMatrix("/profiles/T2", Flatten(r.t2_k), rows, cols, "K",
                     "wheel surface temperature over (step, x)");
    }
  }
  if (r.thermal && !r.t_field_k.empty() && r.t_field_k.size() == r.p_pa.size()) {
    h5.WriteMatrix("/profiles/T", Flatten(r.t_field_k), static_cast<int>(r.t_field_k.size()),
                   static_cast<int>(r.x_m.size()) * r.film_nodes, "K",
                   "film temperature over (step, x, z): row k holds T(x_i, z_j) at index "
                   "i * film_nodes + j, z_j = j h / (film_nodes - 1) from the pinion surface");
    h5.SetIntAttribute("/profiles/T", "film_nodes", r.film_nodes);
  }

  std::vector<std::string> termination, message, restart_reason;
  std::vector<int> iterations, substeps, restarted, converged;
  std::vector<double> residual, wall, load_error, time_error;
  for (const auto& k : r.steps) {
    termination.push_back(ToString(k.summary.termination));
    converged.push_back(k.summary.usable() ? 1 : 0);
    message.push_back(k.summary.message);
    restarted.push_back(k.restarted() ? 1 : 0);
    restart_reason.push_back(k.restart_reason);
    iterations.push_back(k.summary.total_iterations);
    substeps.push_back(k.summary.substeps);
    residual.push_back(k.summary.residual);
    load_error.push_back(k.summary.load_error);
    wall.push_back(k.summary.wall_time_s);
    time_error.push_back(k.summary.time_error);
  }
  h5.WriteStrings("/solver/termination", termination, "how each step's solve ended");
  h5.WriteInts("/solver/converged", converged,
               "1: the step's film converged (a steady restart counts), 0: it did not");
  h5.WriteStrings("/solver/message", message, "the solver's summary message per step");
  h5.WriteInts("/solver/steady_restart", restarted,
               "1: the transient step failed and the film is the steady one at this point "
               "([numerics] failed_step)");
  h5.WriteStrings("/solver/restart_reason", restart_reason,
                  "the failed transient step's termination and message (empty: no restart)");
  h5.WriteInts("/solver/iterations", iterations, "Newton iterations per step (all stages)");
  h5.WriteInts("/solver/substeps", substeps, "time substeps a step needed");
  h5.WriteVector("/solver/residual", residual, "-", "final scaled residual max-norm");
  h5.WriteVector("/solver/load_error", load_error, "-", "|integral p dx - w| / w");
  h5.WriteVector("/solver/wall_time", wall, "s", "wall time of each step's solve");
  h5.WriteVector("/solver/time_error", time_error, "-",
                 "estimated local time error of rho h per step, relative (-1: not estimated)");
  if (r.thermal) {
    std::vector<int> coupling;
    std::vector<double> change, balance;
    for (const auto& k : r.steps) {
      coupling.push_back(k.summary.coupling_iterations);
      change.push_back(k.summary.temperature_change_k);
      balance.push_back(k.summary.energy_balance_error);
    }
    h5.WriteInts("/solver/coupling_iterations", coupling,
                 "pressure/temperature coupling iterations per step");
    h5.WriteVector("/solver/temperature_change", change, "K",
                   "last temperature change of the coupling (-1: not reached)");
    h5.WriteVector("/solver/energy_balance_error", balance, "-",
                   "relative energy balance error of the film (-1: not reached)");
  }
  h5.Commit();
}

void WriteMeshCycleCsv(const std::string& path, const MeshCycleResult& r) {
  const auto& cols = CycleColumns();
  std::vector<CsvColumn> table;
  for (const auto& c : cols) {
    if (c.thermal && !r.thermal) continue;
    // Header = name and unit as in the case keys: s_m, u1_m_s, w_n_per_m, p_max_pa, SRR.
    const std::string unit = c.unit;
    const std::string suffix = unit == "-"     ? ""
                               : unit == "m/s" ? "_m_s"
                               : unit == "N/m" ? "_n_per_m"
                               : unit == "Pa"  ? "_pa"
                               : unit == "K"   ? "_k"
                                               : "_" + unit;
    table.push_back({std::string(c.name) + suffix, Column(r, c)});
    if (std::string(c.name) == "mu") table.push_back({"dT_flash_blok_k", r.BlokFlashRises()});
  }
  // Whether each row's solve converged (1) or not (0): a run that stops writes its last,
  // unconverged step too (its termination is in the HDF5 file's /solver/termination).
  std::vector<double> converged;
  for (const MeshCycleStep& k : r.steps) converged.push_back(k.summary.usable() ? 1.0 : 0.0);
  table.push_back({"converged", converged, true});
  // 1 where the transient step failed and the row is the steady film at its point.
  std::vector<double> restarted;
  for (const MeshCycleStep& k : r.steps) restarted.push_back(k.restarted() ? 1.0 : 0.0);
  table.push_back({"steady_restart", restarted, true});
  // The time substeps of each step and its estimated local time error (-1: not estimated).
  std::vector<double> substeps, time_error;
  for (const MeshCycleStep& k : r.steps) {
    substeps.push_back(k.summary.substeps);
    time_error.push_back(k.summary.time_error);
  }
  table.push_back({"substeps", substeps, true});
  table.push_back({"time_error", time_error});
  // The numeric /cycle columns of the film's resolution, as in the HDF5 file (-1: none).
  std::vector<double> pairs;
  for (const MeshCycleStep& k : r.steps) pairs.push_back(k.pairs_in_contact);
  table.push_back({"pairs_in_contact", pairs, true});
  if (r.p_pa.size() == r.steps.size()) {
    std::vector<double> cells;
    for (const OutletSpike& spike : r.OutletSpikes())
      cells.push_back(spike.found ? spike.width_cells : -1.0);
    table.push_back({"spike_cells", cells});
  }
  {
    std::vector<double> cells;
    for (const HertzEdge& e : r.HertzEdges()) cells.push_back(e.width_m > 0 ? e.width_cells : -1.0);
    if (cells.size() == r.steps.size()) table.push_back({"edge_cells", cells});
  }
  if (r.p_pa.size() == r.steps.size() && r.h_m.size() == r.steps.size()) {
    std::vector<double> deficit;
    for (const InletTruncation& t : r.InletTruncations())
      deficit.push_back(t.estimated ? t.film_deficit : -1.0);
    table.push_back({"inlet_deficit", deficit});
  }
  WriteCsvTable(path, table);
}

}  // namespace tehl::internal
