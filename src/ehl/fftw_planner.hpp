// FFTW's planner (fftw_plan_*, fftw_destroy_plan) is not thread-safe; fftw_execute on
// distinct plans is. Every FFTW user in tehl takes this one process-wide lock around plan
// creation and destruction, so solvers can be built on the threads of a study's pool.
#pragma once

#include <mutex>

namespace tehl::internal {

std::mutex& FftwPlannerMutex();

}  // namespace tehl::internal
