#pragma once
/// \file StrengthReduction.hpp
/// The factor of safety by strength reduction (Griffiths & Lane 1999; as RS2, PLAXIS and FLAC
/// compute it): the model's strengths are divided by trial factors F (material/StrengthReduction.hpp)
/// and the model is solved again for each; the largest F at which it stands is its factor of
/// safety. The search brackets the factor (×1.5 or ÷1.5 from 1 until one trial stands and one
/// does not; factors below 1 too) and narrows the bracket until it is narrower than
/// analysis.factor_tolerance of the factor: at its middle, or — once two trials collapsed —
/// where the limit curve through their collapse loads meets the whole load (estimated_factor).
/// Only the trials' verdicts decide the factor; the guess chooses where to look.
///
/// A trial stands when every step of it reaches equilibrium (the static solver's verdict, with
/// its load bisection: docs/plasticity.md); it does not when a step collapses, when it ends out
/// of equilibrium, or when the solver fails. Where the strength reduction is the model's analysis
/// every trial runs the whole model from its initial state with reduced strengths (RS2); where it
/// is the analysis of the last stage (a safety stage, PLAXIS) the stages before it run once, with
/// their own strengths, and every trial starts from the state they left.

#include "run/FactorOfSafety.hpp"
#include "run/RunLoop.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace mcdda {

/// Is this a strength reduction analysis (the model's, or its last stage's)?
bool is_strength_reduction(const Model& model);

class StrengthReductionSearch {
public:
    /// Throws std::runtime_error, naming the problem, when the model cannot be set up.
    explicit StrengthReductionSearch(const Preprocessed& model);
    ~StrengthReductionSearch();

    struct Callbacks {
        std::function<bool()> should_stop;                      ///< checked before each step
        std::function<void(const StepReport&)> on_step;         ///< steps of the construction stages
        std::function<void(double factor)> on_trial_start;
        std::function<void(const StrengthTrial&)> on_trial;     ///< after each trial
        std::function<void(const IterationInfo&)> on_iteration; ///< inside long steps
    };

    /// Runs the construction stages (recorded and saved in `output` like any run) and the
    /// search. The trials go into the history, one row each; the last state that stood and the
    /// first that did not are saved as the two last steps, the latter with the increments of
    /// displacement and plastic strain between them (the mechanism). RunOutput errors propagate.
    RunEnd run(RunOutput* output, const Callbacks& callbacks);

    const FactorOfSafety& factor() const { return factor_; }
    /// The simulation of the construction stages (or of the last trial): mesh, model, timings.
    const Simulation& simulation() const { return *simulation_; }
    /// Timings summed over the construction stages and every trial.
    const RunTimings& timings() const { return timings_; }

private:
    struct Trial;
    struct Bracket;
    Trial run_trial(double factor, const Callbacks& callbacks);
    /// Runs a trial and places it in the bracket; false when it was cancelled.
    bool try_factor(double factor, Bracket& bracket, RunOutput* output, const Callbacks& callbacks);
    /// Brackets the factor, then narrows the bracket to the tolerance.
    void search(Bracket& bracket, const AnalysisSettings& settings, RunOutput* output, const Callbacks& callbacks);
    /// How a trial inside the bracket was chosen.
    enum class Pick { Middle, Guess, AboveGuess };
    /// The next factor to try inside the bracket: the guess of estimated_factor, kept off the
    /// bracket's ends, or just above it after a trial at the guess stood (`guess_stood`), or the
    /// middle.
    std::pair<double, Pick> next_inside(const Bracket& bracket, double tolerance, bool guess_stood) const;
    /// A guess of the factor from the two collapses at the lowest factors. A trial that collapsed
    /// at F after carrying a share λ of its load is a point (1/(λF), 1/F) of the limit curve in
    /// the plane (cohesion divided by, tan φ divided by): a load λ times larger acts on
    /// Mohr–Coulomb strength as a cohesion λ times smaller would (stresses grow with the load, and
    /// friction's strength with them). The factor is where the curve — here the line through the
    /// two points — meets the diagonal: both divided alike, under the whole load. None without two
    /// collapses that carried part of their load.
    std::optional<double> estimated_factor() const;
    void save_critical_pair(const Bracket& bracket, RunOutput* output, double last_time);
    RunEnd ending(const Bracket& bracket, const AnalysisSettings& settings) const;
    void add_timings(const RunTimings& t);

    const Preprocessed& model_;
    int safety_stage_ = -1;  ///< index of the strength reduction stage; −1: the model's analysis
    std::unique_ptr<Simulation> simulation_;
    std::unique_ptr<SimulationCheckpoint> start_;  ///< where every trial of a safety stage starts
    /// Per trial that collapsed (not in a safety stage): its factor and the share of the load it carried.
    std::vector<std::pair<double, double>> collapses_;
    FactorOfSafety factor_;
    RunTimings timings_;
};

}  // namespace mcdda
