#pragma once
/// \file Progress.hpp
/// A terminal progress bar for long runs: redrawn in place on a terminal (at most ten times a
/// second), one line per tenth of the run otherwise (logs in CI stay short). Inside a long step
/// the equilibrium iterations are shown too: in place on a terminal, every ten seconds in a log.

#include "run/Simulation.hpp"

#include <chrono>

namespace mcdda::cli {

class Progress {
public:
    Progress(int total_steps, bool enabled);
    void update(const StepReport& report);
    void iteration(const IterationInfo& info);  ///< from Simulation's iteration observer
    void finish();

private:
    int total_;
    bool enabled_;
    bool terminal_;
    int next_line_step_ = 0;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point last_draw_;
    std::chrono::steady_clock::time_point step_start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last_iteration_line_ = std::chrono::steady_clock::now();
};

}  // namespace mcdda::cli
