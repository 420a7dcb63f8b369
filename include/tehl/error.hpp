// Errors in tehl come in two tiers:
//  - InputError: a case, lubricant, study or train file (or an Options struct) broke a rule.
//    Always on. It carries every problem found in one pass, each with file, line, key, the
//    value received, the rule and what is allowed. The program exits with code 2.
//  - TEHL_ASSERT: an internal invariant, compiled out in release builds.
// A solver that does not converge is neither: it reports that in its Summary.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace tehl {

// One violated input rule. Printed as "file:line: key = value: rule (allowed: ...)".
struct InputProblem {
  std::string file;     // path of the input file, or "" for a programmatic input
  int line = 0;         // 1-based line in that file; 0 when there is no line (a missing key)
  std::string key;      // dotted key, e.g. "gear.pinion.teeth"
  std::string value;    // the value as written, e.g. "-3" or "\"roelands2\""; "" if missing
  std::string rule;     // what was violated, e.g. "must be > 0 [m]"
  std::string allowed;  // what is allowed, e.g. "a positive length in metres"

  std::string ToString() const;
};

// Thrown for bad user input. what() lists every problem, one per line.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<InputProblem> problems);
  explicit InputError(InputProblem problem);
  const std::vector<InputProblem>& problems() const { return problems_; }

 private:
  static std::string Join(const std::vector<InputProblem>& problems);
  std::vector<InputProblem> problems_;
};

// Collects problems and throws them all at once. Used by every reader and Validate().
class ProblemList {
 public:
  void Add(InputProblem p) { problems_.push_back(std::move(p)); }
  void Append(const std::vector<InputProblem>& more);
  bool empty() const { return problems_.empty(); }
  const std::vector<InputProblem>& problems() const { return problems_; }
  void ThrowIfAny() const;  // throws InputError when not empty

 private:
  std::vector<InputProblem> problems_;
};

namespace internal {
[[noreturn]] void AssertFail(const char* cond, const char* msg, const char* file, int line);
}  // namespace internal

}  // namespace tehl

#ifdef NDEBUG
#define TEHL_ASSERT(cond, msg) ((void)0)
#else
#define TEHL_ASSERT(cond, msg) \
  ((cond) ? (void)0 : ::tehl::internal::AssertFail(#cond, msg, __FILE__, __LINE__))
#endif
