// The Newton-system file (src/ehl/newton_system_file.hpp): a system read back is the system
// written, and a file that is not one is refused with its name.
#include "ehl/newton_system_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "support/random_newton_system.hpp"
#include "support/scratch_path.hpp"

namespace tehl {
namespace {

TEST(NewtonSystemFile, ASystemReadBackIsTheSystemWritten) {
  testing::RandomNewtonSystem rs(257, 4);
  const Eigen::VectorXd rhs = rs.RandomVector();
  const std::string path = testing::ScratchPath("newton_system", "system.bin");
  internal::WriteNewtonSystem(path, rs.sys, rhs);
  const auto back = internal::ReadNewtonSystem(path);
  const internal::NewtonSystem& s = back->system;
  EXPECT_EQ(s.n, rs.sys.n);
  EXPECT_EQ(s.dx, rs.sys.dx);
  EXPECT_EQ(s.p_ref, rs.sys.p_ref);
  EXPECT_EQ(s.h_ref, rs.sys.h_ref);
  EXPECT_EQ(s.load, rs.sys.load);
  EXPECT_EQ(*s.row_scale, *rs.sys.row_scale);
  EXPECT_EQ(*s.a, *rs.sys.a);
  EXPECT_EQ(*s.b, *rs.sys.b);
  EXPECT_EQ(s.cavitated, rs.sys.cavitated);
  EXPECT_EQ(back->rhs, rhs);
  ASSERT_NE(s.elastic, nullptr);
  EXPECT_EQ(s.elastic->e_prime_pa(), rs.kernel.e_prime_pa());
  for (int k = 0; k < s.n; ++k) EXPECT_EQ(s.elastic->Coefficient(k), rs.kernel.Coefficient(k));
  // The same Jacobian: products agree to the FFT's rounding (plans may differ).
  const Eigen::VectorXd x = rs.RandomVector();
  Eigen::VectorXd y0, y1;
  rs.sys.Apply(x, &y0);
  s.Apply(x, &y1);
  EXPECT_LE((y0 - y1).norm(), 1e-13 * y0.norm());
}

TEST(NewtonSystemFile, ARigidSystemHasNoKernel) {
  testing::RandomNewtonSystem rs(65, 5);
  rs.sys.elastic = nullptr;
  const std::string path = testing::ScratchPath("newton_system", "rigid.bin");
  internal::WriteNewtonSystem(path, rs.sys, rs.RandomVector());
  EXPECT_EQ(internal::ReadNewtonSystem(path)->system.elastic, nullptr);
}

void ExpectRefused(const std::string& path, const std::string& what) {
  try {
    internal::ReadNewtonSystem(path);
    FAIL() << "accepted " << path;
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find(what), std::string::npos) << m;
  }
}

TEST(NewtonSystemFile, MissingTruncatedAndForeignFilesAreRefusedByName) {
  ExpectRefused(testing::ScratchPath("newton_system", "missing.bin"), "cannot open");
  testing::RandomNewtonSystem rs(65, 6);
  const std::string whole = testing::ScratchPath("newton_system", "whole.bin");
  internal::WriteNewtonSystem(whole, rs.sys, rs.RandomVector());
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string cut = testing::ScratchPath("newton_system", "cut.bin");
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 8);
  ExpectRefused(cut, "truncated");
  const std::string foreign = testing::ScratchPath("newton_system", "foreign.bin");
  std::ofstream(foreign, std::ios::binary) << "[case]\nname = 1\n" << bytes.substr(16);
  ExpectRefused(foreign, "TEHLNS01");
}

}  // namespace
}  // namespace tehl
