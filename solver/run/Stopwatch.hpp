#pragma once
/// \file Stopwatch.hpp
/// Wall-clock seconds for the run's timing breakdown (RunTimings, `--profile`).

#include <chrono>

namespace mcdda {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace mcdda
