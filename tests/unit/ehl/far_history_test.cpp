// The far part of the moving-heat-source history by FFT (src/ehl/far_history.hpp) against the
// direct O(n^2) sum of the exact cell weights (include/tehl/ehl/surface_temperature.hpp), and
// near + far = the whole history of MovingHeatSource::Rise.
#include "ehl/far_history.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace tehl::internal {
namespace {

const SolidThermal kBronze{7890.0, 375.0, 55.0};  // VALIDATION.md section 5, UNS C61300

// Samples s_k at stride 3 (the layout of the energy unknowns), random signs and sizes.
std::vector<double> Samples(int n, int stride, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 3.0);
  std::vector<double> s(static_cast<size_t>(n) * stride, -7.0);  // gaps must not be read
  for (int k = 0; k < n; ++k) s[static_cast<size_t>(k) * stride] = 1e7 * u(rng);
  return s;
}

// The far part of samples s by FFT and by the direct sum: the largest |difference| and the
// largest |direct value|; fft receives the FFT's values.
struct FftAgainstDirect {
  double err = 0, scale = 0;
  std::vector<double> fft;
};
FftAgainstDirect Compare(const FarHistory& far, const std::vector<double>& s, int stride) {
  const int n = far.size();
  FftAgainstDirect r;
  r.fft.assign(n, 1.0);
  std::vector<double> direct(n, 1.0);
  far.Apply(s.data(), stride, r.fft.data());
  far.ApplyDirect(s.data(), stride, direct.data());
  for (int i = 0; i < n; ++i) {
    r.scale = std::max(r.scale, std::abs(direct[i]));
    r.err = std::max(r.err, std::abs(r.fft[i] - direct[i]));
  }
  return r;
}

TEST(FarHistory, FftEqualsTheDirectSumToRoundOff) {
  // Reference: the direct sum over i - k > near of the exact weights. Tolerance 1e-12 of the
  // largest value: the transform's round-off is ~eps log2(m) times the norm.
  for (int n : {5, 6, 17, 257, 513, 1000}) {  // UniformGrid needs n >= 5
    const MovingHeatSource source(UniformGrid(-3e-4, 1e-4, n));
    for (int near : {0, 1, 16, n - 3, n - 2, n - 1, n + 5}) {
      if (near < 0) continue;
      const FarHistory far(source, near);
      const auto [err, scale, fft] = Compare(far, Samples(n, 3, 17u * n + near), 3);
      for (int i = 0; i <= near && i < n; ++i)  // no far lag
        EXPECT_EQ(fft[i], 0.0) << n << " " << near << " " << i;
      EXPECT_EQ(far.empty(), near >= n - 1);
      if (far.empty()) {
        EXPECT_EQ(scale, 0.0);
      }
      EXPECT_LE(err, 1e-12 * scale) << "n " << n << ", near " << near;
      if (n == 513 && near == 16)
        std::printf("n 513, near 16: FFT length %d, max error %.2e of %.3e\n", far.fft_size(), err,
                    scale);
    }
  }
}

// Rise / F = sum_k G_ik q_k (the O(n^2) sum of MovingHeatSource); the near band
// 0 <= i - k <= near summed from Weight plus the far part must give it back (n = 300, near =
// 7, speed 2 m/s). Returns the largest share of a node's history from lags i - k < 0.
double ExpectNearPlusFarIsTheWhole(const MovingHeatSource& source, unsigned seed) {
  const int n = source.size(), near = 7;
  const double speed = 2.0;
  const std::vector<double> q = Samples(n, 1, seed);
  const Eigen::VectorXd qv = Eigen::Map<const Eigen::VectorXd>(q.data(), n);
  const Eigen::VectorXd whole =
      source.Rise(kBronze, speed, qv) / MovingHeatSource::Factor(kBronze, speed);
  const FarHistory far(source, near);
  std::vector<double> y(n);
  far.Apply(q.data(), 1, y.data());
  const double scale = whole.cwiseAbs().maxCoeff();
  double upstream = 0;
  for (int i = 0; i < n; ++i) {
    double sum = y[i], ahead = 0;
    for (int k = std::max(0, i - near); k <= i; ++k) sum += source.Weight(i, k) * q[k];
    for (int k = i + 1; k < n; ++k) ahead += source.Weight(i, k) * std::abs(q[k]);
    upstream = std::max(upstream, ahead / scale);
    EXPECT_NEAR(sum, whole[i], 1e-12 * scale) << i;
  }
  return upstream;
}

TEST(FarHistory, NearBandPlusFarPartIsTheWholeHistory) {
  EXPECT_EQ(ExpectNearPlusFarIsTheWhole(MovingHeatSource(UniformGrid(-3e-4, 1e-4, 300)), 5u), 0.0);
}

// The finite-Peclet kernel (Jaeger's moving line source): the far part now also holds every
// upstream lag i - k < 0 and the outlet half cell's own weights. Same references as above; the
// kernels are set by Reset on one object, as the energy system does when the speed changes.
TEST(FarHistory, FinitePecletFftEqualsTheDirectSumToRoundOff) {
  for (int n : {5, 17, 257, 1000}) {
    const UniformGrid grid(-3e-4, 1e-4, n);
    FarHistory far(MovingHeatSource(grid), 0);
    for (double omega_b : {0.3, 3.0, 300.0}) {  // Peclet numbers of a contact with b = 1e-4 m
      const MovingHeatSource source(grid, omega_b / 1e-4);
      for (int near : {0, 4, n - 1}) {
        far.Reset(source, near);
        // Empty only without downstream far lags and when even the next cell ahead is out of
        // reach: its weight, about e^(-omega dx) of the lag-0 one, vanishes against 1 (the
        // weights are differences of J near -1).
        EXPECT_EQ(far.empty(), near >= n - 1 && source.omega_1_m() * grid.dx_m() > 40)
            << "n " << n << ", omega b " << omega_b << ", near " << near;
        const FftAgainstDirect c = Compare(far, Samples(n, 3, 31u * n + near), 3);
        EXPECT_LE(c.err, 1e-12 * c.scale)
            << "n " << n << ", omega b " << omega_b << ", near " << near;
      }
    }
  }
}

TEST(FarHistory, FinitePecletNearBandPlusFarPartIsTheWholeHistory) {
  const UniformGrid grid(-3e-4, 1e-4, 300);
  const MovingHeatSource source(grid, MovingHeatSource::DecayRate(kBronze, 2.0));
  // omega b = 0.8 for b = 1e-4 m: the heat ahead is not small.
  EXPECT_GT(ExpectNearPlusFarIsTheWhole(source, 9u), 1e-3);
}

}  // namespace
}  // namespace tehl::internal
