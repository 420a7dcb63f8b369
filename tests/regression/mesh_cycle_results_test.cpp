// The result files of `tehl run` on a gear case: the HDF5 file lists exactly the datasets of
// docs/results.md with the units written there (h5ls -r and the HDF5 C API), the CSV has the
// /cycle columns, and a run killed with SIGKILL half-way leaves no file under the final names.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "regression/mesh_cycle_runs.hpp"
#include "unit/io/hdf5_read.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using testing::ReadText;
using testing::Reduced;
using testing::ReducedCase;
using testing::TempDirFor;

// Dataset path -> unit, from the table of docs/results.md ("| `/a`, `/b` | shape | unit |").
// thermal = true: only the rows written by thermal runs ("thermal runs" in the row); false:
// only the others.
std::map<std::string, std::string> DocumentedDatasets(bool thermal = false) {
  std::map<std::string, std::string> out;
  std::istringstream doc(ReadText(std::string(TEHL_SOURCE_DIR) + "/docs/results.md"));
  std::string line;
  const std::regex row(R"(^\|([^|]*)\|([^|]*)\|([^|]*)\|)");
  const std::regex path("`(/[^`]+)`");
  while (std::getline(doc, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, row) || m[1].str().find("attributes") != std::string::npos)
      continue;
    const std::string cell = m[1].str(), unit = m[3].str();
    if ((line.find("thermal runs") != std::string::npos) != thermal) continue;
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), path);
         it != std::sregex_iterator(); ++it)
      out[(*it)[1].str()] = std::regex_replace(unit, std::regex("^ +| +$"), "");
  }
  return out;
}

std::string Shell(const std::string& cmd) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[512];
  while (p && fgets(buf, sizeof buf, p)) out += buf;
  if (p) pclose(p);
  return out;
}

TEST(MeshCycleResults, FileMatchesDocsResultsMd) {
  const std::string dir = TempDirFor("out");
  const std::string case_path = ReducedCase("seed004_sae40", Reduced({{"steps", "12"}}));
  const std::string cmd = std::string("'") + TEHL_BINARY + "' run -q '" + case_path + "' -o '" +
                          dir + "' > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string stem = fs::path(case_path).stem().string();
  const std::string h5 = dir + "/" + stem + ".h5";
  ASSERT_TRUE(fs::exists(h5));
  EXPECT_FALSE(fs::exists(h5 + ".part"));

  // h5ls -r lists every dataset; each is in the doc and each documented one is in the file.
  const std::map<std::string, std::string> documented = DocumentedDatasets();
  ASSERT_GE(documented.size(), 25u);
  std::set<std::string> listed;
  std::istringstream ls(Shell("h5ls -r '" + h5 + "'"));
  std::string line;
  while (std::getline(ls, line))
    if (line.find("Dataset") != std::string::npos) listed.insert(line.substr(0, line.find(' ')));
  ASSERT_FALSE(listed.empty()) << "h5ls -r printed no datasets";
  for (const auto& name : listed) EXPECT_TRUE(documented.count(name)) << name << " undocumented";
  for (const auto& [name, unit] : documented) EXPECT_TRUE(listed.count(name)) << name << " missing";
  // An isothermal run writes nothing thermal.
  for (const auto& [name, unit] : DocumentedDatasets(true))
    EXPECT_FALSE(listed.count(name)) << name << " written by an isothermal run";

  // The unit attribute of every dataset is the documented one; 13 steps at 257 nodes.
  const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const auto& [name, unit] : documented)
    EXPECT_EQ(testing::Hdf5StringAttribute(f, name, "unit"), unit) << name;
  std::vector<hsize_t> dims;
  testing::Hdf5Doubles(f, "/profiles/p", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{13, 257}));
  EXPECT_EQ(testing::Hdf5Doubles(f, "/cycle/h_c").size(), 13u);
  // The spike width per step: -1 (no spike) or a width within the grid.
  const std::vector<double> spike = testing::Hdf5Doubles(f, "/cycle/spike_cells");
  ASSERT_EQ(spike.size(), 13u);
  for (double w : spike) EXPECT_TRUE(w == -1.0 || (w > 0.0 && w < 256.0)) << w;
  // The Hertzian edge of each row from its own h_c, w and R (include/tehl/ehl/hertz_edge.hpp:
  // delta = b (3 R h_c / (2 sqrt(2) b^2))^(2/3), b = sqrt(8 w R / (pi E')), E' of the seed 004
  // bronze as below) in cells of the grid's spacing; the seed 004 films resolve it.
  {
    const std::vector<double> edge = testing::Hdf5Doubles(f, "/cycle/edge_cells"),
                              hc = testing::Hdf5Doubles(f, "/cycle/h_c"),
                              w = testing::Hdf5Doubles(f, "/cycle/w"),
                              radius = testing::Hdf5Doubles(f, "/cycle/R"),
                              x = testing::Hdf5Doubles(f, "/profiles/x");
    ASSERT_EQ(edge.size(), 13u);
    const double e_prime = 117e9 / (1 - 0.34 * 0.34), pi = 3.14159265358979323846;
    for (size_t k = 0; k < edge.size(); ++k) {
      const double b = std::sqrt(8 * w[k] * radius[k] / (pi * e_prime));
      const double delta =
          b * std::pow(3 * radius[k] * hc[k] / (2 * std::sqrt(2.0) * b * b), 2.0 / 3.0);
      EXPECT_NEAR(edge[k], delta / (x[1] - x[0]), 1e-9 * edge[k]) << k;
      EXPECT_GT(edge[k], 10.0) << k;
    }
  }
  // Blok's flash temperature of each row from its own mu, w, u1, u2 and R, with the seed 004
  // bronze of the case (VALIDATION.md section 5: E = 117 GPa, nu = 0.34, rho = 7890 kg/m^3,
  // k = 55 W/(m K), c = 375 J/(kg K)) on both gears: b = sqrt(8 w R / (pi E')) (Hertz) and
  // theta = c_B mu w |u1 - u2| / (sqrt(b) e (sqrt(u1) + sqrt(u2))), c_B = 0.785983
  // (docs/thermal.md "Flash temperature").
  {
    const std::vector<double> flash = testing::Hdf5Doubles(f, "/cycle/dT_flash_blok"),
                              mu = testing::Hdf5Doubles(f, "/cycle/mu"),
                              w = testing::Hdf5Doubles(f, "/cycle/w"),
                              u1 = testing::Hdf5Doubles(f, "/cycle/u1"),
                              u2 = testing::Hdf5Doubles(f, "/cycle/u2"),
                              radius = testing::Hdf5Doubles(f, "/cycle/R");
    ASSERT_EQ(flash.size(), 13u);
    const double e_prime = 117e9 / (1 - 0.34 * 0.34), e = std::sqrt(55.0 * 7890.0 * 375.0);
    for (size_t k = 0; k < flash.size(); ++k) {
      const double b = std::sqrt(8 * w[k] * radius[k] / (M_PI * e_prime));
      const double expected = 0.785983 * mu[k] * w[k] * std::abs(u1[k] - u2[k]) /
                              (std::sqrt(b) * e * (std::sqrt(u1[k]) + std::sqrt(u2[k])));
      EXPECT_NEAR(flash[k], expected, 1e-5 * expected + 1e-12) << "row " << k;
    }
    EXPECT_GT(flash.front(), 1.0);  // A: sliding at SRR -0.72
  }
  EXPECT_EQ(testing::Hdf5StringAttribute(f, "/", "converged"), "true");
  EXPECT_EQ(testing::Hdf5StringAttribute(f, "/", "grid_rule"), "[numerics] grid_points = 257");
  // /case is the case as run: the reduced keys and the defaults filled in.
  const std::string case_text = testing::Hdf5Text(f, "/case");
  EXPECT_NE(case_text.find("grid_points = 257"), std::string::npos) << case_text;
  EXPECT_NE(case_text.find("time_scheme = \"bdf2\""), std::string::npos) << case_text;
  // /lubricant is the lubricant file read, byte for byte, and lubricant_file where it was.
  const std::string lubricant_file = testing::Hdf5StringAttribute(f, "/", "lubricant_file");
  EXPECT_EQ(fs::path(lubricant_file).filename(), "sae40.toml");
  EXPECT_TRUE(fs::path(lubricant_file).is_absolute()) << lubricant_file;
  std::ifstream oil(lubricant_file, std::ios::binary);
  std::ostringstream oil_text;
  oil_text << oil.rdbuf();
  EXPECT_EQ(testing::Hdf5Text(f, "/lubricant"), oil_text.str());
  H5Fclose(f);

  // The CSV beside it: the /cycle columns with units, one row per step.
  std::ifstream csv(dir + "/" + stem + "_cycle.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "s_m,t_s,R_m,u1_m_s,u2_m_s,um_m_s,SRR,w_n_per_m,w_static_n_per_m,h_min_m,h_c_m,"
            "p_max_pa,mu,dT_flash_blok_k,C_RT,C_UT,C_WT,converged,steady_restart,substeps,"
            "time_error,pairs_in_contact,spike_cells,edge_cells,inlet_deficit");
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 13);

  // h5py reads it (matplotlib and h5py are Debian packages of the project's set-up).
  const std::string py = Shell("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + h5 +
                               "', 'r'); print(f['cycle/h_c'].attrs['unit'], len(f['cycle/s']))\"");
  EXPECT_EQ(py, "m 13\n");
}

// A thermal run with the full temperature field adds exactly the thermal rows of
// docs/results.md, with their units, and the CSV the temperature columns.
TEST(MeshCycleResults, ThermalFileAddsTheDocumentedTemperatureDatasets) {
  const std::string dir = TempDirFor("thermal_h5");
  const std::string case_path =
      ReducedCase("seed004_sae40", {{"grid_points", "129"}, {"steps", "6"}, {"thermal", "true"}});
  std::ofstream(case_path, std::ios::app) << "\n[output]\ntemperature_field = true\n";
  const std::string cmd = std::string("'") + TEHL_BINARY + "' run -q '" + case_path + "' -o '" +
                          dir + "' > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string stem = fs::path(case_path).stem().string();
  const std::string h5 = dir + "/" + stem + ".h5";
  std::set<std::string> listed;
  std::istringstream ls(Shell("h5ls -r '" + h5 + "'"));
  std::string line;
  while (std::getline(ls, line))
    if (line.find("Dataset") != std::string::npos) listed.insert(line.substr(0, line.find(' ')));
  std::map<std::string, std::string> all = DocumentedDatasets(false);
  const std::map<std::string, std::string> thermal = DocumentedDatasets(true);
  ASSERT_GE(thermal.size(), 10u);
  all.insert(thermal.begin(), thermal.end());
  for (const auto& name : listed) EXPECT_TRUE(all.count(name)) << name << " undocumented";
  for (const auto& [name, unit] : all) EXPECT_TRUE(listed.count(name)) << name << " missing";
  const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const auto& [name, unit] : thermal)
    EXPECT_EQ(testing::Hdf5StringAttribute(f, name, "unit"), unit) << name;
  std::vector<hsize_t> dims;
  testing::Hdf5Doubles(f, "/profiles/T", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{7, 129 * 11}));  // 11 film nodes by default
  H5Fclose(f);
  std::ifstream csv(dir + "/" + stem + "_cycle.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find(",mu,dT_flash_blok_k,T_max_k,T_mid_k,T1_max_k,T2_max_k,"),
            std::string::npos)
      << header;
}

TEST(MeshCycleResults, PlotWritesTheThreeFiguresAndRejectsAMissingFile) {
  const std::string dir = TempDirFor("plot");
  const std::string case_path = ReducedCase("seed004_sae40", Reduced({{"steps", "6"}}));
  const std::string tehl = std::string("'") + TEHL_BINARY + "'";
  ASSERT_EQ(std::system((tehl + " run -q '" + case_path + "' -o '" + dir + "' >/dev/null").c_str()),
            0);
  const std::string stem = fs::path(case_path).stem().string();
  ASSERT_EQ(
      std::system(
          (tehl + " plot '" + dir + "/" + stem + ".h5' -o '" + dir + "/png' >/dev/null").c_str()),
      0);
  for (const char* fig : {"_cycle.png", "_profiles.png", "_path.png"}) {
    const fs::path png = fs::path(dir) / "png" / (stem + fig);
    ASSERT_TRUE(fs::exists(png)) << png;
    EXPECT_GT(fs::file_size(png), 10000u) << png;
    EXPECT_EQ(ReadText(png.string()).substr(1, 3), "PNG") << png;
  }
  const int status = std::system((tehl + " plot '" + dir + "/missing.h5' >/dev/null 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

// A cycle that stops at its first step (two Newton iterations allowed: the film at A cannot
// converge) exits 1, names the failed step, and prints no film "at the pitch point" (it never
// got there) nor a temperature of the failed step: never a silent wrong answer.
TEST(MeshCycleResults, StoppedCycleReportsNoPitchPointValues) {
  const std::string dir = TempDirFor("stopped");
  fs::create_directories(dir);
  const std::string case_path = ReducedCase(
      "seed004_sae40", Reduced({{"grid_points", "129"}, {"max_newton_iterations", "2"}}));
  const std::string out = dir + "/stdout.txt", err = dir + "/stderr.txt";
  const int status = std::system(("'" + std::string(TEHL_BINARY) + "' run '" + case_path +
                                  "' -q -o '" + dir + "' >'" + out + "' 2>'" + err + "'")
                                     .c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);  // not converged (tehl/error.hpp)
  const std::string stdout_text = ReadText(out), stderr_text = ReadText(err);
  EXPECT_NE(stdout_text.find("the cycle stopped before the pitch point"), std::string::npos)
      << stdout_text;
  EXPECT_EQ(stdout_text.find("at the pitch point ("), std::string::npos) << stdout_text;
  EXPECT_EQ(stdout_text.find("nearest the pitch point"), std::string::npos) << stdout_text;
  EXPECT_NE(stderr_text.find("step 0 (s = 0 mm) did not converge"), std::string::npos)
      << stderr_text;
  // Its result has no converged step: `tehl plot` says there is nothing to plot (exit 1, not
  // converged) instead of drawing empty figures.
  const std::string stem = fs::path(case_path).stem().string();
  const std::string plot_err = dir + "/plot_stderr.txt";
  const int plotted = std::system(("'" + std::string(TEHL_BINARY) + "' plot '" + dir + "/" + stem +
                                   ".h5' -o '" + dir + "/png' >/dev/null 2>'" + plot_err + "'")
                                      .c_str());
  ASSERT_TRUE(WIFEXITED(plotted));
  EXPECT_EQ(WEXITSTATUS(plotted), 1);
  EXPECT_NE(ReadText(plot_err).find("nothing to plot"), std::string::npos) << ReadText(plot_err);
  EXPECT_FALSE(fs::exists(dir + "/png/" + stem + "_cycle.png"));
}

TEST(MeshCycleResults, KilledRunLeavesNoFileUnderTheFinalName) {
  const std::string dir = TempDirFor("killed");
  fs::create_directories(dir);
  // Long enough to be killed half-way: 400 steps at 257 nodes (about 25 s when not killed).
  const std::string case_path = ReducedCase("seed004_sae40", Reduced({{"steps", "400"}}));
  const std::string stem = fs::path(case_path).stem().string();
  const std::string err = dir + "/stderr.txt";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::FILE* e = std::freopen(err.c_str(), "w", stderr);
    std::FILE* o = std::freopen("/dev/null", "w", stdout);
    (void)e;
    (void)o;
    execl(TEHL_BINARY, "tehl", "run", case_path.c_str(), "-o", dir.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait until the run is under way: the result file is open under its temporary name and a
  // few steps are done.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool midway = false;
  while (!midway && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    midway = fs::exists(dir + "/" + stem + ".h5.part") &&
             ReadText(err).find("step 20/400") != std::string::npos;
  }
  ASSERT_TRUE(midway) << ReadText(err);
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  EXPECT_FALSE(fs::exists(dir + "/" + stem + ".h5"));
  EXPECT_FALSE(fs::exists(dir + "/" + stem + "_cycle.csv"));
  EXPECT_TRUE(fs::exists(dir + "/" + stem + ".h5.part"));  // what a kill leaves: the temporary
  EXPECT_EQ(ReadText(err).find("step 400/400"), std::string::npos);  // it was killed half-way
}

}  // namespace
}  // namespace tehl
