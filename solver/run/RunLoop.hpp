#pragma once
/// \file RunLoop.hpp
/// The step loop shared by `mcdda run` and the desktop program, so that both record, save and
/// report endings (collapse, failure, stop) the same way.

#include "run/RunOutput.hpp"
#include "run/Simulation.hpp"

#include <functional>
#include <string>

namespace mcdda {

struct RunEnd {
    RunStatus status = RunStatus::Completed;
    std::string message;  ///< "completed", or why the run stopped
    /// Collapsed: the load position (steps, fractional) last carried and the first not carried.
    double collapse_carried = 0.0, collapse_not_carried = 0.0;
};

/// Runs `simulation` to its last step: records every step and saves every output_every-th and the
/// last into `output` (may be null), calls `on_step` after each accepted step, and checks
/// `should_stop` before each step (it may block, e.g. while paused). Never throws for solver
/// failures: they become the returned status and message; RunOutput write errors propagate.
/// With `until_stage` ≥ 0 it stops (completed) once the stage before that one has run.
RunEnd run_steps(Simulation& simulation, RunOutput* output, const std::function<bool()>& should_stop,
                 const std::function<void(const StepReport&)>& on_step, int until_stage = -1);

}  // namespace mcdda
