// The module key of gear cases and train files: the bound that catches a module given in
// millimetres. Private to src/.
#pragma once

#include <string>
#include <utility>

#include "base/schema.hpp"

namespace tehl::internal {

// The largest module a gear case or train file takes: the largest spur gears (mill and kiln
// drives) have modules of about 40-50 mm; a module of metres is a module in millimetres [m].
inline constexpr double kMaxModuleM = 0.1;

// A module key in metres, 0 < m <= kMaxModuleM, naming the millimetre slip above the bound.
inline KeySpec GearModule(std::string name, std::string default_toml, std::string meaning) {
  KeySpec k = Real(std::move(name), "m", std::move(default_toml), std::move(meaning), 0.0,
                   kMaxModuleM, false);
  k.above_hint = " (in millimetres? the module is in metres: 3 mm = 0.003)";
  return k;
}

}  // namespace tehl::internal
