// The HDF5 library of Debian is built without its thread-safety option: no two threads may
// be inside the library at once. Every HDF5 call in tehl (the result writer, the study index
// and the readers of result files) holds this one process-wide lock, so mesh cycles can run
// on the threads of a study's pool. Recursive, so a locked helper may call another.
#pragma once

#include <mutex>

namespace tehl::internal {

std::recursive_mutex& Hdf5LibraryMutex();

}  // namespace tehl::internal
