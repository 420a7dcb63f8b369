// The schema of a lubricant file (lubricants/*.toml; docs/case_format.md). Private to src/.
#pragma once

#include "base/schema.hpp"

namespace tehl::internal {

// Built once, immutable, thread-safe to read.
const Schema& LubricantSchema();

}  // namespace tehl::internal
