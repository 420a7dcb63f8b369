// `tehl gear`: the report, the along-path CSV, the profile CSV, and exit code 2 with a
// message that says what to change for bad geometry (cases written into a temp folder).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Result {
  int code = -1;
  std::string out, err;
};

std::string Slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A numeric CSV: the header line and the rows as numbers.
struct NumericCsv {
  std::string header;
  std::vector<std::vector<double>> rows;
};
NumericCsv ReadNumericCsv(const fs::path& p) {
  NumericCsv t;
  std::ifstream in(p);
  std::getline(in, t.header);
  for (std::string line; std::getline(in, line);) {
    std::stringstream row(line);
    t.rows.emplace_back();
    for (std::string cell; std::getline(row, cell, ',');) t.rows.back().push_back(std::stod(cell));
  }
  return t;
}

class GearCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tehl_gear_cli_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Result Tehl(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = std::string("cd ") + TEHL_SOURCE_DIR + " && " + TEHL_BINARY + " " +
                            args + " > " + out.string() + " 2> " + err.string();
    const int status = std::system(cmd.c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = Slurp(out);
    r.err = Slurp(err);
    return r;
  }

  // A case file in the temp folder: the seed 004 pair with `gear`, `pinion` and `wheel`
  // lines added to their sections.
  fs::path Case(const std::string& name,
                const std::string& gear,
                const std::string& pinion,
                const std::string& wheel = "") {
    const fs::path p = dir_ / name;
    std::ofstream(p) << "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\n"
                     << gear << "[gear.pinion]\nteeth = 35\n"
                     << pinion << "[gear.wheel]\nteeth = 105\n"
                     << wheel
                     << "[operating]\npinion_speed_rpm = 1000.0\npower_w = 10000.0\n"
                        "[lubricant]\nname = \"sae40\"\n[numerics]\ngrid_points = 257\n";
    return p;
  }

  // `tehl gear` on a case file `name` with the whole text `text`.
  Result GearReport(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return Tehl("gear " + p.string());
  }

  fs::path dir_;
};

TEST_F(GearCommand, Seed004ReportHasTheValidationNumbers) {
  // VALIDATION.md section 5: eps_alpha = 1.7722; A..E = 6.486 / 11.046 / 11.971 / 12.390 /
  // 16.950 mm from T1; w = 116.14 kN/m; R = 8.978 mm, um = 1.254 m/s, p_H ~ 522 MPa at C.
  const Result r = Tehl("gear cases/seed004_sae40.toml");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* s : {"eps_alpha = 1.7722", "A 6.486  B 11.046  C 11.971  D 12.390  E 16.950",
                        "AE 10.464", "w = F_bt / b = 116.139 kN/m", "R = 8.978 mm, um = 1.2536 m/s",
                        "p_H = 521.9 MPa", "potential_energy", "c_gamma_alpha"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
}

TEST_F(GearCommand, CsvHasUnitsInTheHeaderAndOneRowPerSample) {
  const fs::path csv = dir_ / "cycle.csv";
  const Result r = Tehl("gear cases/fzg_c.toml --points 11 --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("s_m,t_s,rho1_m,rho2_m,R_m,u1_m_s,u2_m_s,um_m_s,SRR,v_slide_m_s,"
                         "k_pair_n_per_m,k_mesh_n_per_m,share,w_n_per_m",
                         0),
            0u)
      << header;
  int rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 15);  // 11 samples + both sides of B and D
}

TEST_F(GearCommand, TipReliefCaseReportsTheReliefAndTheTransmissionError) {
  // In single contact the one pair carries F_bt = w b, so the static transmission error is
  // w b / k_mesh there, with or without relief (tip_relief.hpp).
  const fs::path csv = dir_ / "relief.csv";
  const Result r =
      Tehl("gear cases/seed004_sae40_tip_relief.toml --points 41 --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("static transmission error under F_bt:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mm before E (linear)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("loaded part of the path"), std::string::npos) << r.out;
  const NumericCsv t = ReadNumericCsv(csv);
  ASSERT_NE(t.header.find(",ste_m"), std::string::npos) << t.header;
  int single = 0;
  for (const std::vector<double>& v : t.rows) {
    ASSERT_EQ(v.size(), 18u);
    const double k_mesh = v[11], w = v[13], pairs = v[16], ste = v[17];
    if (pairs != 1) continue;
    EXPECT_NEAR(ste * k_mesh, w * 0.025, 1e-9 * w * 0.025);  // face width 25 mm
    ++single;
  }
  EXPECT_GT(single, 3);
}

TEST_F(GearCommand, MuGivesBlokFlashTemperatureAlongThePath) {
  // theta = c_B mu w |u1 - u2| / (sqrt(b) e (sqrt(u1) + sqrt(u2))) with the seed 004 bronze on
  // both gears (VALIDATION.md section 5: E = 117 GPa, nu = 0.34, rho = 7890 kg/m^3,
  // k = 55 W/(m K), c = 375 J/(kg K)), b = sqrt(8 w R / (pi E')) at the row's w, and
  // c_B = 0.785983 (docs/thermal.md "Flash temperature"). Zero at the pitch point's rolling.
  const fs::path csv = dir_ / "flash.csv";
  const Result r =
      Tehl("gear cases/seed004_sae40.toml --mu 0.05 --points 21 --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Flash temperature (Blok, mu = 0.05"), std::string::npos) << r.out;
  const NumericCsv t = ReadNumericCsv(csv);
  ASSERT_NE(t.header.find(",ste_m,dT_flash_blok_k"), std::string::npos) << t.header;
  const double e_prime = 117e9 / (1 - 0.34 * 0.34), e = std::sqrt(55.0 * 7890.0 * 375.0);
  int rows = 0;
  for (const std::vector<double>& v : t.rows) {
    ASSERT_EQ(v.size(), 19u);
    const double radius = v[4], u1 = v[5], u2 = v[6], w = v[13], flash = v[18];
    const double b = std::sqrt(8 * w * radius / (M_PI * e_prime));
    const double expected = 0.785983 * 0.05 * w * std::abs(u1 - u2) /
                            (std::sqrt(b) * e * (std::sqrt(u1) + std::sqrt(u2)));
    EXPECT_NEAR(flash, expected, 1e-5 * expected + 1e-12) << "row " << rows;
    ++rows;
  }
  EXPECT_EQ(rows, 25);  // 21 samples + both sides of B and D
  // A negative mu is refused (exit 2, the command line).
  EXPECT_EQ(Tehl("gear cases/seed004_sae40.toml --mu -0.1").code, 2);
}

TEST_F(GearCommand, FinitePecletCaseGivesBlokWithJaegersKernel) {
  // The same case with [effects] finite_peclet = true: Blok's partition with Jaeger's kernel
  // at each tooth's Peclet number (docs/thermal.md "Flash temperature"), which stays below the
  // high-Peclet value and approaches it as Pe grows (FinitePecletFlashTemperature tests: 2.6 %
  // below at Pe 1.31 of the slower solid, 0.6 % at 3). The pinion's Pe is 1.31 at A and about
  // 4.8 at the pitch point, so A is lowered most.
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("thermal = true");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, "finite_peclet = true\n");
  const fs::path case_file = dir_ / "finite_peclet.toml";
  std::ofstream(case_file) << text;
  const fs::path high_csv = dir_ / "high.csv", finite_csv = dir_ / "finite.csv";
  ASSERT_EQ(
      Tehl("gear cases/seed004_sae40.toml --mu 0.05 --points 21 --csv " + high_csv.string()).code,
      0);
  const Result r =
      Tehl("gear " + case_file.string() + " --mu 0.05 --points 21 --csv " + finite_csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Flash temperature (Blok, finite Peclet, mu = 0.05"), std::string::npos)
      << r.out;
  const NumericCsv high = ReadNumericCsv(high_csv), finite = ReadNumericCsv(finite_csv);
  ASSERT_EQ(high.rows.size(), finite.rows.size());
  for (size_t i = 0; i < high.rows.size(); ++i) {
    const double h = high.rows[i][18], f = finite.rows[i][18];
    if (h == 0) {
      EXPECT_EQ(f, 0.0) << "row " << i;
      continue;
    }
    EXPECT_LT(f, h) << "row " << i;
    EXPECT_GT(f, 0.95 * h) << "row " << i;
  }
  const double at_a = finite.rows.front()[18] / high.rows.front()[18];
  const double near_c =
      finite.rows[high.rows.size() / 2 + 1][18] / high.rows[high.rows.size() / 2 + 1][18];
  EXPECT_LT(at_a, near_c);
}

TEST_F(GearCommand, ProfileCsvListsBothGears) {
  const fs::path csv = dir_ / "profile.csv";
  const Result r = Tehl("gear cases/asymmetric_35_20.toml --profile " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = Slurp(csv);
  EXPECT_EQ(text.rfind("gear,flank,x_m,y_m\n", 0), 0u);
  for (const char* s : {"pinion,drive,", "pinion,coast,", "wheel,drive,", "wheel,tip,"})
    EXPECT_NE(text.find(s), std::string::npos) << s;
}

// Asymmetric teeth have one undercut limit per flank, x_min = h_F0 - z sin^2(alpha) / 2 with
// h_F0 = h_fP - rho_fP (1 - sin alpha) where the rack's straight flank of that side ends
// (docs/gear.md): for the 35-tooth pinion of cases/asymmetric_35_20.toml (h_fP = 1.25,
// rho_fP = 0.15) 1.18604 - 35 sin^2(35 deg) / 2 = -4.5713 on the drive flank and 1.15130 - 35
// sin^2(20 deg) / 2 = -0.8958 on the coast flank, which governs.
TEST_F(GearCommand, AsymmetricReportGivesTheUndercutLimitOfEachFlank) {
  const Result r = Tehl("gear cases/asymmetric_35_20.toml");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto limit = [](double deg) {
    const double s = std::sin(deg * M_PI / 180);
    return 1.25 - 0.15 * (1 - s) - 35 * s * s / 2;
  };
  char drive[32], coast[32];
  std::snprintf(drive, sizeof drive, "%.4f", limit(35.0));
  std::snprintf(coast, sizeof coast, "%.4f", limit(20.0));
  const size_t d = r.out.find("x_min without undercut, drive");
  const size_t c = r.out.find("x_min without undercut, coast");
  ASSERT_NE(d, std::string::npos) << r.out;
  ASSERT_NE(c, std::string::npos) << r.out;
  EXPECT_EQ(r.out.substr(d, 60).find(drive) != std::string::npos, true) << drive << r.out;
  EXPECT_EQ(r.out.substr(c, 60).find(coast) != std::string::npos, true) << coast << r.out;
}

// And one form circle per flank, where the rack's straight flank of that side ends:
// r_F^2 = r_b^2 + (r sin(alpha) - h_F0 m / sin(alpha))^2 (x = 0; ISO 21771), for the pinion
// (r = 35 mm, m = 2 mm): 32.8033 mm on the 35 deg drive flank, 33.3038 mm on the 20 deg coast
// flank (hand calculation).
TEST_F(GearCommand, AsymmetricReportGivesTheFormCircleOfEachFlank) {
  const Result r = Tehl("gear cases/asymmetric_35_20.toml");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto form = [](double deg) {
    const double a = deg * M_PI / 180, h = 1.25 - 0.15 * (1 - std::sin(a));
    const double q = 35 * std::sin(a) - h * 2 / std::sin(a);
    return std::hypot(35 * std::cos(a), q);
  };
  for (const auto& [flank, deg] :
       {std::pair<const char*, double>{"drive", 35.0}, {"coast", 20.0}}) {
    char want[32];
    std::snprintf(want, sizeof want, "%.4f", form(deg));
    const size_t at = r.out.find(std::string("form radius r_F, ") + flank);
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_NE(r.out.substr(at, 60).find(want), std::string::npos) << want << "\n" << r.out;
  }
}

// The film estimates at A .. E. At the pitch point of seed 004 (SAE 40, 10 kW, 1000 rpm)
// VALIDATION.md section 5 gives Moes' h_c = 0.88 um and Pan-Hamrock's 0.73 um; the rough case
// (0.1 um sinusoidal waviness on both surfaces: Rq = sqrt(2) 0.1 / sqrt(2) = 0.1 um) has
// lambda = h_min / 0.1 um on every row.
TEST_F(GearCommand, FilmEstimatesAtThePointsOfThePath) {
  const auto row = [](const std::string& out, const std::string& point) {
    const size_t head = out.find("Film estimates");
    EXPECT_NE(head, std::string::npos) << out;
    const size_t at = out.find("\n  " + point + " ", head);
    EXPECT_NE(at, std::string::npos) << out;
    std::istringstream in(out.substr(at + 4 + point.size()));
    std::vector<double> v(9, 0.0);
    for (double& x : v) in >> x;  // s, R, um, w, p_H, h_c PH, h_min PH, h_c Moes, lambda
    return v;
  };
  const Result r = Tehl("gear cases/seed004_sae40.toml");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<double> c = row(r.out, "C");
  EXPECT_NEAR(c[1], 8.978, 0.001);                     // R [mm] (VALIDATION.md section 5)
  EXPECT_NEAR(c[4], 521.9, 0.1);                       // p_H [MPa]
  EXPECT_NEAR(c[5], 0.73, 0.005);                      // Pan-Hamrock h_c [um]
  EXPECT_NEAR(c[7], 0.88, 0.005);                      // Moes h_c [um]
  EXPECT_EQ(r.out.find("lambda"), std::string::npos);  // smooth surfaces
  const Result rough = Tehl("gear cases/seed004_sae40_rough.toml");
  ASSERT_EQ(rough.code, 0) << rough.err;
  for (const char* p : {"A", "B", "C", "D", "E"}) {
    const std::vector<double> v = row(rough.out, p);
    EXPECT_NEAR(v[8], v[6] / 0.1, 0.01) << p;
  }
}

TEST_F(GearCommand, EveryCaseOfTheRepositoryIsValid) {
  const Result r = Tehl(
      "case --check cases/seed004_sae40.toml cases/seed004_sae90.toml "
      "cases/fzg_c.toml cases/asymmetric_35_20.toml cases/steel_62_62.toml");
  EXPECT_EQ(r.code, 0) << r.err;
  for (const char* c : {"seed004_sae90", "fzg_c", "asymmetric_35_20", "steel_62_62"}) {
    const Result g = Tehl(std::string("gear cases/") + c + ".toml");
    EXPECT_EQ(g.code, 0) << c << ": " << g.err;
  }
}

TEST_F(GearCommand, UndercutPinionExitsTwoSayingWhatToChange) {
  const fs::path p = Case("undercut.toml", "", "profile_shift = 0.0\n");
  std::string text = Slurp(p);
  text.replace(text.find("teeth = 35"), 10, "teeth = 14");
  text.replace(text.find("teeth = 105"), 11, "teeth = 20");
  std::ofstream(p) << text;
  const Result r = Tehl("gear " + p.string());
  EXPECT_EQ(r.code, 2);
  // x_min = h_F0 - 14 sin^2(20)/2 = 0.99997 - 0.81884 = 0.18112 (ISO 53 rack: h_F0 = 1.25 -
  // 0.38 (1 - sin 20 deg)); line 6 holds the shift.
  EXPECT_NE(r.err.find(p.string() + ":6: gear.pinion.profile_shift = 0.0: the pinion is undercut"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("profile_shift >= 0.1811"), std::string::npos) << r.err;
}

TEST_F(GearCommand, PointedToothExitsTwo) {
  // 12 teeth with x = 0.9: the flanks meet below r + m (1 + x) (gear_pair_test).
  const fs::path p = Case("pointed.toml", "", "profile_shift = 0.9\n");
  std::string text = Slurp(p);
  text.replace(text.find("teeth = 35"), 10, "teeth = 12");
  std::ofstream(p) << text;
  const Result r = Tehl("gear " + p.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("gear.pinion.profile_shift = 0.9: the pinion tooth is pointed"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("tip_radius_m below"), std::string::npos) << r.err;
}

TEST_F(GearCommand, ImpossibleCenterDistanceExitsTwo) {
  const Result r = Tehl("gear " + Case("a.toml", "center_distance_m = 0.130\n", "").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(":4: gear.center_distance_m = 0.13: a = 130.0000 mm is below the sum of "
                       "the base radii"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("center_distance_m >= 0.140000"), std::string::npos) << r.err;
}

TEST_F(GearCommand, InterferenceAndLowContactRatioExitTwo) {
  const Result r =
      Tehl("gear " +
           Case("eps.toml", "", "tip_radius_m = 0.0355\n", "tip_radius_m = 0.1055\n").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("gear.pinion.tip_radius_m"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("< 1: the mesh is not continuous"), std::string::npos) << r.err;
  // The hard limit is 1, with 1.2 the recommended minimum (seed 003 section 4.1).
  EXPECT_NE(r.err.find("allowed: eps_alpha >= 1, 1.2 or more recommended"), std::string::npos)
      << r.err;
}

TEST_F(GearCommand, AsymmetricRackThatDoesNotFitExitsTwo) {
  const Result r = Tehl("gear " + Case("rack.toml",
                                       "pressure_angle_deg = 35.0\n"
                                       "coast_pressure_angle_deg = 20.0\n",
                                       "")
                                      .string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("gear.root_fillet_coefficient = 0.38: the rack tip radius rho_fP = "
                       "0.3800 m_n does not fit"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("root_fillet_coefficient <= 0.1971"), std::string::npos) << r.err;
}

// A high-contact-ratio pair (40/80, 18 deg, h_aP = 1.25: eps_alpha = 2.3032) has no single
// contact zone: the report says so instead of a B-D length of 0 with B after D.
TEST_F(GearCommand, AHighContactRatioPairHasNoSingleContactZone) {
  const Result r =
      GearReport("hcr.toml",
                 "[gear]\nmodule_m = 0.002\nface_width_m = 0.02\npressure_angle_deg = 18.0\n"
                 "addendum_coefficient = 1.25\ndedendum_coefficient = 1.5\n"
                 "root_fillet_coefficient = 0.25\n[gear.pinion]\nteeth = 40\n"
                 "[gear.wheel]\nteeth = 80\n[operating]\npinion_speed_rpm = 1500.0\n"
                 "power_w = 5000.0\n[lubricant]\nname = \"sae40\"\n");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("no single contact (eps_alpha = 2.3032 >= 2"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("single contact B-D"), std::string::npos) << r.out;
}

// A profile-shifted pair at its zero-backlash distance without tip shortening (12/24, m =
// 3 mm, x = 0.6/0.36). By hand: inv a_w = inv 20 deg + 2 tan 20 deg (0.96) / 36 = 0.034316,
// a_w = 26.0886 deg, a = 54 cos 20 deg / cos a_w = 56.4999 mm; r_a1 = 18 + 3 (1 + 0.6) =
// 22.8 mm, r_f2 = 36 - 3 (1.25 - 0.36) = 33.33 mm, so c = a - r_a1 - r_f2 = 0.3699 mm =
// 0.123 m_n (the same on the wheel's tip), where the basic rack gives 0.25 m_n: a warning on
// each member, and the run goes on.
TEST_F(GearCommand, ATipClearanceLostToProfileShiftIsWarned) {
  const Result r =
      GearReport("khk.toml",
                 "[gear]\nmodule_m = 0.003\nface_width_m = 0.02\n[gear.pinion]\nteeth = 12\n"
                 "profile_shift = 0.6\n[gear.wheel]\nteeth = 24\nprofile_shift = 0.36\n"
                 "[operating]\npinion_speed_rpm = 1500.0\npower_w = 5000.0\n"
                 "[lubricant]\nname = \"sae40\"\n");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("warning: gear.pinion.profile_shift: the pinion tip clears the wheel's root "
                       "circle by only 0.3699 mm (0.123 m_n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("gear.wheel.profile_shift: the wheel tip clears"), std::string::npos)
      << r.out;
}

// An internal pair 20/24 (m = 3 mm, ring tip 34.5 mm) passes the checks on the line of action
// but is warned of the interference outside it that a 4-tooth difference makes likely.
TEST_F(GearCommand, AnInternalPairWithFewTeethDifferenceIsWarned) {
  const Result r =
      GearReport("ring.toml",
                 "[gear]\nmodule_m = 0.003\nface_width_m = 0.02\ninternal = true\n"
                 "mesh_stiffness = \"iso\"\n[gear.pinion]\nteeth = 20\n[gear.wheel]\n"
                 "teeth = 24\ntip_radius_m = 0.0345\n[operating]\npinion_speed_rpm = 1500.0\n"
                 "power_w = 5000.0\n[lubricant]\nname = \"sae40\"\n");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("warning: gear.wheel.teeth: the ring has only 4 teeth more than the pinion"),
            std::string::npos)
      << r.out;
}

// A helical pair: the spur-tooth stiffness methods are not applicable (the case reader refuses
// them), and the torsional dynamics, which mesh spur teeth, refuse the helix.
TEST_F(GearCommand, AHelicalPairGetsNoSpurStiffnessAndNoDynamics) {
  const fs::path p = Case("helical.toml", "helix_angle_deg = 15.0\nmesh_stiffness = \"iso\"\n", "");
  const Result r = Tehl("gear " + p.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("potential_energy: not applicable: a spur-tooth model"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("kuang_yang: not applicable: a spur-tooth model"), std::string::npos)
      << r.out;
  const Result d = Tehl("dynamics " + p.string() + " -o " + (dir_ / "dyn").string());
  EXPECT_EQ(d.code, 2) << d.out;
  EXPECT_NE(d.err.find("gear.helix_angle_deg = 15.0: the torsional dynamics mesh spur teeth"),
            std::string::npos)
      << d.err;
}

}  // namespace
