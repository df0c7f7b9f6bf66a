#include "run/RunLoop.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>

namespace mcdda {

namespace {

/// The end of a run at a collapse: the state is the last one carried; the collapse load lies
/// between its loads and those of the smallest increment beyond it that could not be carried.
/// Only the loads that differ between the two are named: a load the step does not change (the
/// far-field pressure of an excavation, a pressure whose table is constant) brackets nothing,
/// and "between 1e7 (carried) and 1e7 (not carried)" reads as a fault.
RunEnd collapse_end(const Simulation& simulation, const PlasticCollapse& e) {
    const auto carried = simulation.load_magnitudes_at(e.carried);
    const auto not_carried = simulation.load_magnitudes_at(e.not_carried);
    std::string below, beyond;
    for (const auto& [name, value] : carried) {
        const auto other = std::find_if(not_carried.begin(), not_carried.end(),
                                        [&name = name](const auto& load) { return load.first == name; });
        if (other == not_carried.end() || other->second == value) continue;
        below += (below.empty() ? "" : ", ") + name + " = " + std::to_string(value);
        beyond += (beyond.empty() ? "" : ", ") + name + " = " + std::to_string(other->second);
    }
    return {RunStatus::Collapsed,
            "collapse: " + std::string(e.what()) +
                (below.empty() ? std::string()
                               : "; collapse load between " + below + " (carried) and " + beyond + " (not carried)"),
            e.carried, e.not_carried};
}

/// Every step ran: is the model at rest? (A block still sliding, a slope still moving.)
RunEnd equilibrium_end(const Simulation& simulation) {
    const double ratio = simulation.state().unbalanced_ratio, limit = simulation.analysis().equilibrium_ratio;
    if (simulation.state().step == 0 || ratio <= limit) return {RunStatus::Completed, "completed"};
    char text[160];
    std::snprintf(text, sizeof text, "not in equilibrium: the unbalanced-force ratio after step %d is %.3g (limit %.3g)",
                  simulation.state().step, ratio, limit);
    return {RunStatus::Unbalanced, text};
}

}  // namespace

RunEnd run_steps(Simulation& simulation, RunOutput* output, const std::function<bool()>& should_stop,
                 const std::function<void(const StepReport&)>& on_step, int until_stage) {
    RunEnd end{RunStatus::Completed, "completed"};
    int last_saved = -1;
    if (output) {
        output->record_history(simulation);
        output->save_step(simulation);
        last_saved = 0;
    }
    // A stop is also heard inside a step (one step of a large model can take minutes).
    simulation.set_stop_check(should_stop);
    while (!simulation.finished()) {
        if (until_stage >= 0 && simulation.stage_complete() && simulation.current_stage() + 1 >= until_stage) break;
        if (should_stop && should_stop()) {
            end = {RunStatus::Cancelled, "cancelled by the user after step " + std::to_string(simulation.state().step)};
            break;
        }
        StepReport report;
        try {
            report = simulation.advance();
        } catch (const StepInterrupted&) {
            end = {RunStatus::Cancelled, "cancelled by the user during step " + std::to_string(simulation.state().step + 1) +
                                             " (the results are those of the last load increment accepted)"};
            if (output && simulation.state().step_fraction > 0.0) {
                output->record_history(simulation);
                output->save_state(simulation, simulation.state(), simulation.state().step + 1, simulation.state().time);
                last_saved = simulation.state().step;
            }
            break;
        } catch (const PlasticCollapse& e) {
            end = collapse_end(simulation, e);
            if (output && simulation.state().step_fraction > 0.0) {
                // Part of the step was carried: that state is saved (as the step it belongs to),
                // so the files show what summary.json reports.
                output->record_history(simulation);
                output->save_state(simulation, simulation.state(), simulation.state().step + 1, simulation.state().time);
                last_saved = simulation.state().step;
            }
            break;
        } catch (const std::exception& e) {
            end = {RunStatus::Failed, "step " + std::to_string(simulation.state().step + 1) + " failed: " + e.what()};
            break;
        }
        if (output) {
            output->record_history(simulation);
            // Every output_every-th step of the stage's settings, and the last of each stage.
            const int every = std::max(1, simulation.analysis().output_every);
            if (report.step % every == 0 || simulation.stage_complete()) {
                output->save_step(simulation);
                last_saved = report.step;
            }
        }
        if (on_step) on_step(report);
    }
    simulation.set_stop_check(nullptr);
    if (end.status == RunStatus::Completed) end = equilibrium_end(simulation);
    // An early ending still leaves its last accepted step on disk.
    if (output && last_saved != simulation.state().step) output->save_step(simulation);
    return end;
}

}  // namespace mcdda
