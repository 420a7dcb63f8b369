// Notes that `tehl run` adds to its report: the outlet pressure spike that the grid does not
// resolve (include/tehl/ehl/outlet_spike.hpp), the film lost to a truncated inlet
// (include/tehl/ehl/inlet_truncation.hpp) and solids too slow for the high-speed surface
// temperatures (docs/thermal.md "Surface temperatures at any Peclet number").
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "run_tehl.hpp"

namespace tehl::testing {
namespace {

// Two 40 mm steel discs at p_H = 0.8 GPa in rolling (the disc of docs/thermal.md, "Open
// points"): on 513 nodes the isothermal spike spans 2.6 cells at half height (docs/accuracy.md
// measures its height 23 % low there). `elastic` false gives a rigid film with no spike.
// x_start_b: the inlet end of the grid in b (with grid_points raised to keep the spacing).
std::string DiscCase(bool elastic, const std::string& out_dir, double x_start_b = -4.5) {
  const std::string path = UniqueTempPath("disc.toml");
  const int cells_in = static_cast<int>(std::lround(-x_start_b * 512 / 6.0));
  std::ofstream(path) << "[contact]\nradius_1_m = 0.04\nradius_2_m = 0.04\n"
                         "speed_1_m_s = 4.881\nspeed_2_m_s = 4.881\nload_n_per_m = "
                      << (elastic ? "355238.0" : "2000.0")
                      << "\n[lubricant]\nname = \"sae40\"\n[effects]\ntransient = false\n"
                         "elastic = "
                      << (elastic ? "true" : "false")
                      << "\n[numerics]\ngrid_points = " << cells_in + 129
                      << "\nx_start_b = " << -cells_in * 6.0 / 512 << "\n"
                      << "[output]\ndirectory = \"" << out_dir << "\"\n";
  return path;
}

TEST(RunNotes, AnUnresolvedOutletSpikeIsNoted) {
  const std::string dir = UniqueTempPath("out");
  const RunResult r = RunTehl("run -q '" + DiscCase(true, dir) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: the outlet pressure spike"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not grid-converged"), std::string::npos) << r.out;
}

TEST(RunNotes, ARigidFilmGetsNoSpikeNote) {
  const std::string dir = UniqueTempPath("out");
  const RunResult r = RunTehl("run -q '" + DiscCase(false, dir) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("note:"), std::string::npos) << r.out;
}

// A film whose Hertzian edge the grid does not span (include/tehl/ehl/hertz_edge.hpp): two
// 40 mm steel discs (E = 210 GPa, nu = 0.3) at 3 MN/m (p_H 3.3 GPa) rolling at 0.05 m/s in
// SAE 40. Measured with `tehl run` (docs/results.md, "The edge note"): h_c 0.0218 um on 513
// nodes (edge 0.67 cells), 0.0491 um on 2049 (4.6 cells), 0.05131 um on 32769 nodes.
std::string HeavySlowDisc(int nodes) {
  const std::string path = UniqueTempPath("heavy.toml");
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\n"
                         "youngs_modulus_1_pa = 210e9\npoisson_ratio_1 = 0.3\n"
                         "youngs_modulus_2_pa = 210e9\npoisson_ratio_2 = 0.3\n"
                         "speed_1_m_s = 0.05\nspeed_2_m_s = 0.05\nload_n_per_m = 3.0e6\n"
                         "[lubricant]\nname = \"sae40\"\n[numerics]\ngrid_points = "
                      << nodes << "\n[output]\ndirectory = \"" << UniqueTempPath("out") << "\"\n";
  return path;
}

TEST(RunNotes, AnUnresolvedHertzianEdgeIsNoted) {
  const RunResult coarse = RunTehl("run -q '" + HeavySlowDisc(513) + "'");
  ASSERT_TRUE(coarse.exited);
  ASSERT_EQ(coarse.exit_code, 0) << coarse.out << coarse.err;
  EXPECT_NE(coarse.out.find("note: the film's Hertzian edge"), std::string::npos) << coarse.out;
  EXPECT_NE(coarse.out.find("it is not resolved and may be far too thin"), std::string::npos)
      << coarse.out;
  // 2049 nodes: 4.2 % below the 32769-node film; the note's bound 1.1 / N^2 is above that.
  const RunResult fine = RunTehl("run -q '" + HeavySlowDisc(2049) + "'");
  ASSERT_EQ(fine.exit_code, 0) << fine.out << fine.err;
  const size_t at = fine.out.find("too thin by up to about ");
  ASSERT_NE(at, std::string::npos) << fine.out;
  const double bound = std::stod(fine.out.substr(at + 24));
  EXPECT_GE(bound, 100 * (1 - 0.0491487 / 0.0513142)) << fine.out;
  EXPECT_LE(bound, 4 * 100 * (1 - 0.0491487 / 0.0513142)) << fine.out;
}

TEST(RunNotes, AResolvedHertzianEdgeGetsNoEdgeNote) {
  const std::string dir = UniqueTempPath("out");
  const RunResult r = RunTehl("run -q '" + DiscCase(true, dir) + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("Hertzian edge"), std::string::npos) << r.out;
}

// The same disc at 4.9 m/s: the default inlet (-4.5 b) cuts off about 1.9 MPa of inlet
// pressure, about 3 % of the film (tests/verification/inlet_truncation_disc_test.cpp measures
// 3.0 % at 5 m/s); at -12 b the estimate is (4.5/12)^3 of that, below the note's 0.5 %.
TEST(RunNotes, AShortInletIsNoted) {
  const std::string dir = UniqueTempPath("out");
  const RunResult r = RunTehl("run -q '" + DiscCase(true, dir) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: the inlet at x_start_b = -4.5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("thinner than with an unbounded inlet"), std::string::npos) << r.out;
}

TEST(RunNotes, ALongInletGetsNoInletNote) {
  const std::string dir = UniqueTempPath("out");
  const RunResult r = RunTehl("run -q '" + DiscCase(true, dir, -12.0) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("note: the inlet"), std::string::npos) << r.out;
}

// The seed 004 cycle (cases/seed004_sae40.toml, thermal, bronze) on 129 nodes and 6 steps,
// `thermal` (and `finite_peclet`) as given, writing into out_dir; `numerics` adds lines to
// [numerics].
std::string Seed004Case(bool thermal,
                        const std::string& out_dir,
                        bool finite_peclet = false,
                        const std::string& numerics = "") {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("grid_points = 513", "grid_points = 129\nsteps = 6\n" + numerics);
  replace("thermal = true",
          thermal ? (finite_peclet ? "thermal = true\nfinite_peclet = true" : "thermal = true")
                  : "thermal = false");
  const std::string path = UniqueTempPath("seed004.toml");
  std::ofstream(path) << text << "[output]\ndirectory = \"" << out_dir << "\"\n";
  return path;
}

// Pe = u1 b / (2 kappa) of the pinion at A: u1 = 0.679 m/s (VALIDATION.md section 5: rho1 =
// 6.486 mm at 1000 rpm), b = 71.5 um (Hertz at the pair's load 47.4 kN/m = 0.408 F_bt / b and
// R = 5.608 mm, E' of the bronze), kappa = 55 / (7890 x 375) = 1.86e-5 m^2/s: 1.31, the
// smallest of both gears along the path. An isothermal run has no surface temperatures and no
// such note.
TEST(RunNotes, ASlowSolidIsNotedInAThermalCycle) {
  const RunResult r = RunTehl("run -q '" + Seed004Case(true, UniqueTempPath("out")) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: the Peclet number u b / (2 kappa) of the pinion falls to 1.31 (at "
                       "s = 0 mm)"),
            std::string::npos)
      << r.out;
  const RunResult iso = RunTehl("run -q '" + Seed004Case(false, UniqueTempPath("out")) + "'");
  ASSERT_TRUE(iso.exited);
  ASSERT_EQ(iso.exit_code, 0) << iso.out << iso.err;
  EXPECT_EQ(iso.out.find("Peclet"), std::string::npos) << iso.out;
  EXPECT_NE(r.out.find("finite_peclet = true includes it"), std::string::npos) << r.out;
}

// With effects.finite_peclet the film's surfaces and Blok's partition both use Jaeger's
// kernel at each tooth's Peclet number: no note, and the flash line says which form it is.
TEST(RunNotes, FinitePecletSurfacesNeedNoPecletNote) {
  const RunResult r = RunTehl("run -q '" + Seed004Case(true, UniqueTempPath("out"), true) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("Peclet number"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("flash temperature (Blok, finite Peclet, with each step's mu)"),
            std::string::npos)
      << r.out;
}

// A thermal [contact] run gets the same note. Steel discs R1 = R2 = 20 mm at w = 100 kN/m:
// b = sqrt(8 w R / (pi E')) = 0.10607 mm (R = 10 mm, E' = 226.4 GPa), kappa = 46 / (7850 x
// 470) = 1.2468e-5 m^2/s; body 2 at 0.225 m/s: Pe = 0.225 b / (2 kappa) = 0.957.
std::string SlowThermalDisc(bool finite_peclet) {
  const std::string path = UniqueTempPath("slow_disc.toml");
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 0.375\n"
                         "speed_2_m_s = 0.225\nload_n_per_m = 1.0e5\n[lubricant]\nname = "
                         "\"sae40\"\n[effects]\ntransient = false\nthermal = true\n"
                         "non_newtonian = true\nfinite_peclet = "
                      << (finite_peclet ? "true" : "false") << "\n[output]\ndirectory = \""
                      << UniqueTempPath("out") << "\"\n";
  return path;
}

TEST(RunNotes, ASlowDiscIsNotedInAThermalContactRun) {
  const RunResult r = RunTehl("run -q '" + SlowThermalDisc(false) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: the Peclet number u b / (2 kappa) of body 2 falls to 0.957 (at "
                       "t = 0 s)"),
            std::string::npos)
      << r.out;
  const RunResult f = RunTehl("run -q '" + SlowThermalDisc(true) + "'");
  ASSERT_TRUE(f.exited);
  ASSERT_EQ(f.exit_code, 0) << f.out << f.err;
  EXPECT_EQ(f.out.find("Peclet number"), std::string::npos) << f.out;
  EXPECT_NE(f.out.find("flash temperature (Blok, finite Peclet, with this mu)"), std::string::npos)
      << f.out;
}

// A Newtonian film at gear pressures carries a shear stress no oil can (DESIGN.md section 4;
// the limiting shear stress of lubricants is at most about 0.1 p): the isothermal seed 004
// cycle has mu = 0.52 at A (docs/thermal.md "Friction"), above the note's 0.2. The Ree-Eyring
// film bounds the stress (mu 0.04 at the pitch point), and the thermal Newtonian film's heating
// keeps mu near 0.13 at A: neither gets the note.
TEST(RunNotes, AnUnphysicalNewtonianFrictionIsNoted) {
  const RunResult iso = RunTehl("run -q '" + Seed004Case(false, UniqueTempPath("out")) + "'");
  ASSERT_TRUE(iso.exited);
  ASSERT_EQ(iso.exit_code, 0) << iso.out << iso.err;
  EXPECT_NE(iso.out.find("films the Newtonian friction coefficient exceeds 0.2, up to"),
            std::string::npos)
      << iso.out;
  EXPECT_NE(iso.out.find("non_newtonian = true bounds the shear stress"), std::string::npos)
      << iso.out;

  std::string text = ReadAll(Seed004Case(false, UniqueTempPath("out")));
  const size_t at = text.find("\nthermal = false\n");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 17, "\nthermal = false\nnon_newtonian = true\n");
  const std::string eyring = UniqueTempPath("eyring.toml");
  std::ofstream(eyring) << text;
  const RunResult e = RunTehl("run -q '" + eyring + "'");
  ASSERT_EQ(e.exit_code, 0) << e.out << e.err;
  EXPECT_EQ(e.out.find("Newtonian friction"), std::string::npos) << e.out;

  const RunResult hot = RunTehl("run -q '" + Seed004Case(true, UniqueTempPath("out")) + "'");
  ASSERT_EQ(hot.exit_code, 0) << hot.out << hot.err;
  EXPECT_EQ(hot.out.find("Newtonian friction"), std::string::npos) << hot.out;
}

// Six steps from A to E leave the film after the load jump at B unresolved in time: the
// estimate of the step after it is above 1 % (on 513 nodes and 150 steps its h_min and h_c
// are 7.3 % and 9.0 % from a run of 4800 steps: docs/case_format.md). With time_tolerance the
// steps take substeps and the note goes.
TEST(RunNotes, ALargeTimeErrorIsNotedUnlessControlled) {
  const RunResult r = RunTehl("run -q '" + Seed004Case(false, UniqueTempPath("out")) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("time steps have an estimated local time error above 1 %"),
            std::string::npos)
      << r.out;
  const RunResult c = RunTehl(
      "run -q '" + Seed004Case(false, UniqueTempPath("out"), false, "time_tolerance = 1e-3") + "'");
  ASSERT_TRUE(c.exited);
  ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_EQ(c.out.find("local time error"), std::string::npos) << c.out;
}

// The disc of DiscCase in rolling at 1 mm/s instead of 4.881 m/s: its film (h_c 2.05 um at
// 4.881 m/s, docs/thermal.md "Open points") thins as u^0.7 (Dowson-Higginson) to about
// 2.05 um x (1e-3 / 4.881)^0.7 = 5 nm, below the 10 nm of the thin-film note; at 4.881 m/s
// there is no note.
TEST(RunNotes, AFilmOfAFewNanometresIsNotedAsAsperityContact) {
  auto disc = [](const char* speed) {
    const std::string path = UniqueTempPath("thin.toml");
    std::ofstream(path) << "[contact]\nradius_1_m = 0.04\nradius_2_m = 0.04\nspeed_1_m_s = "
                        << speed << "\nspeed_2_m_s = " << speed
                        << "\nload_n_per_m = 355238.0\n[lubricant]\nname = \"sae40\"\n"
                           "[effects]\ntransient = false\n[numerics]\ngrid_points = 513\n"
                           "[output]\ndirectory = \""
                        << UniqueTempPath("out") << "\"\n";
    return path;
  };
  const RunResult thin = RunTehl("run -q '" + disc("0.001") + "'");
  ASSERT_TRUE(thin.exited);
  ASSERT_EQ(thin.exit_code, 0) << thin.out << thin.err;
  EXPECT_NE(thin.out.find("note: in 1 of 1 films h_min is below 10 nm"), std::string::npos)
      << thin.out;
  EXPECT_NE(thin.out.find("asperity (mixed) contact"), std::string::npos) << thin.out;
  const RunResult thick = RunTehl("run -q '" + disc("4.881") + "'");
  ASSERT_EQ(thick.exit_code, 0) << thick.out << thick.err;
  EXPECT_EQ(thick.out.find("h_min is below"), std::string::npos) << thick.out;
}

// The seed 004 pair at 10 W instead of 10 kW (a thousandth of the load): its films are
// nearly isoviscous (alpha p_max about 0.1) and would build their pressure over millimetres
// (Martin), while the cycle's grid starts 4.5 b_max, about 15 um, upstream: every film gets the
// note. At 10 kW (alpha p_max above 5) the Grubin estimate applies instead and this note is
// not printed.
TEST(RunNotes, ANearlyIsoviscousCycleWithAShortInletIsNoted) {
  std::string text = ReadAll(Seed004Case(false, UniqueTempPath("out")));
  const size_t at = text.find("power_w = 10000.0");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 17, "power_w = 10.0");
  const std::string light = UniqueTempPath("light.toml");
  std::ofstream(light) << text;
  const RunResult r = RunTehl("run -q '" + light + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("the film is nearly isoviscous"), std::string::npos) << r.out;
  const RunResult normal = RunTehl("run -q '" + Seed004Case(false, UniqueTempPath("out")) + "'");
  ASSERT_EQ(normal.exit_code, 0) << normal.out << normal.err;
  EXPECT_EQ(normal.out.find("nearly isoviscous"), std::string::npos) << normal.out;
}

// A waviness of 2 um on a disc whose smooth film is about 0.7 um (the disc of
// cases/disc_steady.toml, R = 10 mm, 100 kN/m, um = 1 m/s; docs/validation.md section 3):
// no full film carries the load, the solve fails (exit 1), and its message says that the
// roughness exceeds the film rather than only that the line search stalled.
TEST(RunNotes, AFailedRoughFilmSaysTheRoughnessExceedsTheFilm) {
  const std::string path = UniqueTempPath("closing.toml");
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.1\n"
                         "speed_2_m_s = 0.9\nload_n_per_m = 1.0e5\ntime_s = [0.0, 2.0e-4]\n"
                         "steps = 100\n[lubricant]\nname = \"sae40\"\n[effects]\n"
                         "roughness = true\n[numerics]\ngrid_points = 257\n"
                         "[surfaces.surface1]\nroughness = \"sinusoidal\"\namplitude_m = 2.0e-6\n"
                         "wavelength_m = 5.0e-5\n[output]\ndirectory = \""
                      << UniqueTempPath("out") << "\"\n";
  const RunResult r = RunTehl("run -q '" + path + "'");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  // Peak to valley 2 x 2 um = 4 um against Moes' smooth film of about 0.8 um.
  EXPECT_NE(r.err.find("the roughness spans 4e-06 m peak to valley"), std::string::npos) << r.err;
}

// The steel disc of docs/validation.md section 6 at L_T = 5 and SRR = 1 with the Ree-Eyring
// film: T_max - T0 = 305 K there (that table, 257 nodes), so T_max = 618 K, above the 473 K
// of the hot-film note; rolling at L_T = 1 (17 K) gets no note.
TEST(RunNotes, AFilmHotterThan200CIsNoted) {
  auto disc = [](double u1, double u2) {
    const std::string path = UniqueTempPath("hot.toml");
    std::ofstream(path) << "[contact]\nradius_1_m = 0.04\nradius_2_m = 0.04\nspeed_1_m_s = " << u1
                        << "\nspeed_2_m_s = " << u2
                        << "\nload_n_per_m = 355238.0\n[lubricant]\nname = \"sae40\"\n"
                           "[effects]\ntransient = false\nthermal = true\nnon_newtonian = true\n"
                           "[numerics]\ngrid_points = 257\n[output]\ndirectory = \""
                        << UniqueTempPath("out") << "\"\n";
    return path;
  };
  const RunResult hot = RunTehl("run -q '" + disc(16.371, 5.457) + "'");
  ASSERT_TRUE(hot.exited);
  ASSERT_EQ(hot.exit_code, 0) << hot.out << hot.err;
  EXPECT_NE(hot.out.find("note: in 1 of 1 films the oil is hotter than 473 K"), std::string::npos)
      << hot.out;
  EXPECT_EQ(hot.out.find("Newtonian film in sliding"), std::string::npos) << hot.out;
  const RunResult cool = RunTehl("run -q '" + disc(4.881, 4.881) + "'");
  ASSERT_EQ(cool.exit_code, 0) << cool.out << cool.err;
  EXPECT_EQ(cool.out.find("hotter than"), std::string::npos) << cool.out;
}

// A nearly isoviscous disc film (694 N/m, p_H = 50 MPa, alpha p_max = 0.03; its default
// inlet reaches the isoviscous inlet length l_iso = R/2, tests/unit/scene/
// automatic_grid_test.cpp) with x_start_b = -1, a fifth of that, gets the short-inlet note and
// the x_start_b (-4.5) that reaches it; the default inlet gets none.
// A load typed in kN/m as N/m: 100 N/m on the R = 10 mm discs at 1 m/s, Martin's film 55.8 um
// (VALIDATION.md section 2), whose flooded inlet would reach tens of mm; the grid stops at R/2
// and the film comes out 9 % thinner than Martin's, as the truncated rigid solution says
// (RigidInletFilmRatio at X0 = -4.73: 0.909). The run says so.
TEST(RunNotes, AFilmThickAgainstItsRadiusIsNoted) {
  const std::string path = UniqueTempPath("thick.toml");
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\n"
                         "speed_2_m_s = 1.0\nload_n_per_m = 100.0\n[lubricant]\n"
                         "name = \"sae40\"\n[effects]\ntransient = false\n[output]\n"
                         "directory = \""
                      << UniqueTempPath("out") << "\"\n";
  const RunResult r = RunTehl("run -q '" + path + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      r.out, m, std::regex(R"(note: the film is thick against its radius: .* about ([0-9.]+) %)")))
      << r.out;
  EXPECT_NEAR(std::stod(m[1]), 9.1, 0.3) << r.out;
}

TEST(RunNotes, AShortInletOfANearlyIsoviscousDiscIsNoted) {
  auto disc = [](const std::string& numerics) {
    const std::string path = UniqueTempPath("light.toml");
    std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\n"
                           "speed_2_m_s = 1.0\nload_n_per_m = 694.0\n[lubricant]\n"
                           "name = \"sae40\"\n[effects]\ntransient = false\n[numerics]\n"
                        << numerics << "\n[output]\ndirectory = \"" << UniqueTempPath("out")
                        << "\"\n";
    return path;
  };
  const RunResult r = RunTehl("run -q '" + disc("x_start_b = -1.0") + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: the film is nearly isoviscous"), std::string::npos) << r.out;
  // The advice keeps the spacing: N - 1 cells of the run's dx from the new inlet to the
  // outlet, N odd (the profile CSV gives the run's grid).
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m,
                                std::regex(R"(\[numerics\] x_start_b = -4\.5 with grid_points = )"
                                           R"((\d+) \(the same spacing\))")))
      << r.out;
  const int n = std::stoi(m[1]);
  EXPECT_EQ(n % 2, 1);
  std::smatch w;
  ASSERT_TRUE(std::regex_search(r.out, w, std::regex(R"(wrote (\S+_profile\.csv))")));
  std::ifstream csv(w[1].str());
  std::string line;
  std::getline(csv, line);  // header
  std::vector<double> x;
  while (std::getline(csv, line)) x.push_back(std::stod(line.substr(0, line.find(','))));
  ASSERT_EQ(x.size(), 513u);
  const double dx = (x.back() - x.front()) / 512, x0_new = 4.5 * x.front();
  EXPECT_GE((n - 1) * dx, x.back() - x0_new - 1e-9 * dx);
  EXPECT_LT((n - 3) * dx, x.back() - x0_new);
  const RunResult d = RunTehl("run -q '" + disc("") + "'");
  ASSERT_EQ(d.exit_code, 0) << d.out << d.err;
  EXPECT_EQ(d.out.find("nearly isoviscous"), std::string::npos) << d.out;
}

}  // namespace
}  // namespace tehl::testing
