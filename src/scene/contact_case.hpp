// The inputs of a plain [contact] case (two discs or rollers, or a roller on a plane): radii,
// E', and the load and speed tables, read and checked (exit 2 on a problem, docs/case_format.md).
#pragma once

#include <vector>

#include "base/schema.hpp"

namespace tehl::internal {

struct ContactInputs {
  double r1 = 0, r2 = 0;             // radii; r2 = 0 means a plane [m]
  double e_prime = 0;                // [Pa]
  std::vector<double> t, w, u1, u2;  // tables (size 1 for a steady run) [s, N/m, m/s, m/s]
  int steps = 0;
  double ReducedRadius() const { return r2 > 0 ? r1 * r2 / (r1 + r2) : r1; }
};

// Reads [contact]; speeds that do not entrain, loads <= 0 and loads beyond Hertz line-contact
// theory (b > 0.2 R) are reported to `doc`.
ContactInputs ReadContact(Document& doc);

}  // namespace tehl::internal
