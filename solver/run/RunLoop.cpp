#include "run/RunLoop.hpp"

#include <algorithm>
#include <exception>

namespace mcdda {

RunEnd run_steps(Simulation& simulation, RunOutput* output, const std::function<bool()>& should_stop,
                 const std::function<void(const StepReport&)>& on_step) {
    const int steps = simulation.model().analysis.steps;
    const int every = std::max(1, simulation.model().analysis.output_every);
    RunEnd end{RunStatus::Completed, "completed"};
    int last_saved = -1;
    if (output) {
        output->record_history(simulation);
        output->save_step(simulation);
        last_saved = 0;
    }
    while (simulation.state().step < steps) {
        if (should_stop && should_stop()) {
            end = {RunStatus::Cancelled, "cancelled by the user after step " + std::to_string(simulation.state().step)};
            break;
        }
        StepReport report;
        try {
            report = simulation.advance();
        } catch (const PlasticCollapse& e) {
            // The state is the last one carried; the collapse load lies between its loads and
            // those of the smallest increment beyond it that could not be carried.
            auto loads = [&](double position) {
                std::string text;
                for (const auto& [name, value] : simulation.load_magnitudes_at(position))
                    text += (text.empty() ? "" : ", ") + name + " = " + std::to_string(value);
                return text;
            };
            const std::string carried = loads(e.carried), not_carried = loads(e.not_carried);
            end = {RunStatus::Collapsed,
                   "collapse: " + std::string(e.what()) +
                       (carried.empty() ? std::string()
                                        : "; collapse load between " + carried + " (carried) and " + not_carried +
                                              " (not carried)")};
            if (output && simulation.state().step_fraction > 0.0) output->record_history(simulation);
            break;
        } catch (const std::exception& e) {
            end = {RunStatus::Failed,
                   "step " + std::to_string(simulation.state().step + 1) + " failed: " + e.what()};
            break;
        }
        if (output) {
            output->record_history(simulation);
            if (report.step % every == 0 || report.step == steps) {
                output->save_step(simulation);
                last_saved = report.step;
            }
        }
        if (on_step) on_step(report);
    }
    // An early ending still leaves its last accepted step on disk.
    if (output && last_saved != simulation.state().step) output->save_step(simulation);
    return end;
}

}  // namespace mcdda
