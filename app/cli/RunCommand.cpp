// `mcdda run`: the headless analysis. Results stay valid at every moment (see RunOutput); Ctrl-C
// stops at the next equilibrium iteration, keeping the last load increment accepted.

#include "Commands.hpp"
#include "Progress.hpp"

#include "Preprocess.hpp"
#include "parallel/ParallelFor.hpp"
#include "run/RunLoop.hpp"
#include "run/RunOutput.hpp"
#include "run/Simulation.hpp"
#include "run/StrengthReduction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <functional>
#include <iostream>

namespace mcdda::cli {

namespace {

std::atomic<bool> stop_requested{false};

extern "C" void request_stop(int) { stop_requested = true; }

std::string flops_text(double flops) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", flops);
    return text;
}

void print_timings(const RunTimings& t, int steps) {
    std::cout << "timing (s): assembly " << t.assembly << ", factorization " << t.factorization << ", solve "
              << t.solve << ", contact " << t.contact << ", plasticity " << t.plasticity << ", total " << t.total
              << "\n"
              << "factorizations " << t.factorizations << " (" << t.symbolic_analyses << " symbolic analyses) in "
              << steps << " steps; " << t.reused_factors << " matrices solved with a held factor ("
              << t.refinement_iterations << " conjugate-gradient iterations)"
              << (t.ordering.empty() ? std::string()
                                     : "; ordering " + t.ordering + ", " + flops_text(t.factorization_flops) +
                                           " flops per Cholesky factorization")
              << "\n"
              << "equilibrium iterations " << t.iterations << " (at most " << t.max_iterations << " in a step), "
              << t.load_cuts << " load increments halved"
              << (t.steps_at_rest > 0 ? "; " + std::to_string(t.steps_at_rest) +
                                            " steps in equilibrium at unchanged loads, nothing to solve"
                                      : std::string())
              << "\n"
              << "threads " << thread_count() << " (element loops and contact search)\n"
              << "CPU time of the process " << static_cast<double>(std::clock()) / CLOCKS_PER_SEC << " s\n";
    if (steps > 0 && t.factorizations > 0)
        std::cout << "per step " << t.total / steps << " s; one factorization " << t.factorization / t.factorizations
                  << " s; step / factorization = " << (t.total / steps) / (t.factorization / t.factorizations) << "\n";
}

/// Ctrl-C and SIGTERM (a batch system's stop) end the run while this lives (within the step).
class StopOnSignals {
public:
    StopOnSignals() {
        stop_requested = false;
        interrupt_ = std::signal(SIGINT, request_stop);
        terminate_ = std::signal(SIGTERM, request_stop);
    }
    ~StopOnSignals() {
        std::signal(SIGINT, interrupt_);
        std::signal(SIGTERM, terminate_);
    }
    StopOnSignals(const StopOnSignals&) = delete;
    StopOnSignals& operator=(const StopOnSignals&) = delete;

private:
    void (*interrupt_)(int);
    void (*terminate_)(int);
};

/// The run's output folder; nullptr, said on stderr, when it cannot be made or written.
std::unique_ptr<RunOutput> open_output(const Request& r, const std::string& stem) {
    try {
        return std::make_unique<RunOutput>(r.out, stem);
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return nullptr;
    }
}

/// After a failed write: where the earlier run's results are, when the run kept them.
void note_previous(const RunOutput& output) {
    if (!output.kept_results().empty()) std::cerr << "the earlier results are kept in " << output.kept_results() << "\n";
}

/// summary.json; false, said on stderr, when the folder became unwritable or full during the run.

bool write_summary(RunOutput& output, const Simulation& simulation, const RunEnd& end,
                   const FactorOfSafety* factor = nullptr) {
    try {
        output.write_summary(&simulation, end.status, end.message, factor);
        return true;
    } catch (const std::exception& e) {
        std::cerr << "error: cannot write the run's summary: " << e.what() << "\n";
        note_previous(output);
        return false;
    }
}

/// Builds the solver object (a Simulation or a search) for `p`; a model it refuses is reported
/// with the results kept noted, and null returned. Done before the output folder is touched:
/// a run refused here leaves earlier results in the folder as they were.
template <class Solver>
std::unique_ptr<Solver> set_up(const Request& r, const Preprocessed& p, const std::function<void()>& note_kept_results) {
    try {
        return std::make_unique<Solver>(p);
    } catch (const std::exception& e) {
        std::cerr << r.model << ": error: " << e.what() << "\n";
        note_kept_results();
        return nullptr;
    }
}

/// `mcdda run` of a strength reduction analysis: the trials one line each, then the factor.
int run_strength_reduction(const Request& r, const Preprocessed& p, const std::string& stem,
                           const std::function<void()>& note_kept_results) {
    const std::unique_ptr<StrengthReductionSearch> search = set_up<StrengthReductionSearch>(r, p, note_kept_results);
    if (!search) return exit_model_error;
    const std::unique_ptr<RunOutput> output = open_output(r, stem);
    if (!output) return exit_output_error;
    if (!r.quiet)
        std::cout << "running " << r.model << ": " << p.statistics.elements << " elements, " << p.statistics.blocks
                  << " blocks, strength reduction -> " << r.out << std::endl;
    StrengthReductionSearch::Callbacks callbacks;
    callbacks.should_stop = [] { return stop_requested.load(); };
    callbacks.on_trial = [&](const StrengthTrial& t) {
        if (r.quiet) return;
        char line[200];
        std::snprintf(line, sizeof line, "trial %d: F = %.4f %s (%d steps, %d iterations, largest displacement %.4g m)",
                      t.number, t.factor, t.stands ? "stands" : ("does not stand: " + t.status).c_str(), t.steps,
                      t.iterations, t.max_displacement);
        std::cout << line << std::endl;
    };
    RunEnd end;
    try {
        const StopOnSignals stop;
        end = search->run(output.get(), callbacks);
    } catch (const std::exception& e) {  // writing results failed
        std::cerr << "error: " << e.what() << "\n";
        note_previous(*output);
        return exit_output_error;
    }
    if (!write_summary(*output, search->simulation(), end, &search->factor())) return exit_output_error;
    if (end.status != RunStatus::Completed) std::cerr << r.model << ": " << status_name(end.status) << ": " << end.message << "\n";
    if (!r.quiet) {
        const FactorOfSafety& f = search->factor();
        if (f.found)
            std::cout << "factor of safety " << f.value << " (stands at " << f.converged << ", not at " << f.not_converged
                      << "; " << f.trials << " trials"
                      << (f.non_associated_flow == "davis" ? "; ψ < φ by Davis's reduction, associated flow" : "")
                      << (f.non_associated_flow == "direct" ? "; ψ < φ solved directly" : "") << "); results in "
                      << r.out << "\n";
    }
    if (r.profile) print_timings(search->timings(), search->simulation().state().step);
    return exit_status(end.status);
}

}  // namespace

int run_run(const Request& r) {
    if (r.threads > 0) set_thread_count(r.threads);
    const Preprocessed p = preprocess_file(r.model, r.overrides, PreprocessStage::Mesh);
    for (const Diagnostic& d : p.diagnostics)
        if (d.severity == Diagnostic::Severity::Error || !r.quiet) std::cerr << r.model << ": " << format_diagnostic(d) << "\n";
    // A refused run leaves the folder alone; say so when it holds earlier results.
    const auto note_kept_results = [&] {
        std::error_code ec;  // an unreadable folder is no reason to fail differently
        if (std::filesystem::exists(std::filesystem::path(r.out) / "summary.json", ec))
            std::cerr << "the results already in " << r.out << " are left as they were\n";
    };
    if (!p.ok) {
        note_kept_results();
        return exit_model_error;
    }

    std::string stem = std::filesystem::path(r.model).stem().string();
    if (stem.empty()) stem = "model";
    if (is_strength_reduction(p.model)) return run_strength_reduction(r, p, stem, note_kept_results);
    const std::unique_ptr<Simulation> simulation = set_up<Simulation>(r, p, note_kept_results);
    if (!simulation) return exit_model_error;
    const std::unique_ptr<RunOutput> output = open_output(r, stem);
    if (!output) return exit_output_error;
    if (!r.quiet)
        std::cout << "running " << r.model << ": " << p.statistics.elements << " elements, " << p.statistics.blocks
                  << " blocks, " << simulation->planned_steps() << " steps"
                  << (p.model.stages.empty() ? std::string() : " in " + std::to_string(p.model.stages.size()) + " stages")
                  << " -> " << r.out << "\n";

    Progress progress(simulation->planned_steps(), !r.quiet);
    simulation->set_iteration_observer([&progress](const IterationInfo& info) { progress.iteration(info); });
    RunEnd end;
    try {
        const StopOnSignals stop;
        end = run_steps(*simulation, output.get(), [] { return stop_requested.load(); },
                        [&](const StepReport& report) { progress.update(report); });
    } catch (const std::exception& e) {  // writing results failed
        progress.finish();
        std::cerr << "error: " << e.what() << "\n";
        note_previous(*output);
        return exit_output_error;
    }
    progress.finish();
    if (!write_summary(*output, *simulation, end)) return exit_output_error;
    const RunStatus status = end.status;
    if (status != RunStatus::Completed) std::cerr << r.model << ": " << status_name(status) << ": " << end.message << "\n";
    if (status != RunStatus::Completed && status != RunStatus::Collapsed && !output->kept_results().empty())
        std::cerr << "the earlier results are kept in " << output->kept_results() << "\n";
    if (!r.quiet) {
        std::cout << status_name(status) << ": " << simulation->state().step << " steps, t = " << simulation->state().time
                  << " s";
        if (simulation->full_model().base_motion.present()) {
            // What the shaking left, relative to the base (summary.json's permanent_displacement).
            const Eigen::VectorXd u = simulation->displacement_since_shaking();
            double largest = 0.0;
            for (Eigen::Index n = 0; 2 * n + 1 < u.size(); ++n) largest = std::max(largest, std::hypot(u[2 * n], u[2 * n + 1]));
            std::cout << "; permanent displacement " << largest * 1e3 << " mm (largest, relative to the base)";
        }
        std::cout << "; results in " << r.out << "\n";
    }
    if (r.profile) print_timings(simulation->timings(), simulation->state().step);
    return exit_status(status);
}

}  // namespace mcdda::cli
