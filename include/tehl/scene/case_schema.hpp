// The schema of a tehl case file (docs/case_format.md): its sections and keys, with
// types, units, defaults, ranges and meanings. `tehl case --print-default` prints it.
#pragma once

#include <string>

namespace tehl {
namespace internal {
struct Schema;
}
// The case-file schema (built once, immutable, thread-safe to read).
const internal::Schema& CaseSchema();
// Every key with its default, unit and meaning, as commented TOML.
std::string CaseDefaultsText();
}  // namespace tehl
