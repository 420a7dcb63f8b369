// Geometric validity of a gear pair: every problem found in one pass, each tied to the
// case-file key a user would change, with the numbers and what to change (tehl/error.hpp).
// The scene layer attaches file:line; the gear layer knows no files.
//
// Errors: impossible or overlapping centre distance, a basic rack whose tip rounding does
// not fit, undercut (unless allowed), a tip circle inside a base circle, a pointed tooth
// (top land <= 0), involute interference (the mating tip reaches below the base circle,
// Kapelevich seed 000 eqs. 3.34-3.37, or below the involute form circle into the fillet),
// tip-to-root interference, a drive-flank contact ratio below 1 (seed 003 section 1.1).
// Warnings: undercut with allow_undercut, a thin top land (< 0.2 m_n), eps_alpha < 1.2 or
// near an integer (seed 003 section 4.1), a coast-flank contact ratio below 1.
#pragma once

#include <string>
#include <vector>

#include "tehl/gear/gear_pair.hpp"

namespace tehl {

struct GeometryProblem {
  std::string section;   // case-file section: "gear", "gear.pinion" or "gear.wheel"
  std::string key;       // key in that section, e.g. "profile_shift"
  std::string rule;      // what is wrong, with the numbers (lengths in mm, angles in deg)
  std::string allowed;   // what to change
  bool warning = false;  // true: reported, the pair is still usable

  std::string ToString() const;  // "gear.pinion.profile_shift: rule (allowed: ...)"
};

// Every problem of the pair, errors and warnings, in a fixed order.
std::vector<GeometryProblem> CheckGeometry(const GearPair& pair);

// Throws InputError (file "") with every error of CheckGeometry; returns the warnings.
std::vector<GeometryProblem> RequireValidGeometry(const GearPair& pair);

}  // namespace tehl
