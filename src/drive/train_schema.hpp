// The schema of a train file (train_reader.hpp), built per file: the member names the user
// wrote become sections ([gear.NAME], [carrier.NAME], [rack.NAME], [mesh.NAME]), so every key
// is still declared, typed and range-checked with file:line. Private to src/drive.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "base/schema.hpp"

namespace tehl::internal {

// Member names by group ("gear", "carrier", "rack", "mesh"), each group in file order.
using TrainMemberNames = std::map<std::string, std::vector<std::string>>;

// The names written in the train file `path`: a pre-scan, without checks (the Document does
// all the checking); nothing for a file that cannot be read or parsed.
TrainMemberNames ScanTrainMemberNames(const std::string& path);

// [train], a section per name of `names`, [motor] and [load].
Schema BuildTrainSchema(const TrainMemberNames& names);

}  // namespace tehl::internal
