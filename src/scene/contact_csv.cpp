#include "scene/contact_csv.hpp"

#include <cstdio>
#include <stdexcept>

#include "io/csv_table.hpp"
#include "tehl/io/hdf5_writer.hpp"

namespace tehl::internal {
namespace {

struct Column {
  const char* header;
  std::vector<double> values;
  bool integer = false;  // counts and flags: "%.0f"
};

// Refuses the first NaN or Inf of any column, naming the file, the column and the row.
void CheckColumns(const std::string& file, const std::vector<Column>& columns) {
  for (const Column& c : columns) CheckFinite("CSV " + file + " column " + c.header, c.values);
}

std::string Header(const std::vector<Column>& columns) {
  std::string o;
  for (size_t j = 0; j < columns.size(); ++j) {
    if (j) o += ',';
    o += columns[j].header;
  }
  return o;
}

std::string Cells(const std::vector<Column>& columns, size_t row) {
  std::string o;
  for (size_t j = 0; j < columns.size(); ++j) {
    if (j) o += ',';
    AppendCsvCell(&o, columns[j].values[row], columns[j].integer);
  }
  return o;
}

}  // namespace

std::string ContactStepsCsv(const std::string& file, const std::vector<ContactStepRecord>& steps) {
  std::vector<Column> num = {{"t_s", {}},         {"w_n_per_m", {}},   {"u1_m_s", {}},
                             {"u2_m_s", {}},      {"h_min_m", {}},     {"h_c_m", {}},
                             {"p_max_pa", {}},    {"t_max_k", {}},     {"mu", {}},
                             {"wall_time_s", {}}, {"spike_cells", {}}, {"inlet_deficit", {}}};
  // Columns added later go after the existing ones, before the text column (readers look
  // columns up by name; docs/results.md).
  std::vector<Column> added = {{"t1_max_k", {}},
                               {"t2_max_k", {}},
                               {"dT_flash_blok_k", {}},
                               {"steady_restart", {}, true},
                               {"edge_cells", {}},
                               {"substeps", {}, true},
                               {"time_error", {}},
                               {"um_m_s", {}},
                               {"SRR", {}}};
  for (const ContactStepRecord& s : steps) {
    const double row[] = {s.time_s,
                          s.load_n_per_m,
                          s.u1_m_s,
                          s.u2_m_s,
                          s.h_min_m,
                          s.h_c_m,
                          s.p_max_pa,
                          s.t_max_k,
                          s.friction_coefficient,
                          s.wall_time_s,
                          s.outlet_spike.found ? s.outlet_spike.width_cells : -1.0,
                          s.inlet.estimated ? s.inlet.film_deficit : -1.0};
    for (size_t j = 0; j < num.size(); ++j) num[j].values.push_back(row[j]);
    const double um = 0.5 * (s.u1_m_s + s.u2_m_s);  // > 0 in every run (u1 + u2 > 0 is a rule)
    const double later[] = {s.t1_max_k,
                            s.t2_max_k,
                            s.flash_rise_blok_k,
                            s.restarted() ? 1.0 : 0.0,
                            s.hertz_edge.width_m > 0 ? s.hertz_edge.width_cells : -1.0,
                            static_cast<double>(s.summary.substeps),
                            s.summary.time_error,
                            um,
                            um > 0 ? (s.u1_m_s - s.u2_m_s) / um : 0.0};
    for (size_t j = 0; j < added.size(); ++j) added[j].values.push_back(later[j]);
  }
  CheckColumns(file, num);
  CheckColumns(file, added);
  std::string o =
      Header(num) + ",newton_iterations,coupling_iterations," + Header(added) + ",termination\n";
  for (size_t k = 0; k < steps.size(); ++k) {
    const LineContactSolver::Summary& sum = steps[k].summary;
    char tail[64];
    std::snprintf(tail, sizeof tail, ",%d,%d,", sum.total_iterations, sum.coupling_iterations);
    o += Cells(num, k) + tail + Cells(added, k) + "," + ToString(sum.termination) + "\n";
  }
  return o;
}

std::string ContactProfileCsv(const std::string& file,
                              const std::vector<double>& x_m,
                              const std::vector<double>& p_pa,
                              const std::vector<double>& h_m,
                              const std::vector<double>& t_mid_k,
                              const std::vector<double>& t1_k,
                              const std::vector<double>& t2_k) {
  std::vector<Column> cols = {{"x_m", x_m}, {"p_pa", p_pa}, {"h_m", h_m}};
  if (!t_mid_k.empty()) cols.push_back({"t_mid_k", t_mid_k});
  if (!t1_k.empty()) cols.push_back({"t1_k", t1_k});
  if (!t2_k.empty()) cols.push_back({"t2_k", t2_k});
  for (const Column& c : cols)
    if (c.values.size() != x_m.size())
      throw std::runtime_error("CSV " + file + ": column " + c.header + " has " +
                               std::to_string(c.values.size()) + " rows, expected " +
                               std::to_string(x_m.size()));
  CheckColumns(file, cols);
  std::string o = Header(cols) + "\n";
  for (size_t i = 0; i < x_m.size(); ++i) o += Cells(cols, i) + "\n";
  return o;
}

}  // namespace tehl::internal
