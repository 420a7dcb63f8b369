// scripts/accuracy_report.py reads a [contact] run's NAME_steps.csv: h_min, h_c, p_max of the
// last step, max of t_max_k, mean of mu, the wall time as the sum of wall_time_s (None for a
// file written before those columns existed), on hand-made files and on a real 129-node disc
// run; and it takes a mesh cycle's h_c at the pitch point linearly between the two step ends
// around C. The script's functions are called by /usr/bin/python3 (the interpreter of
// scripts/accuracy_report.sh); the report itself (a run of a few minutes) is not made here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

// True when /usr/bin/python3 can import what accuracy_report.py imports.
bool PythonReady() {
  return std::system("/usr/bin/python3 -c 'import h5py, matplotlib, numpy' >/dev/null 2>&1") == 0;
}

// Runs `call` (a Python expression giving a dict or None) with accuracy_report imported as `a`
// and returns the dict as key -> repr of the value ("None" when the call gives None).
std::map<std::string, std::string> CallScript(const std::string& call) {
  const std::string py = testing::UniqueTempPath("call.py"), out = testing::UniqueTempPath("o");
  std::ofstream(py) << "import sys\nsys.path.insert(0, '" << TEHL_SOURCE_DIR << "/scripts')\n"
                    << "import accuracy_report as a\n"
                    << "d = " << call << "\n"
                    << "for k, v in (d or {'result': None}).items():\n"
                    << "    print(k, repr(v))\n";
  const std::string cmd = "/usr/bin/python3 '" + py + "' >'" + out + "' 2>&1";
  const int status = std::system(cmd.c_str());
  const std::string text = testing::ReadAll(out);
  EXPECT_EQ(status, 0) << text;
  std::map<std::string, std::string> m;
  std::istringstream in(text);
  for (std::string k, v; in >> k && std::getline(in, v);) m[k] = v.substr(1);
  return m;
}

double Num(const std::map<std::string, std::string>& m, const std::string& key) {
  const auto it = m.find(key);
  EXPECT_NE(it, m.end()) << "no " << key;
  return it == m.end() ? 0.0 : std::stod(it->second);
}

// Expected values by hand from the three rows (the rows of study_index_test.cpp):
// last step h_min 2.8e-7, h_c 3.8e-7, p_max 6.2e8; T_max max(320, 335, 330) = 335 K;
// mu (0.01 + 0.04 + 0.03)/3 = 0.08/3; wall 0.5 + 0.25 + 0.125 = 0.875 s (exact in binary);
// steps_run = rows - 1 = 2 (the cycle's convention: the initial state is not a step).
TEST(AccuracyReport, ContactStepsAreSummarizedLikeTheCycle) {
  if (!PythonReady()) GTEST_SKIP() << "/usr/bin/python3 without h5py, matplotlib or numpy";
  const std::string csv = testing::UniqueTempPath("new_steps.csv");
  std::ofstream(csv) << "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,t_max_k,mu,"
                        "wall_time_s,newton_iterations,coupling_iterations,termination\n"
                        "0.0,1e5,1.2,0.8,3.0e-7,4.0e-7,6.0e8,320,0.01,0.5,12,8,converged\n"
                        "1e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,335,0.04,0.25,5,4,converged\n"
                        "2e-4,1e5,1.2,0.8,2.8e-7,3.8e-7,6.2e8,330,0.03,0.125,4,4,converged\n";
  const auto m = CallScript("a.read_contact_steps('" + csv + "')");
  EXPECT_EQ(Num(m, "h_min"), 2.8e-7);
  EXPECT_EQ(Num(m, "h_c"), 3.8e-7);
  EXPECT_EQ(Num(m, "p_max"), 6.2e8);
  EXPECT_EQ(Num(m, "T_max"), 335.0);
  EXPECT_NEAR(Num(m, "mu"), 0.08 / 3, 1e-15);
  EXPECT_EQ(Num(m, "wall_s"), 0.875);
  EXPECT_EQ(Num(m, "steps_run"), 2.0);
  EXPECT_EQ(Num(m, "restarts"), 0.0);  // no steady_restart column: none
}

// A run with a step restarted from the steady film ([numerics] failed_step) counts its
// restarts (0 + 1 + 0 = 1); read_result then marks it not ok, so it neither gets an error nor
// becomes a series' reference.
TEST(AccuracyReport, ContactStepsCountTheirSteadyRestarts) {
  if (!PythonReady()) GTEST_SKIP() << "/usr/bin/python3 without h5py, matplotlib or numpy";
  const std::string csv = testing::UniqueTempPath("restart_steps.csv");
  std::ofstream(csv) << "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,steady_restart,"
                        "termination\n"
                        "0.0,1e5,1.2,0.8,3.0e-7,4.0e-7,6.0e8,0,converged\n"
                        "1e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,1,converged\n"
                        "2e-4,1e5,1.2,0.8,2.8e-7,3.8e-7,6.2e8,0,converged\n";
  EXPECT_EQ(Num(CallScript("a.read_contact_steps('" + csv + "')"), "restarts"), 1.0);
  const std::string stem = csv.substr(0, csv.size() - std::string("_steps.csv").size());
  const auto row = CallScript("a.read_result({'case': '" + stem + ".toml', 'rc': 0})");
  EXPECT_EQ(row.at("ok"), "False");
}

// A file of the earlier format: the film is read, T_max, mu and the wall time are None (shown
// as '-' in the report); a file with a header only is no result.
TEST(AccuracyReport, ContactStepsWithoutTheNewColumnsGiveNone) {
  if (!PythonReady()) GTEST_SKIP() << "/usr/bin/python3 without h5py, matplotlib or numpy";
  const std::string header =
      "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,"
      "newton_iterations,termination\n";
  const std::string csv = testing::UniqueTempPath("old_steps.csv");
  std::ofstream(csv) << header << "0.0,1e5,1,1,3.0e-7,4.0e-7,6.0e8,12,converged\n";
  const auto m = CallScript("a.read_contact_steps('" + csv + "')");
  EXPECT_EQ(Num(m, "h_min"), 3.0e-7);
  EXPECT_EQ(m.at("T_max"), "None");
  EXPECT_EQ(m.at("mu"), "None");
  EXPECT_EQ(m.at("wall_s"), "None");
  const std::string empty = testing::UniqueTempPath("empty_steps.csv");
  std::ofstream(empty) << header;
  EXPECT_EQ(CallScript("a.read_contact_steps('" + empty + "')").at("result"), "None");
}

// A mesh cycle's h_c at the pitch point C (read_result of a NAME.h5) is at_s(/cycle/s,
// /cycle/h_c, s_C): linear in s between the two step ends around C, which is in general no step
// end; at a step end that step's value. By hand: 5 + 0.25 (9 - 5) = 6, exact in binary.
TEST(AccuracyReport, PitchFilmIsInterpolatedBetweenTheStepsAroundC) {
  if (!PythonReady()) GTEST_SKIP() << "/usr/bin/python3 without h5py, matplotlib or numpy";
  const auto m = CallScript(
      "{'between': a.at_s([0.0, 1.0, 2.0], [3.0, 5.0, 9.0], 1.25), "
      "'at_step': a.at_s([0.0, 1.0, 2.0], [3.0, 5.0, 9.0], 1.0)}");
  EXPECT_EQ(Num(m, "between"), 6.0);
  EXPECT_EQ(Num(m, "at_step"), 5.0);
}

// Column `name` of a CSV file with a header row, as numbers.
std::vector<double> CsvColumn(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> head;
  for (std::istringstream h(line); std::getline(h, line, ',');) head.push_back(line);
  const size_t j = std::find(head.begin(), head.end(), name) - head.begin();
  EXPECT_LT(j, head.size()) << "no column " << name;
  std::vector<double> v;
  for (std::string row; std::getline(in, row);) {
    std::istringstream r(row);
    std::string cell;
    for (size_t k = 0; k <= j; ++k) std::getline(r, cell, ',');
    v.push_back(std::stod(cell));
  }
  return v;
}

// The real file: a steady thermal Ree-Eyring disc with sliding (the report's disc, SRR 0.4, at
// 129 nodes; T0 = 313.15 K given), run by `tehl run` into the case's folder as the report does.
// read_result finds the _steps.csv next to the case and gives the column's max, mean and sum
// (one steady step: the cells themselves); the film is heated (T_max above the inlet) and
// sheared (mu > 0), and the solve took time.
TEST(AccuracyReport, TinyDiscRunIsReadFromItsStepsFile) {
  if (!PythonReady()) GTEST_SKIP() << "/usr/bin/python3 without h5py, matplotlib or numpy";
  const std::string dir = testing::UniqueTempPath("accuracy_disc");
  fs::create_directories(dir);
  const std::string toml = dir + "/disc.toml";
  std::ofstream(toml) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.2\n"
                         "speed_2_m_s = 0.8\nload_n_per_m = 1.0e5\n[lubricant]\n"
                         "name = \"sae40\"\ninlet_temperature_k = 313.15\n[effects]\n"
                         "transient = false\nthermal = true\nnon_newtonian = true\n"
                         "[numerics]\ngrid_points = 129\n[output]\ndirectory = \""
                      << dir << "\"\n";
  const testing::RunResult r = testing::RunTehl("run '" + toml + "'");
  ASSERT_TRUE(r.exited) << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string steps = dir + "/disc_steps.csv";
  ASSERT_TRUE(fs::exists(steps));
  const auto m = CallScript("a.read_result({'case': '" + toml + "', 'rc': 0})");
  EXPECT_EQ(m.at("ok"), "True");
  EXPECT_EQ(Num(m, "steps_run"), 0.0);
  const std::vector<double> t = CsvColumn(steps, "t_max_k"), mu = CsvColumn(steps, "mu"),
                            wall = CsvColumn(steps, "wall_time_s"),
                            h_min = CsvColumn(steps, "h_min_m");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(Num(m, "T_max"), t[0]);
  EXPECT_EQ(Num(m, "mu"), mu[0]);
  EXPECT_EQ(Num(m, "wall_s"), wall[0]);
  EXPECT_EQ(Num(m, "h_min"), h_min[0]);
  EXPECT_GT(Num(m, "T_max"), 313.15);
  EXPECT_GT(Num(m, "mu"), 0.0);
  EXPECT_GT(Num(m, "wall_s"), 0.0);
}

}  // namespace
}  // namespace tehl
