#include "lubricant/law_check.hpp"

#include <cstdio>

#include "base/schema.hpp"

namespace tehl::internal {

void RequireParameter(bool ok,
                      const char* key,
                      double value,
                      std::string rule,
                      std::string allowed,
                      std::vector<InputProblem>* problems) {
  if (ok) return;
  problems->push_back({"", 0, key, FormatReal(value), std::move(rule), std::move(allowed)});
}

void ThrowIfInvalid(const char* law, std::vector<InputProblem> problems) {
  if (problems.empty()) return;
  for (auto& p : problems) p.key = std::string(law) + "." + p.key;
  throw InputError(std::move(problems));
}

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", x);
  return buf;
}

}  // namespace tehl::internal
