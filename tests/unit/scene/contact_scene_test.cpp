// The [contact] scene end to end: `tehl run` on the shipped disc cases and on bad input; the
// per-step T_max, friction and wall time of the _steps.csv and the NaN/Inf guard of both files.
#include "tehl/scene/contact_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "scene/contact_csv.hpp"
#include "tehl/io/hdf5_writer.hpp"
#include "tehl/units.hpp"
#include "support/scratch_path.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

fs::path TempDir(const std::string& name) {
  const fs::path d = testing::ScratchPath("tehl_contact", name);
  fs::create_directories(d);
  return d;
}

int RunTehl(const std::string& args, std::string* output) {
  const std::string cmd = std::string(TEHL_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  char buf[512];
  output->clear();
  while (fgets(buf, sizeof buf, pipe)) *output += buf;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// cases/disc_steady.toml (R = 10 mm steel, w = 100 kN/m, SAE 40, pure rolling at 1 m/s) with
// the inlet temperature given in K and the grid and thermal switch of the test.
constexpr double kInletK = 313.15;
std::string DiscCase(const fs::path& dir, bool thermal, int nodes) {
  const fs::path path = dir / "disc.toml";
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\n"
                         "speed_2_m_s = 1.0\nload_n_per_m = 1.0e5\n[lubricant]\nname = \"sae40\"\n"
                         "inlet_temperature_k = 313.15\n[effects]\ntransient = false\nthermal = "
                      << (thermal ? "true" : "false") << "\n[numerics]\ngrid_points = " << nodes
                      << "\n";
  return path.string();
}

// A CSV file as its header and rows of cells.
struct Csv {
  std::vector<std::string> head;
  std::vector<std::vector<std::string>> rows;
  size_t Col(const std::string& name) const {
    const auto it = std::find(head.begin(), head.end(), name);
    EXPECT_NE(it, head.end()) << "no column " << name;
    return static_cast<size_t>(it - head.begin());
  }
  double At(size_t row, const std::string& name) const { return std::stod(rows[row][Col(name)]); }
};

Csv ReadCsv(const std::string& path) {
  auto split = [](const std::string& line) {
    std::vector<std::string> out(1);
    for (char c : line) {
      if (c == ',')
        out.emplace_back();
      else
        out.back() += c;
    }
    return out;
  };
  Csv csv;
  std::ifstream in(path);
  std::string line;
  if (std::getline(in, line)) csv.head = split(line);
  while (std::getline(in, line))
    if (!line.empty()) csv.rows.push_back(split(line));
  return csv;
}

// Upper bound of mu for a Newtonian film in pure rolling. The wall shear stress of the
// Poiseuille profile is tau = -+(h/2) dp/dx on both surfaces (no Couette part), so
// mu = (|F1| + |F2|)/(2w) = |integral h dp/dx dx| / (2w) = |integral p dh/dx dx| / (2w)
// (by parts, p = 0 at both ends) <= max|dh/dx| / 2 where p > 0. Outside the Hertz zone the
// gap slope of the deformed surfaces, (|x| - sqrt(x^2 - b^2))/R, is below the rigid |x|/R, and
// the pressure starts after the inlet end x = -4.5 b (case_schema x_start_b default), so
// mu < 4.5 b / (2 R).
double RollingFrictionBound() {
  const double e_prime = ReducedModulus(206e9, 0.3, 206e9, 0.3);
  const double b = LineContactHertz(1e5, 0.01, e_prime).half_width_m;
  return 4.5 * b / (2 * 0.01);
}

TEST(ContactScene, SteadyDiscCaseConvergesAndWritesItsFiles) {
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = TempDir("steady").string();
  const ContactRunResult r =
      RunContactCase(std::string(TEHL_SOURCE_DIR) + "/cases/disc_steady.toml", o);
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_TRUE(fs::exists(r.profile_csv));
  EXPECT_FALSE(fs::exists(r.profile_csv + ".tmp"));
  // Film above the Hertz zone: h_min < h_c, and the peak pressure is at least p_H of
  // w = 100 kN/m on R = 10 mm steel (VALIDATION.md section 1: p_H = sqrt(w E'/(2 pi R))).
  const auto& s = r.steps[0];
  EXPECT_LT(s.h_min_m, s.h_c_m);
  const double e_prime = ReducedModulus(206e9, 0.3, 206e9, 0.3);
  EXPECT_GT(s.p_max_pa, 0.99 * LineContactHertz(1e5, 0.01, e_prime).max_pressure_pa);
  // The profile file has one row per node and a header.
  std::ifstream in(r.profile_csv);
  std::string line;
  int rows = -1;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 513);
}

// [output] profiles = false: only the steps file is written (the mesh cycle's rule).
TEST(ContactScene, ProfilesOffWritesOnlyTheStepsFile) {
  const fs::path dir = TempDir("no_profiles");
  const std::string path = DiscCase(dir, false, 129);
  std::ofstream(path, std::ios::app) << "[output]\nprofiles = false\n";
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = dir.string();
  const ContactRunResult r = RunContactCase(path, o);
  ASSERT_TRUE(r.converged());
  EXPECT_TRUE(r.profile_csv.empty());
  EXPECT_TRUE(fs::exists(r.history_csv));
  EXPECT_FALSE(fs::exists(dir / "disc_profile.csv"));
}

// Rigid, isoviscous, incompressible discs (effects elastic, piezoviscous, compressible off):
// the case's default grid is sized on the Martin length l = sqrt(2 R h0), not on the Hertz
// half-width (b = 34 um here, 0.3 l: an inlet at -4.5 b would starve the film by 44 %). The
// film is Martin's, h0 = 4.896 eta0 um R / w (VALIDATION.md section 2, tolerance 0.5 %), and
// it ruptures at x = 0.4751 l.
TEST(ContactScene, ARigidCaseGetsAGridOnTheMartinLengthAndMartinsFilm) {
  const fs::path dir = TempDir("rigid");
  const fs::path path = dir / "rigid.toml";
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\n"
                         "speed_2_m_s = 1.0\nload_n_per_m = 1.0e4\n[lubricant]\nname = \"sae40\"\n"
                         "inlet_temperature_k = 313.15\n[effects]\ntransient = false\n"
                         "elastic = false\npiezoviscous = false\ncompressible = false\n"
                         "[numerics]\ngrid_points = 1025\n";
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = dir.string();
  const ContactRunResult r = RunContactCase(path.string(), o);
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  const double eta0 = 0.1140574;  // SAE 40 at 313.15 K (seed 004 Table 2)
  const double radius = 0.01, um = 1.0, w = 1.0e4;
  const double h0 = 4.896 * eta0 * um * radius / w;
  const double l = std::sqrt(2 * radius * h0);
  EXPECT_NEAR(r.steps[0].h_min_m / h0, 1.0, 0.005);
  // The grid: the inlet 40 l upstream (x_start_b -4.5), the outlet 2 l downstream (1.5); the
  // pressure ends (film rupture) at 0.4751 l, within two cells.
  const Csv profile = ReadCsv(r.profile_csv);
  ASSERT_EQ(profile.rows.size(), 1025u);
  EXPECT_NEAR(profile.At(0, "x_m") / l, -40.0, 1e-6);  // CSV: 10 significant digits
  EXPECT_NEAR(profile.At(1024, "x_m") / l, 2.0, 1e-6);
  const double dx = (profile.At(1, "x_m") - profile.At(0, "x_m")) / l;
  double rupture = 0;
  for (size_t i = 0; i < profile.rows.size(); ++i)
    if (profile.At(i, "p_pa") > 0) rupture = profile.At(i, "x_m") / l;
  EXPECT_NEAR(rupture, 0.4751, 2 * dx);
}

TEST(ContactScene, LoadDoublingConvergesAtEveryStepAndThinsTheFilm) {
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = TempDir("step").string();
  const ContactRunResult r =
      RunContactCase(std::string(TEHL_SOURCE_DIR) + "/cases/disc_load_step.toml", o);
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_EQ(r.steps.size(), 101u);
  // Higher load, thinner film (seed 004 trend 4): the end state at 2w has a smaller h_c.
  EXPECT_LT(r.steps.back().h_c_m, r.steps.front().h_c_m);
}

// The load step of cases/disc_load_step.toml with sliding (SRR 0.4), the energy equation and
// the Ree-Eyring film, every step settled with a margin: at most half of the coupling's 40
// iterations. While the Eyring factor was relaxed on its own next to the temperature's Anderson
// step, a step of this run took 37 (of the full case, 100 steps to 2 ms, 40, and an earlier
// version stopped there: docs/studies.md "Known problems"); with the joint step, 15.
TEST(ContactScene, SlidingThermalEyringLoadStepConvergesAtEveryStep) {
  const fs::path dir = TempDir("eyring_step");
  const fs::path path = dir / "step.toml";
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.2\n"
                         "speed_2_m_s = 0.8\nload_n_per_m = 1.0e5\n"
                         "time_s = [0.0, 1.0e-4, 1.01e-4, 6.0e-4]\n"
                         "load_table_n_per_m = [1.0e5, 1.0e5, 2.0e5, 2.0e5]\nsteps = 30\n"
                         "[lubricant]\nname = \"sae40\"\n"
                         "[effects]\nthermal = true\nnon_newtonian = true\n"
                         "[numerics]\ngrid_points = 257\n";
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = (dir / "out").string();
  const ContactRunResult r = RunContactCase(path.string(), o);
  ASSERT_EQ(r.steps.size(), 31u);
  int most = 0;
  for (const ContactStepRecord& k : r.steps) {
    most = std::max(most, k.summary.coupling_iterations);
    EXPECT_TRUE(k.summary.usable()) << "t = " << k.time_s << " s: " << k.summary.BriefReport();
    EXPECT_GT(k.t_max_k, kInletK) << "t = " << k.time_s;
    // Shear-thinned friction of a sliding EHL film: a few hundredths (the Newtonian film at
    // these pressures gives tenths; docs/thermal.md, "Friction").
    EXPECT_GT(k.friction_coefficient, 0.01) << "t = " << k.time_s;
    EXPECT_LT(k.friction_coefficient, 0.1) << "t = " << k.time_s;
  }
  EXPECT_LT(r.steps.back().h_c_m, r.steps.front().h_c_m);  // twice the load, a thinner film
  std::printf("most coupling iterations in a step: %d\n", most);
  EXPECT_LE(most, LineContactSolver::Options{}.max_coupling_iterations / 2);
}

TEST(ContactScene, MovingWavinessMakesThePressureRippleAndConvergesEveryStep) {
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = TempDir("rough").string();
  const ContactRunResult r =
      RunContactCase(std::string(TEHL_SOURCE_DIR) + "/cases/disc_rough.toml", o);
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  // Seed 004 trend 3: roughness dominates the pressure ripple. A 0.1 um waviness passing
  // through a 0.6 GPa contact moves p_max by well over 10 % between steps, while the smooth
  // steady film has one p_max.
  double lo = 1e300, hi = 0;
  for (size_t k = r.steps.size() / 2; k < r.steps.size(); ++k) {
    lo = std::min(lo, r.steps[k].p_max_pa);
    hi = std::max(hi, r.steps[k].p_max_pa);
  }
  EXPECT_GT((hi - lo) / lo, 0.1);
}

// Isothermal: T_max is the inlet temperature itself (ContactStepRecord::t_max_k), mu of the
// rolling film is positive and below the Poiseuille bound, the step took time, and the files
// carry the new columns (and no t_mid_k in the profile).
TEST(ContactScene, IsothermalDiscRecordsTheInletTemperatureAndRollingFriction) {
  ContactRunOptions o;
  o.quiet = true;
  const fs::path d = TempDir("iso_columns");
  o.output_dir = d.string();
  const ContactRunResult r = RunContactCase(DiscCase(d, false, 257), o);
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  ASSERT_EQ(r.steps.size(), 1u);
  const ContactStepRecord& s = r.steps[0];
  EXPECT_EQ(s.t_max_k, kInletK);
  EXPECT_GT(s.friction_coefficient, 0.0);
  EXPECT_LT(s.friction_coefficient, RollingFrictionBound());
  EXPECT_GT(s.wall_time_s, 0.0);
  const Csv steps = ReadCsv(r.history_csv);
  ASSERT_EQ(steps.rows.size(), 1u);
  // Existing columns first and unchanged; the text column stays last.
  const std::vector<std::string> head = {"t_s",
                                         "w_n_per_m",
                                         "u1_m_s",
                                         "u2_m_s",
                                         "h_min_m",
                                         "h_c_m",
                                         "p_max_pa",
                                         "t_max_k",
                                         "mu",
                                         "wall_time_s",
                                         "spike_cells",
                                         "inlet_deficit",
                                         "newton_iterations",
                                         "coupling_iterations",
                                         "t1_max_k",
                                         "t2_max_k",
                                         "dT_flash_blok_k",
                                         "steady_restart",
                                         "edge_cells",
                                         "substeps",
                                         "time_error",
                                         "um_m_s",
                                         "SRR",
                                         "termination"};
  EXPECT_EQ(steps.head, head);
  // Counts and flags are integers; um and SRR of the disc's 1 m/s rolling.
  EXPECT_EQ(steps.rows[0][steps.Col("steady_restart")], "0");
  EXPECT_EQ(steps.rows[0][steps.Col("substeps")], "1");  // the steady solve: one piece
  EXPECT_DOUBLE_EQ(steps.At(0, "um_m_s"), 1.0);
  EXPECT_DOUBLE_EQ(steps.At(0, "SRR"), 0.0);
  // Isothermal: the surfaces stay at the inlet temperature.
  EXPECT_NEAR(steps.At(0, "t1_max_k"), kInletK, 1e-9 * kInletK);
  EXPECT_NEAR(steps.At(0, "t2_max_k"), kInletK, 1e-9 * kInletK);
  EXPECT_NEAR(steps.At(0, "dT_flash_blok_k"), s.flash_rise_blok_k,
              1e-9 * std::abs(s.flash_rise_blok_k) + 1e-300);
  // %.9e keeps 10 significant digits.
  EXPECT_NEAR(steps.At(0, "t_max_k"), kInletK, 1e-9 * kInletK);
  EXPECT_NEAR(steps.At(0, "mu"), s.friction_coefficient, 1e-9 * s.friction_coefficient);
  EXPECT_NEAR(steps.At(0, "wall_time_s"), s.wall_time_s, 1e-9 * s.wall_time_s);
  EXPECT_EQ(steps.At(0, "coupling_iterations"), s.summary.coupling_iterations);
  EXPECT_NEAR(steps.At(0, "spike_cells"), s.outlet_spike.found ? s.outlet_spike.width_cells : -1.0,
              1e-9);
  EXPECT_NEAR(steps.At(0, "edge_cells"), s.hertz_edge.width_cells, 1e-9 * s.hertz_edge.width_cells);
  EXPECT_GT(s.hertz_edge.width_cells, 10.0);  // this light disc resolves its edge
  const Csv profile = ReadCsv(r.profile_csv);
  EXPECT_EQ(profile.head, (std::vector<std::string>{"x_m", "p_pa", "h_m"}));
}

// Thermal pure rolling (converges: docs/studies.md "Known problems"): the film is heated by
// the Poiseuille shear and the inlet compression, so T_max > T0; mu as above (identical solids
// at one speed: T and eta are symmetric about mid-film, so the wall stresses stay
// -+(h/2) dp/dx and the bound holds); the coupling iterated; the profile has T_mid, never
// above T_max.
TEST(ContactScene, ThermalRollingDiscIsHotterThanItsInletWithPositiveFriction) {
  ContactRunOptions o;
  o.quiet = true;
  const fs::path d = TempDir("thermal_columns");
  o.output_dir = d.string();
  const ContactRunResult r = RunContactCase(DiscCase(d, true, 257), o);
  ASSERT_TRUE(r.converged()) << r.steps.back().summary.message;
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  const ContactStepRecord& s = r.steps[0];
  EXPECT_GT(s.t_max_k, kInletK);
  EXPECT_GT(s.friction_coefficient, 0.0);
  EXPECT_LT(s.friction_coefficient, RollingFrictionBound());
  EXPECT_GE(s.summary.coupling_iterations, 1);
  const Csv steps = ReadCsv(r.history_csv);
  ASSERT_EQ(steps.rows.size(), 1u);
  EXPECT_GT(steps.At(0, "t_max_k"), kInletK);
  EXPECT_GT(steps.At(0, "mu"), 0.0);
  EXPECT_GT(steps.At(0, "wall_time_s"), 0.0);
  const Csv profile = ReadCsv(r.profile_csv);
  ASSERT_EQ(profile.head,
            (std::vector<std::string>{"x_m", "p_pa", "h_m", "t_mid_k", "t1_k", "t2_k"}));
  ASSERT_EQ(profile.rows.size(), 257u);
  double t_mid_max = 0, t1_max = 0, t2_max = 0;
  for (size_t i = 0; i < profile.rows.size(); ++i) {
    t_mid_max = std::max(t_mid_max, profile.At(i, "t_mid_k"));
    t1_max = std::max(t1_max, profile.At(i, "t1_k"));
    t2_max = std::max(t2_max, profile.At(i, "t2_k"));
  }
  EXPECT_GT(t_mid_max, kInletK);
  EXPECT_LE(t_mid_max, s.t_max_k * (1 + 1e-9));
  // The surface profiles' maxima are the steps file's (written from the same film, %.10g).
  EXPECT_NEAR(t1_max, steps.At(0, "t1_max_k"), 1e-9 * t1_max);
  EXPECT_NEAR(t2_max, steps.At(0, "t2_max_k"), 1e-9 * t2_max);
}

// The guard: a NaN or Inf is refused before any byte is formatted, naming file, column, row.
TEST(ContactScene, NonFiniteValuesAreRefusedWithTheirColumnAndRow) {
  std::vector<ContactStepRecord> steps(3);
  for (auto& s : steps) s.summary.termination = LineContactSolver::Termination::kConverged;
  EXPECT_NO_THROW(internal::ContactStepsCsv("a_steps.csv", steps));
  steps[1].friction_coefficient = std::nan("");
  try {
    internal::ContactStepsCsv("a_steps.csv", steps);
    ADD_FAILURE() << "a NaN mu was formatted";
  } catch (const NonFiniteError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("a_steps.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("mu[1]"), std::string::npos) << what;
  }
  const std::vector<double> x = {0, 1, 2}, p = {0, 1, 0}, h = {1, 1, 1};
  EXPECT_NO_THROW(internal::ContactProfileCsv("a_profile.csv", x, p, h, {}));
  try {
    internal::ContactProfileCsv("a_profile.csv", x, p, h, {300, 310, HUGE_VAL});
    ADD_FAILURE() << "an infinite T_mid was formatted";
  } catch (const NonFiniteError& e) {
    EXPECT_NE(std::string(e.what()).find("t_mid_k[2]"), std::string::npos) << e.what();
  }
}

// An effect the case cannot have: the Ree-Eyring film with a lubricant that has no [eyring]
// section is rejected at its line before any solve.
TEST(ContactScene, EffectWithoutItsDataExitsWithCode2) {
  std::string out;
  const fs::path d = TempDir("bad");
  const fs::path bad = d / "eyring.toml";
  std::ofstream(bad) << "[contact]\nradius_1_m = 0.02\nspeed_1_m_s = 1.0\nspeed_2_m_s = 1.0\n"
                        "load_n_per_m = 1e5\n[lubricant]\nname = \"reference_z068\"\n[effects]\n"
                        "non_newtonian = true\n";
  EXPECT_EQ(RunTehl("run " + bad.string(), &out), 2) << out;
  EXPECT_NE(out.find(bad.string() + ":9: effects.non_newtonian = true"), std::string::npos) << out;
}

}  // namespace
}  // namespace tehl
