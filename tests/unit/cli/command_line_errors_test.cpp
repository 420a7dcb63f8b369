// The real program's answers to mistakes of the command line and of the environment (not of a
// case file's keys, which tests/malformed/ covers): each is exit code 2 with a message naming
// what was wrong, never an internal error (exit 3); and a run that stops says which rows of
// its table did not converge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

std::string SourcePath(const std::string& relative) {
  return std::string(TEHL_SOURCE_DIR) + "/" + relative;
}

// The seed 004 pair (35/105 teeth, m = 2 mm, SAE 40) with the given [operating] speed line and
// extra sections.
std::string GearCase(const std::string& speed_line, const std::string& extra = "") {
  return "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\n"
         "[gear.pinion]\nteeth = 35\n[gear.wheel]\nteeth = 105\n"
         "[operating]\n" + speed_line + "\npower_w = 10000.0\n"
         "[lubricant]\nname = \"sae40\"\n" + extra;
}

TEST(CommandLineErrors, AMistypedCommandIsNamedWithTheAllowedOnes) {
  const testing::RunResult r = testing::RunTehl("rn cases/disc_steady.toml");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown command 'rn'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("run"), std::string::npos) << r.err;
}

// `tehl run -q cases/disc_steady.toml -o DIR`.
testing::RunResult RunDiscInto(const std::string& dir) {
  return testing::RunTehl("run -q '" + SourcePath("cases/disc_steady.toml") + "' -o '" + dir + "'");
}

// Exit 2 with "cannot write the results" naming `path`, never an internal error.
void ExpectCannotWrite(const testing::RunResult& r, const std::string& path) {
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("cannot write the results"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
}

TEST(CommandLineErrors, AnOutputFolderThatIsAFileIsBadInput) {
  const std::string file = testing::UniqueTempPath("not_a_folder");
  std::ofstream(file) << "x";
  const testing::RunResult r = RunDiscInto(file);
  fs::remove(file);
  ExpectCannotWrite(r, file);
}

// A result table that cannot be written once the run is done (here a folder in the way of the
// profile CSV's temporary name; a full disk fails the same way) is the environment's fault:
// exit 2 naming the path, as for an output folder that is a file, not an internal error.
TEST(CommandLineErrors, AResultFileThatCannotBeWrittenIsBadInput) {
  const std::string dir = testing::UniqueTempPath("blocked_results");
  const std::string blocked = dir + "/disc_steady_profile.csv.part";
  fs::create_directories(blocked);
  const testing::RunResult r = RunDiscInto(dir);
  fs::remove_all(dir);
  ExpectCannotWrite(r, blocked);
}

// A plot needs a Python with matplotlib and h5py: one that cannot be started is named with
// what is needed (exit 2, the environment's fault), never "internal error".
TEST(CommandLineErrors, APythonThatCannotStartIsNamedWithWhatThePlotNeeds) {
  const std::string result = testing::UniqueTempPath("any_result.h5");
  std::ofstream(result) << "not read";
  setenv("TEHL_PYTHON", "/nonexistent/python3", 1);
  const testing::RunResult r = testing::RunTehl("plot '" + result + "'");
  unsetenv("TEHL_PYTHON");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("cannot start /nonexistent/python3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("matplotlib and h5py"), std::string::npos) << r.err;
}

TEST(CommandLineErrors, AFolderGivenAsTheCaseFileIsNamedAsAFolder) {
  const std::string dir = testing::UniqueTempPath("case_folder.toml");
  fs::create_directories(dir);
  const testing::RunResult r = testing::RunTehl("run '" + dir + "'");
  fs::remove(dir);
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("is a folder"), std::string::npos) << r.err;
  // Reported once, as a folder, not also as a case without sections.
  EXPECT_EQ(r.err.find("required section"), std::string::npos) << r.err;
}

// A device (here /dev/zero, which never ends) is not read as a case file: it is named as not
// a regular file, and the program neither hangs nor runs out of memory.
TEST(CommandLineErrors, ADeviceGivenAsTheCaseFileIsRefused) {
  const testing::RunResult r = testing::RunTehl("case --check /dev/zero");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
}

// Barus' eta0 exp(alpha p) with alpha = 1e-7 1/Pa overflows above p = ln(DBL_MAX) / alpha =
// 7.1 GPa: a table from 8 GPa is refused at --p instead of printing inf and NaN.
TEST(CommandLineErrors, ALubricantTableBeyondTheLawsRangeIsRefused) {
  const std::string path = testing::UniqueTempPath("barus.toml");
  std::ifstream in(SourcePath("lubricants/sae40.toml"));
  std::ostringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const size_t v = s.find("[viscosity]");
  ASSERT_NE(v, std::string::npos);
  const size_t end = s.find("\n[", v + 1);
  s.replace(v, end - v,
            "[viscosity]\nmodel = \"barus\"\nviscosity_pa_s = 1.0\n"
            "pressure_coefficient_per_pa = 1e-7\ntemperature_coefficient_per_k = 0.0");
  std::ofstream(path) << s;
  const testing::RunResult ok = testing::RunTehl("lubricant '" + path + "' --p 0:7e9:3");
  ASSERT_TRUE(ok.exited);
  EXPECT_EQ(ok.exit_code, 0) << ok.err << ok.out;
  const testing::RunResult r = testing::RunTehl("lubricant '" + path + "' --p 8e9:1e10:3");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err << r.out;
  EXPECT_NE(r.err.find("--p"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("inf"), std::string::npos) << r.out;
}

// `tehl dynamics --speeds` given empty, or beyond 1e6 rpm, is refused at --speeds (it used to
// skip the sweep silently, or to print a factor of 0 at 1e300 rpm).
TEST(CommandLineErrors, ADynamicsSweepOutsideGearSpeedsIsRefused) {
  for (const char* speeds : {"''", "1e300:1e301:1e300"}) {
    const testing::RunResult r = testing::RunTehl(
        "dynamics '" + SourcePath("cases/seed004_sae40_dynamic.toml") + "' --no-plot -o '" +
        testing::UniqueTempPath("dyn") + "' --speeds " + speeds);
    ASSERT_TRUE(r.exited) << speeds;
    EXPECT_EQ(r.exit_code, 2) << speeds << "\n" << r.err;
    EXPECT_NE(r.err.find("--speeds"), std::string::npos) << r.err;
  }
}

// A sweep beyond the pitch-line speeds a case accepts (200 m/s) is refused as the case key is:
// the seed 004 pinion (r = 35 mm, 35 teeth of 2 mm) reaches 200 m/s at 200 / (pi/30 * 0.035)
// = 54567 rpm.
TEST(CommandLineErrors, ADynamicsSweepBeyondTheCasesPitchLineSpeedIsRefused) {
  const testing::RunResult r = testing::RunTehl(
      "dynamics '" + SourcePath("cases/seed004_sae40_dynamic.toml") + "' --no-plot -o '" +
      testing::UniqueTempPath("dyn") + "' --speeds 50000:100000:50000");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--speeds"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("366.5 m/s"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("up to 54567 rpm"), std::string::npos) << r.err;
}

TEST(CommandLineErrors, ASpeedOfTheWrongTypeIsNotAlsoReportedMissing) {
  const std::string path = testing::UniqueTempPath("string_speed.toml");
  std::ofstream(path) << GearCase("pinion_speed_rpm = \"1000 rpm\"");
  const testing::RunResult r = testing::RunTehl("case --check '" + path + "'");
  std::remove(path.c_str());
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("wrong type"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("missing"), std::string::npos) << r.err;
}

// A gear run whose first step cannot converge (one Newton iteration allowed) stops with exit
// code 1, and its cycle CSV marks that row converged = 0 (and steady_restart = 0: the steady
// film at A has nothing to restart from).
TEST(CommandLineErrors, AStoppedRunMarksItsUnconvergedRowInTheCycleCsv) {
  const std::string dir = testing::UniqueTempPath("stopped_run");
  const std::string path = dir + "/stopped.toml";
  fs::create_directories(dir);
  std::ofstream(path) << GearCase("pinion_speed_rpm = 1000.0",
                                  "[numerics]\ngrid_points = 65\nsteps = 4\n"
                                  "max_newton_iterations = 1\n");
  const testing::RunResult r = testing::RunTehl("run -q '" + path + "' -o '" + dir + "'");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  std::ifstream csv(dir + "/stopped_cycle.csv");
  ASSERT_TRUE(csv.good()) << r.err;
  std::string header, row, last;
  std::getline(csv, header);
  while (std::getline(csv, row))
    if (!row.empty()) last = row;
  fs::remove_all(dir);
  // The columns by name (readers look them up so: docs/results.md).
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    return cells;
  };
  const std::vector<std::string> names = split(header), cells = split(last);
  ASSERT_EQ(cells.size(), names.size()) << last;
  auto at = [&](const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    EXPECT_NE(it, names.end()) << name << " in " << header;
    return it == names.end() ? std::nan("") : std::stod(cells[it - names.begin()]);
  };
  EXPECT_EQ(at("converged"), 0.0) << last;
  EXPECT_EQ(at("steady_restart"), 0.0) << last;
}

// A waviness spanning few cells of the grid: `case --check` says how many and the grid that
// resolves it (15 cells per wave, docs/studies.md "Roughness grid"). The seed 004 pair in the
// default steel on 129 nodes over -4.5 .. 1.5 b_max (b_max = 109.4 um: dx = 5.13 um) with
// 50 um waves: 9.7 cells; 257 nodes give 19.5 (twice as many).
TEST(CommandLineErrors, AWavinessOnTooFewCellsIsNotedWithTheGridThatResolvesIt) {
  const std::string path = testing::UniqueTempPath("wavy.toml");
  const std::string waves =
      "[effects]\nroughness = true\n"
      "[surfaces.surface1]\nroughness = \"sinusoidal\"\namplitude_m = 1e-7\nwavelength_m = 5e-5\n"
      "[numerics]\ngrid_points = 129\n";
  std::ofstream(path) << GearCase("pinion_speed_rpm = 1000.0", waves);
  const testing::RunResult r = testing::RunTehl("case --check '" + path + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("the waviness of surface1 (50 um) spans 9.7 cells"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("grid_points = 257 gives 19"), std::string::npos) << r.out;
  std::string fine = testing::ReadAll(path);
  fine.replace(fine.find("grid_points = 129"), 17, "grid_points = 257");
  std::ofstream(path) << fine;
  const testing::RunResult ok = testing::RunTehl("case --check '" + path + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.out.find("waviness"), std::string::npos) << ok.out;
}

// A waviness of 50 um written as wavelength_m = 50.0 is, across the seed 004 pair's film grid,
// an offset the film takes up: `case --check` notes it with the unit slip. The grid spans
// -4.5 .. 1.5 b_max, b_max = (8 w R / (pi E'))^(1/2) = 109.5 um at D in the default steel
// (w = 116.14 kN/m, R = 9.184 mm, E' = 226.4 GPa; VALIDATION.md sections 1 and 5): 0.657 mm,
// so 50 m is 7.61e4 grids. The 50 um wave (0.076 grids) and a 5 mm one (7.6 grids, a form
// deviation across the contact) are not noted.
TEST(CommandLineErrors, AWavinessLongerThanTenGridsIsNotedAsNoRoughness) {
  const std::string path = testing::UniqueTempPath("long_wave.toml");
  auto check = [&](const std::string& wavelength) {
    std::ofstream(path, std::ios::trunc) << GearCase(
        "pinion_speed_rpm = 1000.0",
        "[effects]\nroughness = true\n"
        "[surfaces.surface1]\nroughness = \"sinusoidal\"\namplitude_m = 1e-7\nwavelength_m = " +
            wavelength + "\n[numerics]\ngrid_points = 129\n");
    return testing::RunTehl("case --check '" + path + "'");
  };
  const testing::RunResult slip = check("50.0");
  ASSERT_EQ(slip.exit_code, 0) << slip.err;
  EXPECT_NE(slip.out.find("the waviness of surface1 (wavelength_m = 50 m) is 7.61e+04 times as "
                          "long as the film grid (0.65"),
            std::string::npos)
      << slip.out;
  EXPECT_NE(slip.out.find("micrometres written in metres"), std::string::npos) << slip.out;
  for (const char* wavelength : {"5e-5", "5e-3"}) {
    const testing::RunResult ok = check(wavelength);
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_EQ(ok.out.find("times as long as the film grid"), std::string::npos)
        << wavelength << "\n"
        << ok.out;
  }
  std::remove(path.c_str());
}

// A step count below one per contact zone is raised, and the plan says so.
TEST(CommandLineErrors, AStepCountBelowTheZonesIsRaisedAndSaidSo) {
  const std::string path = testing::UniqueTempPath("one_step.toml");
  std::ofstream(path) << GearCase("pinion_speed_rpm = 1000.0", "[numerics]\nsteps = 1\n");
  const testing::RunResult r = testing::RunTehl("case --check '" + path + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("mesh cycle of 3 steps ([numerics] steps = 1, raised to 3"),
            std::string::npos)
      << r.out;
}

// A Newton tolerance below what rounding allows is bad input (it used to run and fail with a
// message about the grid).
TEST(CommandLineErrors, ANewtonToleranceBelowRoundingIsRefused) {
  const std::string path = testing::UniqueTempPath("tol.toml");
  std::ofstream(path) << GearCase("pinion_speed_rpm = 1000.0",
                                  "[numerics]\nnewton_tolerance = 1e-300\n");
  const testing::RunResult r = testing::RunTehl("case --check '" + path + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("numerics.newton_tolerance = 1e-300"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1e-14"), std::string::npos) << r.err;
}

// `tehl run --at`: a point that is not on the path is bad input naming the option and what
// is allowed; --at has no checkpoint to resume; a [contact] case has no path.
TEST(CommandLineErrors, APointOffThePathIsBadInput) {
  const std::string dir = testing::UniqueTempPath("at_bad");
  fs::create_directories(dir);
  const std::string gear = dir + "/pair.toml";
  std::ofstream(gear) << GearCase("pinion_speed_rpm = 1000.0");
  for (const char* at : {"F", "3", "25mm"}) {
    const testing::RunResult r =
        testing::RunTehl("run -q '" + gear + "' -o '" + dir + "' --at " + at);
    ASSERT_TRUE(r.exited);
    EXPECT_EQ(r.exit_code, 2) << at << ": " << r.err;
    EXPECT_NE(r.err.find("--at"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("allowed: "), std::string::npos) << r.err;
  }
  // Several points: all are checked before any is solved, so a bad second point leaves
  // nothing of the first behind.
  {
    const testing::RunResult several =
        testing::RunTehl("run -q '" + gear + "' -o '" + dir + "' --at A,X");
    ASSERT_TRUE(several.exited);
    EXPECT_EQ(several.exit_code, 2) << several.err;
    EXPECT_NE(several.err.find("\"X\""), std::string::npos) << several.err;
    EXPECT_FALSE(fs::exists(dir + "/pair_at_A.toml"));
    EXPECT_FALSE(fs::exists(dir + "/pair_at_A_steps.csv"));
  }
  testing::RunResult r = testing::RunTehl("run -q '" + gear + "' --at C --resume");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = testing::RunTehl("run -q '" + SourcePath("cases/disc_steady.toml") + "' -o '" + dir +
                       "' --at C");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("[gear]"), std::string::npos) << r.err;
}

// `tehl run --at C` solves the steady film at the pitch point and writes the point's case
// beside its results; running that case again gives the same film.
TEST(CommandLineErrors, ThePointsCaseRunsAgainToTheSameFilm) {
  const std::string dir = testing::UniqueTempPath("at_c");
  fs::create_directories(dir);
  const std::string gear = dir + "/pair.toml";
  std::ofstream(gear) << GearCase("pinion_speed_rpm = 1000.0", "[numerics]\ngrid_points = 129\n");
  const testing::RunResult r = testing::RunTehl("run -q '" + gear + "' -o '" + dir + "' --at C");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("steady film at C"), std::string::npos) << r.out;
  const std::string written = dir + "/pair_at_C.toml";
  ASSERT_TRUE(fs::exists(written)) << r.out;
  ASSERT_TRUE(fs::exists(dir + "/pair_at_C_steps.csv")) << r.out;
  const std::string first = testing::ReadAll(dir + "/pair_at_C_steps.csv");
  const testing::RunResult again = testing::RunTehl("run -q '" + written + "'");
  ASSERT_TRUE(again.exited);
  ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
  // The same numbers but the wall time.
  auto body = [](const std::string& csv) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(csv);
    for (std::string line; std::getline(in, line);) {
      rows.emplace_back();
      std::istringstream cells(line);
      for (std::string c; std::getline(cells, c, ',');) rows.back().push_back(c);
    }
    const auto col = std::find(rows[0].begin(), rows[0].end(), "wall_time_s") - rows[0].begin();
    for (auto& row : rows)
      if (col < static_cast<long>(row.size())) row.erase(row.begin() + col);
    return rows;
  };
  EXPECT_EQ(body(testing::ReadAll(dir + "/pair_at_C_steps.csv")), body(first));
}

}  // namespace
}  // namespace tehl
