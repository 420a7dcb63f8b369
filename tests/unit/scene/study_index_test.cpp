// The study index of [contact] scenes: ContactRow reads T_max, mu and the wall time of a disc
// run's _steps.csv (and files without those columns), and `tehl sweep` over a disc case
// writes them into index.csv, equal after --resume.
#include "tehl/scene/study_index.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/csv_cells.hpp"
#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

// A contact study with one scene whose result file is `steps_csv`.
Study OneSceneStudy(const std::string& name, const std::string& steps_csv, StudyScene* scene) {
  Study s;
  s.gear = false;
  s.output_dir = testing::UniqueTempPath(name);
  scene->id = 0;
  scene->name = "scene_0000";
  fs::create_directories(s.ScenesDir());
  std::ofstream(s.ResultPath(*scene)) << steps_csv;
  return s;
}

// A file of the earlier format (no t_max_k, mu, wall_time_s): the film summaries are read, the
// others stay 0 ("0: not in the file", study_index.hpp).
TEST(StudyIndex, ContactStepsWithoutTheNewColumnsGiveZeros) {
  StudyScene scene;
  const Study s = OneSceneStudy(
      "old_steps",
      "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,newton_iterations,termination\n"
      "0.0,1e5,1,1,3.0e-7,4.0e-7,6.0e8,12,converged\n"
      "1e-4,2e5,1,1,2.5e-7,3.5e-7,8.0e8,5,converged\n",
      &scene);
  const SceneRow r = ReadSceneRow(s, scene);
  EXPECT_EQ(r.status, "ok");
  EXPECT_EQ(r.steps, 2);
  EXPECT_EQ(r.h_min_min_m, 2.5e-7);
  EXPECT_EQ(r.h_c_pitch_m, 3.5e-7);  // contact cases: the last step
  EXPECT_EQ(r.p_max_max_pa, 8.0e8);
  EXPECT_EQ(r.t_max_max_k, 0.0);
  EXPECT_EQ(r.mu_mean, 0.0);
  EXPECT_EQ(r.mu_max, 0.0);
  EXPECT_EQ(r.wall_time_s, 0.0);
  EXPECT_EQ(r.t_surface_max_k, 0.0);
  EXPECT_EQ(r.flash_blok_max_k, 0.0);
  EXPECT_EQ(r.steady_restarts, 0.0);
  EXPECT_EQ(r.edge_cells_min, -1.0);  // no edge_cells column
}

// The surface and flash temperature columns (docs/results.md): the hottest surface of either
// body over the steps, max(321, 318, 325, 324) = 325 K, and the largest flash rise,
// max(2.5, 4.0) = 4 K. Any column order is read.
TEST(StudyIndex, ContactStepsWithSurfaceAndFlashColumnsAreSummarized) {
  StudyScene scene;
  const Study s = OneSceneStudy(
      "flash_steps",
      "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,t_max_k,mu,wall_time_s,"
      "newton_iterations,coupling_iterations,t1_max_k,t2_max_k,dT_flash_blok_k,termination\n"
      "0.0,1e5,1.2,0.8,3.0e-7,4.0e-7,6.0e8,330,0.03,0.5,12,8,321,318,2.5,converged\n"
      "1e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,340,0.04,0.25,5,4,325,324,4.0,converged\n",
      &scene);
  const SceneRow r = ReadSceneRow(s, scene);
  EXPECT_EQ(r.status, "ok");
  EXPECT_EQ(r.t_surface_max_k, 325.0);
  EXPECT_EQ(r.flash_blok_max_k, 4.0);
  // The text form carries them between MPI ranks.
  const std::vector<SceneRow> back = SceneRowsFromText(SceneRowsToText({r}));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].t_surface_max_k, 325.0);
  EXPECT_EQ(back[0].flash_blok_max_k, 4.0);
}

// The steady_restart column ([numerics] failed_step): the index counts the restarted steps
// (0 + 1 + 1 = 2) and keeps the status ok (every row converged); a file without the column
// counts 0 (the first test above).
TEST(StudyIndex, ContactStepsCountTheirSteadyRestarts) {
  StudyScene scene;
  const Study s = OneSceneStudy(
      "restart_steps",
      "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,t1_max_k,t2_max_k,dT_flash_blok_k,"
      "steady_restart,termination\n"
      "0.0,1e5,1.2,0.8,3.0e-7,4.0e-7,6.0e8,321,318,2.5,0,converged\n"
      "1e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,325,324,4.0,1,converged\n"
      "2e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,325,324,4.0,1,converged\n",
      &scene);
  const SceneRow r = ReadSceneRow(s, scene);
  EXPECT_EQ(r.status, "ok");
  EXPECT_EQ(r.steady_restarts, 2.0);
  const std::vector<SceneRow> back = SceneRowsFromText(SceneRowsToText({r}));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].steady_restarts, 2.0);
}

// The edge_cells column (docs/results.md, "The edge note"): the index keeps the fewest cells
// over the films that have an edge (-1 marks none); a file without the column gives -1 (the
// first test above).
TEST(StudyIndex, ContactStepsKeepTheFewestEdgeCells) {
  StudyScene scene;
  const Study s = OneSceneStudy(
      "edge_steps",
      "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,steady_restart,edge_cells,termination\n"
      "0.0,1e5,1.2,0.8,3.0e-7,4.0e-7,6.0e8,0,25.5,converged\n"
      "1e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,0,7.25,converged\n"
      "2e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,0,-1,converged\n",
      &scene);
  const SceneRow r = ReadSceneRow(s, scene);
  EXPECT_EQ(r.edge_cells_min, 7.25);
  const std::vector<SceneRow> back = SceneRowsFromText(SceneRowsToText({r}));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].edge_cells_min, 7.25);
}

// The new columns: T_max the largest, mu mean and max over the converged films, wall time the
// sum over all steps. Expected values by hand from the rows: max(320, 335) = 335 K; mu
// (0.01 + 0.04)/2 = 0.025, max 0.04; wall 0.5 + 0.25 + 0.125 = 0.875 s (exact in binary).
TEST(StudyIndex, ContactStepsWithTheNewColumnsAreSummarized) {
  StudyScene scene;
  const Study s = OneSceneStudy(
      "new_steps",
      "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,t_max_k,mu,wall_time_s,"
      "newton_iterations,coupling_iterations,termination\n"
      "0.0,1e5,1.2,0.8,3.0e-7,4.0e-7,6.0e8,320,0.01,0.5,12,8,converged\n"
      "1e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,335,0.04,0.25,5,4,converged\n"
      "2e-4,1e5,1.2,0.8,2.8e-7,3.8e-7,6.2e8,330,0.03,0.125,40,40,coupling_not_converged\n",
      &scene);
  const SceneRow r = ReadSceneRow(s, scene);
  EXPECT_EQ(r.status, "not_converged");
  EXPECT_EQ(r.message, "coupling_not_converged");
  EXPECT_EQ(r.steps, 3);
  // The summaries are over the two converged films; the failed third is no result (its
  // thinner film, 2.8e-7 m, is not the scene's). The wall time counts every step.
  EXPECT_EQ(r.h_min_min_m, 2.9e-7);
  EXPECT_EQ(r.h_c_pitch_m, 3.9e-7);
  EXPECT_EQ(r.p_max_max_pa, 6.1e8);
  EXPECT_EQ(r.t_max_max_k, 335.0);
  EXPECT_NEAR(r.mu_mean, 0.05 / 2, 1e-15);
  EXPECT_EQ(r.mu_max, 0.04);
  EXPECT_EQ(r.wall_time_s, 0.875);
}

// A Newtonian film's mu above 0.2 (kPhysicalFrictionLimit) is not physical: the flash rise
// from it is left out of the scene's maximum and the film is counted (a sweep note names it).
TEST(StudyIndex, UnphysicalNewtonianFrictionIsCountedAndItsFlashLeftOut) {
  StudyScene scene;
  const Study s = OneSceneStudy(
      "unphysical_mu",
      "t_s,w_n_per_m,u1_m_s,u2_m_s,h_min_m,h_c_m,p_max_pa,t_max_k,mu,wall_time_s,"
      "newton_iterations,coupling_iterations,t1_max_k,t2_max_k,dT_flash_blok_k,termination\n"
      "0.0,1e5,1.2,0.8,3.0e-7,4.0e-7,6.0e8,320,0.05,0.5,12,8,320,320,12.5,converged\n"
      "1e-4,1e5,1.2,0.8,2.9e-7,3.9e-7,6.1e8,335,0.45,0.25,5,4,320,320,120.0,converged\n",
      &scene);
  const SceneRow r = ReadSceneRow(s, scene);
  EXPECT_EQ(r.mu_max, 0.45);  // the model's answer stays in the index
  EXPECT_EQ(r.flash_blok_max_k, 12.5);
  EXPECT_EQ(r.unphysical_mu_films, 1.0);
}

using testing::ReadCsvCells;

size_t Column(const std::vector<std::string>& head, const std::string& name) {
  const auto it = std::find(head.begin(), head.end(), name);
  EXPECT_NE(it, head.end()) << "no column " << name;
  return static_cast<size_t>(it - head.begin());
}

// `tehl sweep -j 2` of a one-key study over the base case `base_toml` (written to dir/base.toml)
// into dir/out; the study's key and its values (a TOML array).
testing::RunResult Sweep(const std::string& dir,
                         const std::string& base_toml,
                         const std::string& key,
                         const std::string& values) {
  fs::create_directories(dir);
  std::ofstream(dir + "/base.toml") << base_toml;
  std::ofstream(dir + "/study.toml") << "[study]\nbase = \"base.toml\"\n[[vary]]\nkey = \"" << key
                                     << "\"\nvalues = " << values << "\n";
  return testing::RunTehl("sweep -j 2 -q -o '" + dir + "/out' '" + dir + "/study.toml'");
}

// A string varied in a study is its plain text in index.csv (the HDF5 index keeps the TOML
// literal): sae40, not """sae40""". The index also keeps each scene's inlet deficit.
TEST(StudyIndex, AVariedStringIsItsPlainTextInTheCsv) {
  const std::string dir = testing::UniqueTempPath("oil_study"), out = dir + "/out";
  const testing::RunResult r =
      Sweep(dir,
            "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\n"
            "speed_2_m_s = 1.0\nload_n_per_m = 1.0e5\n[lubricant]\nname = \"sae40\"\n"
            "[numerics]\ngrid_points = 129\n",
            "lubricant.name", "[\"sae40\", \"sae90\"]");
  ASSERT_TRUE(r.exited) << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto cells = ReadCsvCells(out + "/index.csv");
  ASSERT_EQ(cells.size(), 3u);
  const size_t i = Column(cells[0], "lubricant.name");
  EXPECT_EQ(cells[1][i], "sae40");
  EXPECT_EQ(cells[2][i], "sae90");
  // The disc of cases/disc_steady.toml on a set grid: its inlet at -4.5 b costs the SAE 40
  // film about 3 % (docs/results.md, "The inlet note": 2.99 % estimated, 2.87 % measured), and
  // the sweep says so.
  const size_t d = Column(cells[0], "inlet_deficit_max");
  EXPECT_GT(std::stod(cells[1][d]), 0.02);
  EXPECT_LT(std::stod(cells[1][d]), 0.04);
  EXPECT_NE(r.out.find("note: 2 scene(s) have films that the inlet at x_start_b thins by more "
                       "than 0.5 %"),
            std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

// A heavy slow disc (3 MN/m, p_H 3.3 GPa, 0.05 m/s; docs/results.md, "The edge note") on 513
// and 8193 nodes: the index keeps each scene's fewest cells across the Hertzian edge (0.67
// and about 18 measured with `tehl run`), and the sweep notes the one scene under 10.
TEST(StudyIndex, ASweepNotesScenesWhoseHertzianEdgeIsNotResolved) {
  const std::string dir = testing::UniqueTempPath("edge_study"), out = dir + "/out";
  const testing::RunResult r =
      Sweep(dir,
            "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nyoungs_modulus_1_pa = 210e9\n"
            "poisson_ratio_1 = 0.3\nyoungs_modulus_2_pa = 210e9\npoisson_ratio_2 = 0.3\n"
            "speed_1_m_s = 0.05\nspeed_2_m_s = 0.05\nload_n_per_m = 3.0e6\n[lubricant]\n"
            "name = \"sae40\"\n",
            "numerics.grid_points", "[513, 8193]");
  ASSERT_TRUE(r.exited) << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: 1 scene(s) have films whose Hertzian edge spans fewer than 10"),
            std::string::npos)
      << r.out;
  const auto cells = ReadCsvCells(out + "/index.csv");
  ASSERT_EQ(cells.size(), 3u);
  const size_t ie = Column(cells[0], "edge_cells_min");
  EXPECT_NEAR(std::stod(cells[1][ie]), 0.67, 0.01);
  EXPECT_GT(std::stod(cells[2][ie]), 10.0);
  const size_t ig = Column(cells[0], "grid_points");
  EXPECT_EQ(cells[1][ig], "513");
  EXPECT_EQ(cells[2][ig], "8193");
  EXPECT_NE(r.out.find("note: the scenes ran on grids of 513 to 8193 nodes"), std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

// A thermal pure-rolling disc (cases/disc_steady.toml at 129 nodes, T0 = 313.15 K given) at two
// loads. Every row: T_max above the inlet (the film is heated), 0 < mu_mean <= mu_max (one
// step: equal), wall time > 0. A --resume rebuilds the rows from the files: every column equal
// to the fresh row (the fresh row is read from the same file, wall time included: the sum of the
// steps' wall_time_s) except `computed`, 1 then 0.
TEST(StudyIndex, DiscSweepIndexCarriesTemperatureFrictionAndWallTime) {
  const std::string dir = testing::UniqueTempPath("disc_study"), out = dir + "/out";
  const testing::RunResult r =
      Sweep(dir,
            "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\n"
            "speed_2_m_s = 1.0\nload_n_per_m = 1.0e5\n[lubricant]\nname = \"sae40\"\n"
            "inlet_temperature_k = 313.15\n[effects]\ntransient = false\nthermal = true\n"
            "[numerics]\ngrid_points = 129\n",
            "contact.load_n_per_m", "[5e4, 1e5]");
  ASSERT_TRUE(r.exited) << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto first = ReadCsvCells(out + "/index.csv");
  ASSERT_EQ(first.size(), 3u);
  const auto& head = first[0];
  const size_t it = Column(head, "t_max_max_k"), im = Column(head, "mu_mean"),
               ix = Column(head, "mu_max"), iw = Column(head, "wall_time_s"),
               is = Column(head, "status"), ic = Column(head, "computed");
  for (size_t k = 1; k < first.size(); ++k) {
    EXPECT_EQ(first[k][is], "ok") << k;
    EXPECT_GT(std::stod(first[k][it]), 313.15) << k;
    EXPECT_GT(std::stod(first[k][im]), 0.0) << k;
    EXPECT_EQ(std::stod(first[k][ix]), std::stod(first[k][im])) << k;  // one step
    EXPECT_GT(std::stod(first[k][iw]), 0.0) << k;
    // Thermal rolling: the surfaces warm above the inlet; no sliding, no flash rise.
    EXPECT_GT(std::stod(first[k][Column(head, "t_surface_max_k")]), 313.15) << k;
    EXPECT_EQ(std::stod(first[k][Column(head, "dT_flash_blok_max_k")]), 0.0) << k;
  }
  const testing::RunResult again =
      testing::RunTehl("sweep --resume -j 2 -q -o '" + out + "' '" + dir + "/study.toml'");
  ASSERT_TRUE(again.exited) << again.err;
  ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
  const auto second = ReadCsvCells(out + "/index.csv");
  ASSERT_EQ(second.size(), first.size());
  ASSERT_EQ(second[0], head);
  for (size_t k = 1; k < second.size(); ++k) {
    EXPECT_EQ(first[k][ic], "1") << k;
    EXPECT_EQ(second[k][ic], "0") << k;
    ASSERT_EQ(second[k].size(), first[k].size()) << k;
    for (size_t j = 0; j < head.size(); ++j)
      if (j != ic) {
        EXPECT_EQ(second[k][j], first[k][j]) << "row " << k << " column " << head[j];
      }
  }
}

// A study whose oil is a file beside its base case: editing that file (here its viscosity,
// 0.114 -> 0.3 Pa s) changes every scene, so --resume reruns them instead of reading back the
// films of the old oil (the isoviscous disc's film grows with eta0^0.7 or so: thicker).
TEST(StudyIndex, ResumeRerunsScenesWhoseLubricantFileChanged) {
  const std::string dir = testing::UniqueTempPath("edited_oil_study"), out = dir + "/out";
  fs::create_directories(dir);
  std::ifstream sae40(std::string(TEHL_SOURCE_DIR) + "/lubricants/sae40.toml");
  std::ostringstream oil;
  oil << sae40.rdbuf();
  std::ofstream(dir + "/mylub.toml") << oil.str();
  const testing::RunResult r =
      Sweep(dir,
            "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\n"
            "speed_2_m_s = 1.0\nload_n_per_m = 1.0e5\n[lubricant]\nname = \"mylub\"\n"
            "[numerics]\ngrid_points = 129\n",
            "contact.load_n_per_m", "[1e5, 2e5]");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto before = ReadCsvCells(out + "/index.csv");
  ASSERT_EQ(before.size(), 3u);
  const size_t ih = Column(before[0], "h_min_min_m"), ic = Column(before[0], "computed");
  // Unchanged: read back.
  testing::RunResult again =
      testing::RunTehl("sweep --resume -j 2 -q -o '" + out + "' '" + dir + "/study.toml'");
  ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
  const auto reread = ReadCsvCells(out + "/index.csv");
  ASSERT_EQ(reread.size(), 3u);
  for (size_t k = 1; k < reread.size(); ++k) EXPECT_EQ(reread[k][ic], "0") << k;
  const std::string text = oil.str();
  const size_t v = text.find("viscosity_pa_s = ");
  ASSERT_NE(v, std::string::npos);
  const size_t end = text.find('\n', v);
  std::ofstream(dir + "/mylub.toml")
      << text.substr(0, v) + "viscosity_pa_s = 0.3" + text.substr(end);
  again = testing::RunTehl("sweep --resume -j 2 -q -o '" + out + "' '" + dir + "/study.toml'");
  ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
  const auto after = ReadCsvCells(out + "/index.csv");
  ASSERT_EQ(after.size(), 3u);
  for (size_t k = 1; k < after.size(); ++k) {
    EXPECT_EQ(after[k][ic], "1") << k;
    EXPECT_GT(std::stod(after[k][ih]), 1.5 * std::stod(before[k][ih])) << k;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tehl
