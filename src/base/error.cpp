#include "tehl/error.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace tehl {

std::string InputProblem::ToString() const {
  std::ostringstream s;
  if (!file.empty()) {
    s << file;
    if (line > 0) s << ":" << line;
    s << ": ";
  }
  s << key;
  if (!value.empty()) s << " = " << value;
  s << ": " << rule;
  if (!allowed.empty()) s << " (allowed: " << allowed << ")";
  return s.str();
}

InputError::InputError(std::vector<InputProblem> problems)
    : std::runtime_error(Join(problems)), problems_(std::move(problems)) {}

InputError::InputError(InputProblem problem)
    : InputError(std::vector<InputProblem>{std::move(problem)}) {}

std::string InputError::Join(const std::vector<InputProblem>& problems) {
  std::string out;
  for (const auto& p : problems) {
    if (!out.empty()) out += '\n';
    out += p.ToString();
  }
  return out;
}

void ProblemList::Append(const std::vector<InputProblem>& more) {
  problems_.insert(problems_.end(), more.begin(), more.end());
}

void ProblemList::ThrowIfAny() const {
  if (!problems_.empty()) throw InputError(problems_);
}

namespace internal {
void AssertFail(const char* cond, const char* msg, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: internal error: %s (%s)\n", file, line, msg, cond);
  std::abort();
}
}  // namespace internal

}  // namespace tehl
