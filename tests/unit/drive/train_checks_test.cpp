// Rules a train file must keep beyond its kinematics (docs/trains.md): an internal pair's
// ring holds the gear inside it, the tooth difference of an internal pair, and the ends of
// the train value. Messages at the file's lines; references by hand.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "drive/train_reader.hpp"
#include "tehl/drive/gear_train.hpp"
#include "tehl/error.hpp"
#include "unit/cli/run_tehl.hpp"
#include "unit/drive/train_report_run.hpp"
#include "unit/drive/train_spec_builders.hpp"

namespace tehl {
namespace {
using testing::Gear;
using testing::Mesh;

using testing::Message;

// Every problem of a train file, its path replaced by F.
std::string Problems(const std::string& text) {
  const std::string path = testing::UniqueTempPath("train.toml");
  std::ofstream(path) << text;
  std::string m;
  try {
    internal::ReadTrainFile(path);
  } catch (const InputError& e) {
    m = e.what();
    while (m.find(path) != std::string::npos) m.replace(m.find(path), path.size(), "F");
  }
  std::remove(path.c_str());
  return m;
}

using testing::TrainReport;

// An internal pair's ring (b) holds the gear inside it (a) at the centre distance
// m (z_b - z_a)/2: with z_a = 20 and z_b = 18 that is -m, no place at all; a ring named as
// a (60 teeth, the 20 inside it as b) is the same mistake the other way round.
TEST(TrainChecks, InternalPairNeedsARingWithMoreTeethThanTheGearInsideIt) {
  GearTrainSpec s;
  s.members = {Gear("p", 20), Gear("r", 18)};
  s.members[0].speed = 1.0;
  s.meshes = {Mesh("p", "r", MeshKind::kInternal)};
  std::string m = Message(s);
  EXPECT_NE(m.find("mesh.pr.b: the ring r (b, internal teeth) has 18 teeth, fewer than p (a, "
                   "20) inside it: the centre distance m (z_ring - z_pinion)/2 = m (18 - 20)/2 "
                   "is negative"),
            std::string::npos)
      << m;
  s.members[1].teeth = 60;
  s.meshes = {Mesh("r", "p", MeshKind::kInternal)};
  m = Message(s);
  EXPECT_NE(m.find("mesh.rp.b: the ring p (b, internal teeth) has 20 teeth, fewer than r"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("swap a and b if r is the ring"), std::string::npos) << m;
  // The right way round: w_r = (z_p / z_r) w_p = 1/3, same sense (eq. 2.4 with the arm at
  // rest).
  s.meshes = {Mesh("p", "r", MeshKind::kInternal)};
  EXPECT_NEAR(SolveGearTrain(s).speed[1], 1.0 / 3.0, 1e-15);
}

// Sun 24, planet 80 on arm, ring 72 held, module 3 mm: the planet sits 3 (24 + 80)/2 =
// 156 mm from the central axis by the sun mesh and 3 (72 - 80)/2 = -12 mm by the ring mesh:
// no such train. Lines: [carrier.arm] 16, then the carrier's own lines, then [mesh.sp] (3
// lines) and [mesh.pr] (a, b on the 2nd and 3rd of its lines).
std::string RingSmallerThanItsPlanet(const std::string& carrier_lines) {
  return "[train]\ninput = \"sun\"\noutput = \"arm\"\n"
         "[gear.sun]\nteeth = 24\nmodule_m = 0.003\nspeed_rpm = 1000.0\n"
         "[gear.planet]\nteeth = 80\nmodule_m = 0.003\ncarrier = \"arm\"\n"
         "[gear.ring]\nteeth = 72\nmodule_m = 0.003\nheld = true\n"
         "[carrier.arm]\n" +
         carrier_lines +
         "[mesh.sp]\na = \"sun\"\nb = \"planet\"\n"
         "[mesh.pr]\na = \"planet\"\nb = \"ring\"\nkind = \"internal\"\n";
}

TEST(TrainChecks, PlanetLargerThanItsRingIsRejectedAtTheMesh) {
  std::string m = Problems(RingSmallerThanItsPlanet(""));
  EXPECT_NE(m.find("F:22: mesh.pr.b = \"ring\": the ring ring (b, internal teeth) has 72 teeth, "
                   "fewer than planet (a, 80) inside it"),
            std::string::npos)
      << m;
  // With a declared planet count the carrier says why there is no set to check.
  m = Problems(RingSmallerThanItsPlanet("planets = 1\n"));
  EXPECT_NE(m.find("F:23: mesh.pr.b"), std::string::npos) << m;
  EXPECT_NE(m.find("F:17: carrier.arm.planets = 1: no simple planetary set (sun, planet, ring) "
                   "on this carrier to check: ring ring (z = 72) cannot hold planet planet "
                   "(z = 80) inside it, [mesh.pr]: a ring needs more teeth than its planet"),
            std::string::npos)
      << m;
}

std::string InternalPair(int z_pinion, int z_ring) {
  return "[train]\ninput = \"p\"\noutput = \"r\"\n[gear.p]\nteeth = " + std::to_string(z_pinion) +
         "\nspeed_rpm = 1000.0\n[gear.r]\nteeth = " + std::to_string(z_ring) +
         "\n[mesh.pr]\na = \"p\"\nb = \"r\"\nkind = \"internal\"\n";
}

TEST(TrainChecks, InternalPairWithFewerThanTenTeethDifferenceGetsANote) {
  // SDP/SI, Elements of Metric Gear Technology, section 5.2: standard 20 deg teeth clear the
  // tips (no trochoid interference) when z_ring - z_pinion > 9. 20 in 22: a note, and the
  // speeds as ever: w_r = 1000 (20/22) = 909.091 rpm.
  int code = -1;
  std::string out = TrainReport(InternalPair(20, 22), &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("909.091"), std::string::npos) << out;
  EXPECT_NE(out.find("[mesh.pr]: ring r has only 2 teeth more than p inside it"), std::string::npos)
      << out;
  EXPECT_NE(out.find("difference of at least 10"), std::string::npos) << out;
  out = TrainReport(InternalPair(20, 29), &code);
  EXPECT_NE(out.find("has only 9 teeth more"), std::string::npos) << out;
  out = TrainReport(InternalPair(20, 30), &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_EQ(out.find("Notes:"), std::string::npos) << out;
}

TEST(TrainChecks, OutputThatIsTheInputIsRejected) {
  // w_a / w_a = 1 for any train: the file names one member twice.
  const std::string m = Problems(
      "[train]\ninput = \"a\"\noutput = \"a\"\n[gear.a]\nteeth = 30\nspeed_rpm = 1000.0\n"
      "[gear.b]\nteeth = 30\n[mesh.ab]\na = \"a\"\nb = \"b\"\n");
  EXPECT_NE(m.find("F:3: train.output = \"a\": the output is the input member a: w_a / w_a = 1"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("allowed: a member other than the input (a)"), std::string::npos) << m;
}

}  // namespace
}  // namespace tehl
