// How well the Newton-Krylov preconditioner does on real Newton systems (docs/performance.md,
// "where the GMRES iterations go"). A plain program, two modes:
//   tehl_preconditioner_spectrum write N PREFIX
//     solves the Moes point M = 20, L = 10 (reference oil, VALIDATION.md section 3) cold on N
//     nodes, then warm after +1 % load, writing every Newton system of the process to
//     PREFIX_<n>_<k>.bin (TEHL_WRITE_NEWTON_SYSTEMS, src/ehl/newton_system_file.hpp);
//   tehl_preconditioner_spectrum FILE... [--dense]
//     for each system, GMRES iterations to 1e-3 / 1e-6 / 1e-10 with the two-level
//     preconditioner (uniform coarse hats, and wide inlet hats where the solver uses them),
//     freshly factorized; with --dense (n up to about 2049) also the eigenvalues of I - M J
//     above 0.2 in modulus, and where their eigenvectors lie.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "ehl/banded_film_preconditioner.hpp"
#include "ehl/coarse_correction.hpp"
#include "ehl/gmres.hpp"
#include "ehl/newton_system_file.hpp"
#include "support/test_lubricants.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/units.hpp"

namespace {

using tehl::internal::NewtonSystem;
using Vec = Eigen::VectorXd;

int WriteSystems(int n, const std::string& prefix) {
  constexpr double kEPrime = 226.4e9, kRadius = 0.01, kEta0 = 0.04;  // as bench/ehl_bench.cpp
  const double alpha = 0.68 * (std::log(kEta0) + 9.67) / 1.96e8;
  const double u = std::pow(10.0 / (alpha * kEPrime), 4) / 2.0;  // Moes L = 10
  const double w = 20.0 * std::sqrt(2.0 * u);                    // Moes M = 20
  const double um = u * kEPrime * kRadius / kEta0;
  tehl::ContactConditions c{kRadius, um, um, w * kEPrime * kRadius, tehl::testing::kReferenceT0};
  tehl::FilmEffects effects;
  effects.transient = false;
  tehl::LineContactSolver::Options opt;
  opt.linear_solver = tehl::LinearSolverKind::kNewtonKrylov;
  const auto hz = tehl::LineContactHertz(c.load_n_per_m, kRadius, kEPrime);
  const tehl::Lubricant oil = tehl::testing::ReferenceOil(kEta0, 0.68);  // outlives the solver
  tehl::LineContactSolver solver(tehl::UniformGrid::AroundHertz(hz.half_width_m, n), kEPrime, oil,
                                 effects, opt);
  setenv("TEHL_WRITE_NEWTON_SYSTEMS", prefix.c_str(), 1);
  tehl::FilmState s;
  const auto cold = solver.SolveSteady(c, &s);
  c.load_n_per_m *= 1.01;
  const auto warm = solver.SolveSteady(c, &s);
  std::printf("cold: %s\nwarm: %s\n", cold.BriefReport().c_str(), warm.BriefReport().c_str());
  return cold.usable() && warm.usable() ? 0 : 1;
}

struct TwoLevel {  // the solver's preconditioner (coarse_correction.hpp, ApplyTwoLevel)
  tehl::internal::BandedFilmPreconditioner band;
  tehl::internal::CoarseCorrection coarse;
  mutable tehl::internal::TwoLevelScratch scratch;
  void Apply(const NewtonSystem& s, const Vec& in, Vec* y) const {
    tehl::internal::ApplyTwoLevel(s, coarse, band, in, y, &scratch);
  }
};

int Iterations(const NewtonSystem& s, const TwoLevel& m, const Vec& rhs, double tol) {
  Vec dz = Vec::Zero(rhs.size());
  const auto g = tehl::internal::Gmres([&](const Vec& v, Vec* y) { s.Apply(v, y); },
                                       [&](const Vec& v, Vec* y) { m.Apply(s, v, y); }, rhs, &dz,
                                       60, 400, tol);
  return g.converged ? g.iterations : -g.iterations;  // negative: not converged
}

void Study(const std::string& path, bool dense) {
  const auto stored = tehl::internal::ReadNewtonSystem(path);
  const NewtonSystem& s = stored->system;
  const int n = s.n, stride = tehl::internal::CoarseStride(n, 128);
  const int zone = tehl::internal::ElasticZoneStart(s);
  std::printf("%s: %d nodes, elastic zone from node %d\n", path.c_str(), n, zone);
  for (int wide : {0, 1}) {
    if (wide && stride < 8) continue;  // the solver merges only from stride 8 on
    TwoLevel m;
    std::string why;
    const bool ok = m.band.Factorize(s, 8, &why) &&
                    (wide ? m.coarse.Build(s, stride / 2, zone, 8) : m.coarse.Build(s, stride));
    if (!ok) {
      std::printf("  factorization failed %s\n", why.c_str());
      continue;
    }
    std::printf("  %s hats, %d coarse pressures: GMRES %d / %d / %d (1e-3 / 1e-6 / 1e-10)\n",
                wide ? "wide inlet" : "uniform", m.coarse.coarse_size() - 1,
                Iterations(s, m, stored->rhs, 1e-3), Iterations(s, m, stored->rhs, 1e-6),
                Iterations(s, m, stored->rhs, 1e-10));
    if (!dense) continue;
    const Eigen::MatrixXd j = s.Dense();
    Eigen::MatrixXd e(n - 1, n - 1);
    Vec y;
    for (int c = 0; c < n - 1; ++c) {
      m.Apply(s, j.col(c), &y);
      e.col(c) = -y;
      e(c, c) += 1.0;  // I - M J
    }
    const Eigen::EigenSolver<Eigen::MatrixXd> es(e, true);
    std::vector<int> big;
    for (int i = 0; i < n - 1; ++i)
      if (std::abs(es.eigenvalues()[i]) > 0.2) big.push_back(i);
    std::sort(big.begin(), big.end(), [&](int a, int b) {
      return std::abs(es.eigenvalues()[a]) > std::abs(es.eigenvalues()[b]);
    });
    std::printf("    %zu eigenvalues of I - M J above 0.2 in modulus\n", big.size());
    for (int i : big) {
      const Vec w = es.eigenvectors().col(i).cwiseAbs2();
      int peak = 0;
      w.maxCoeff(&peak);
      int lo = peak, hi = peak;  // the shortest window around the peak holding 90 %
      double in = w[peak];
      while (in < 0.9 * w.sum()) {
        const double l = lo > 0 ? w[lo - 1] : -1, h = hi + 1 < w.size() ? w[hi + 1] : -1;
        in += l > h ? w[--lo] : w[++hi];
      }
      std::printf("    |lambda| %.3f (%+.3f %+.3fi): peak at node %d, 90 %% on nodes %d..%d\n",
                  std::abs(es.eigenvalues()[i]), es.eigenvalues()[i].real(),
                  es.eigenvalues()[i].imag(), peak + 1, lo + 1, hi + 1);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 4 && std::string(argv[1]) == "write")
    return WriteSystems(std::atoi(argv[2]), argv[3]);
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s write N PREFIX | %s FILE... [--dense]\n", argv[0], argv[0]);
    return 2;
  }
  bool dense = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--dense")
      dense = true;
    else
      files.push_back(argv[i]);
  }
  try {
    for (const auto& f : files) Study(f, dense);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
