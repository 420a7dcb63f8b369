// A Newton system (newton_system.hpp) and its right-hand side in a binary file, for offline
// study of the linear solvers and their preconditioners (bench/preconditioner_spectrum.cpp,
// docs/performance.md). The Newton-Krylov solver writes one file per linear solve when the
// environment variable TEHL_WRITE_NEWTON_SYSTEMS names a path prefix:
//   <prefix>_<n>_<k>.bin   (n grid nodes, k counting the solves of the process from 0).
// Layout (native byte order, little-endian on every supported machine): the 8 bytes
// "TEHLNS01"; int32 n; doubles dx [m], p_ref [Pa], h_ref [m], load [N/m], E' [Pa] (0 = rigid);
// doubles row_scale[n]; A and B as n x 4 column-major doubles; n bytes of cavitation flags;
// doubles rhs[n - 1].
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "ehl/newton_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl::internal {

// Writes `system` and `rhs` to `path`. Throws std::runtime_error if the file cannot be written.
void WriteNewtonSystem(const std::string& path,
                       const NewtonSystem& system,
                       const Eigen::VectorXd& rhs);

// A system read back: owns what NewtonSystem points to (the kernel is rebuilt from n, dx, E').
struct StoredNewtonSystem {
  Eigen::VectorXd row_scale, rhs;
  Eigen::Matrix<double, Eigen::Dynamic, 4> a, b;
  std::unique_ptr<ElasticDeflection> kernel;
  NewtonSystem system;  // points into the members above
};

// Throws std::runtime_error naming the file if it is missing, truncated or not such a file.
std::unique_ptr<StoredNewtonSystem> ReadNewtonSystem(const std::string& path);

// The solver's hook: writes the system to the next file name if TEHL_WRITE_NEWTON_SYSTEMS is
// set (a write error is reported on stderr once and ignored: the solve goes on).
void MaybeWriteNewtonSystem(const NewtonSystem& system, const Eigen::VectorXd& rhs);

}  // namespace tehl::internal
