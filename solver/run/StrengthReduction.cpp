#include "run/StrengthReduction.hpp"

#include "material/MaterialLaws.hpp"

#include <algorithm>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

namespace mcdda {

namespace {

/// The bracket grows (or shrinks) by this factor from 1 until one trial stands and one does not.
constexpr double bracket_growth = 1.5;
/// Factors beyond these are not searched: "stands at 100" or "does not stand at 0.01" is the answer.
constexpr double largest_factor = 100.0, smallest_factor = 0.01;

double largest_displacement(const SimulationState& s) { return Simulation::largest_increment(s.reported_displacement()); }

/// The largest nodal length of a motion (2 per node); 0 when it is empty or not finite.
double largest_motion(const Eigen::VectorXd& u) { return u.allFinite() ? Simulation::largest_increment(u) : 0.0; }

/// t − before, field by field (the counts and seconds of one trial).
RunTimings difference(const RunTimings& t, const RunTimings& before) {
    RunTimings d;
    d.assembly = t.assembly - before.assembly;
    d.factorization = t.factorization - before.factorization;
    d.solve = t.solve - before.solve;
    d.contact = t.contact - before.contact;
    d.plasticity = t.plasticity - before.plasticity;
    d.total = t.total - before.total;
    d.factorizations = t.factorizations - before.factorizations;
    d.symbolic_analyses = t.symbolic_analyses - before.symbolic_analyses;
    d.reused_factors = t.reused_factors - before.reused_factors;
    d.refinement_iterations = t.refinement_iterations - before.refinement_iterations;
    d.iterations = t.iterations - before.iterations;
    d.max_iterations = t.max_iterations;
    d.load_cuts = t.load_cuts - before.load_cuts;
    d.steps_at_rest = t.steps_at_rest - before.steps_at_rest;
    d.ordering = t.ordering;
    d.factorization_flops = t.factorization_flops;
    return d;
}

std::string factor_text(double f) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", f);
    return text;
}

}  // namespace

bool is_strength_reduction(const Model& model) {
    if (model.stages.empty()) return model.analysis.strength_reduction;
    return model.stages.back().analysis.strength_reduction;
}

struct StrengthReductionSearch::Trial {
    StrengthTrial record;
    SimulationState state;
    bool cancelled = false;
    bool collapsed = false;  ///< stopped short of its load: `state` is the last load it carried
    /// Collapsed: the share of the analysis's load it carried. (The middle of the collapse
    /// bracket, as a guess of what it could carry, chose worse factors to try.)
    double carried = 0.0;
    /// Collapsed: where its last try went from `state` (Simulation::CollapseBracket::motion).
    Eigen::VectorXd motion;
};

StrengthReductionSearch::StrengthReductionSearch(const Preprocessed& p) : model_(p) {
    if (!is_strength_reduction(p.model))
        throw std::runtime_error("the model's analysis (or its last stage's) is not a strength reduction");
    if (!p.model.stages.empty()) safety_stage_ = static_cast<int>(p.model.stages.size()) - 1;
    // Built once here so that a model that cannot be solved is refused before anything runs.
    simulation_ = std::make_unique<Simulation>(p);
}

StrengthReductionSearch::~StrengthReductionSearch() = default;

void StrengthReductionSearch::add_timings(const RunTimings& t) {
    timings_.assembly += t.assembly;
    timings_.factorization += t.factorization;
    timings_.solve += t.solve;
    timings_.contact += t.contact;
    timings_.plasticity += t.plasticity;
    timings_.total += t.total;
    timings_.factorizations += t.factorizations;
    timings_.symbolic_analyses += t.symbolic_analyses;
    timings_.reused_factors += t.reused_factors;
    timings_.refinement_iterations += t.refinement_iterations;
    timings_.iterations += t.iterations;
    timings_.max_iterations = std::max(timings_.max_iterations, t.max_iterations);
    timings_.load_cuts += t.load_cuts;
    timings_.steps_at_rest += t.steps_at_rest;
    timings_.ordering = t.ordering;
    timings_.factorization_flops = t.factorization_flops;
}

StrengthReductionSearch::Trial StrengthReductionSearch::run_trial(double factor, const Callbacks& callbacks) {
    if (callbacks.on_trial_start) callbacks.on_trial_start(factor);
    const auto start = std::chrono::steady_clock::now();
    // A strength reduction of the whole model, or of its first stage: every trial from the start.
    if (safety_stage_ <= 0) simulation_ = std::make_unique<Simulation>(model_, factor);
    else {
        simulation_->restore(*start_);
        simulation_->set_strength_factor(factor);
    }
    if (callbacks.on_iteration) simulation_->set_iteration_observer(callbacks.on_iteration);
    const RunTimings before = simulation_->timings();
    const int first_step = simulation_->state().step;
    const RunEnd end = run_steps(*simulation_, nullptr, callbacks.should_stop, nullptr);
    add_timings(difference(simulation_->timings(), before));

    Trial trial;
    trial.cancelled = end.status == RunStatus::Cancelled;
    trial.collapsed = end.status == RunStatus::Collapsed;
    if (trial.collapsed) trial.carried = end.collapse_carried / std::max(1, simulation_->analysis().steps);
    if (trial.collapsed && simulation_->collapse()) trial.motion = simulation_->collapse()->motion;
    trial.state = simulation_->state();
    StrengthTrial& r = trial.record;
    r.number = static_cast<int>(factor_.table.size()) + 1;
    r.factor = factor;
    r.stands = end.status == RunStatus::Completed;
    r.status = r.stands ? "stands" : status_name(end.status);
    if (!r.stands) r.message = end.message;
    r.steps = trial.state.step - first_step;
    r.iterations = simulation_->timings().iterations - before.iterations;
    r.max_displacement = largest_displacement(trial.state);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return trial;
}

/// The search's bracket: the highest factor that stood, the lowest that did not, and the factor
/// that stood before `stood` (the next lower one).
struct StrengthReductionSearch::Bracket {
    std::optional<Trial> stood, fell, below;
    bool cancelled = false;
};

RunEnd StrengthReductionSearch::run(RunOutput* output, const Callbacks& callbacks) {
    factor_ = FactorOfSafety{};
    collapses_.clear();
    double last_time = 0.0;
    if (safety_stage_ > 0) {
        // The construction stages, once, with their own strengths; the history keeps the trials.
        if (output) output->set_step_history(false);
        const RunEnd stages = run_steps(*simulation_, output, callbacks.should_stop, callbacks.on_step, safety_stage_);
        add_timings(simulation_->timings());
        if (stages.status != RunStatus::Completed) {
            RunEnd end = stages;
            end.message = "the stages before the strength reduction did not complete: " + stages.message;
            return end;
        }
        start_ = std::make_unique<SimulationCheckpoint>(simulation_->checkpoint());
        last_time = simulation_->state().time;
    }
    const AnalysisSettings& settings =
        safety_stage_ >= 0 ? model_.model.stages[safety_stage_].analysis : model_.model.analysis;
    const bool non_associated = std::any_of(model_.model.materials.begin(), model_.model.materials.end(),
                                            [](const Material& m) {
                                                const MaterialLaw* law = find_material_law(m.law);
                                                return m.reduce && law && law->non_associated && law->non_associated(m);
                                            });
    if (non_associated && settings.plasticity)
        factor_.non_associated_flow = non_associated_flow_name(settings.non_associated_flow);
    Bracket bracket;
    search(bracket, settings, output, callbacks);
    if (output) save_critical_pair(bracket, output, last_time);
    return ending(bracket, settings);
}

bool StrengthReductionSearch::try_factor(double f, Bracket& bracket, RunOutput* output, const Callbacks& callbacks) {
    Trial t = run_trial(f, callbacks);
    if (t.cancelled) return false;
    factor_.table.push_back(t.record);
    if (output) output->record_trial(*simulation_, t.record, t.state);
    if (callbacks.on_trial) callbacks.on_trial(t.record);
    if (t.collapsed && safety_stage_ < 0) collapses_.push_back({f, t.carried});
    if (t.record.stands) {
        if (!bracket.stood || f > bracket.stood->record.factor) {
            if (bracket.stood) bracket.below = std::move(bracket.stood);
            bracket.stood = std::move(t);
        }
    } else if (!bracket.fell || f < bracket.fell->record.factor) {
        bracket.fell = std::move(t);
    }
    return true;
}

void StrengthReductionSearch::search(Bracket& b, const AnalysisSettings& settings, RunOutput* output,
                                     const Callbacks& callbacks) {
    auto trials_left = [&] { return static_cast<int>(factor_.table.size()) < settings.max_trials; };
    b.cancelled = !try_factor(1.0, b, output, callbacks);
    // Bracket: up from a factor that stands, down from one that does not.
    while (!b.cancelled && (!b.stood || !b.fell) && trials_left()) {
        if (b.stood && b.stood->record.factor >= largest_factor) break;
        if (b.fell && b.fell->record.factor <= smallest_factor) break;
        const double next = b.stood ? b.stood->record.factor * bracket_growth : b.fell->record.factor / bracket_growth;
        b.cancelled = !try_factor(next, b, output, callbacks);
    }
    // Narrow the bracket.
    Pick last = Pick::Middle;
    while (!b.cancelled && b.stood && b.fell && trials_left() &&
           b.fell->record.factor - b.stood->record.factor > settings.factor_tolerance * b.stood->record.factor) {
        const auto [f, pick] = next_inside(b, settings.factor_tolerance, last == Pick::Guess && factor_.table.back().stands);
        b.cancelled = !try_factor(f, b, output, callbacks);
        last = pick;
    }

    factor_.trials = static_cast<int>(factor_.table.size());
    if (b.stood) factor_.value = factor_.converged = b.stood->record.factor;
    if (b.fell) factor_.not_converged = b.fell->record.factor;
    factor_.found = b.stood && b.fell &&
                    b.fell->record.factor - b.stood->record.factor <=
                        settings.factor_tolerance * b.stood->record.factor * (1 + 1e-12);
}

std::optional<double> StrengthReductionSearch::estimated_factor() const {
    // The two collapses at the lowest factors, nearest the factor of safety.
    std::vector<std::pair<double, double>> c;
    for (const auto& [factor, carried] : collapses_)
        if (carried > 0.0 && carried < 1.0) c.push_back({factor, carried});
    if (c.size() < 2) return std::nullopt;
    std::partial_sort(c.begin(), c.begin() + 2, c.end());
    // The line through (x1, y1) and (x2, y2) meets the diagonal x = y at s = 1/F.
    const double x1 = 1.0 / (c[0].second * c[0].first), y1 = 1.0 / c[0].first;
    const double x2 = 1.0 / (c[1].second * c[1].first), y2 = 1.0 / c[1].first;
    const double denominator = (x2 - x1) - (y2 - y1);
    if (std::fabs(denominator) < 1e-12 * std::max(std::fabs(x1), std::fabs(y1))) return std::nullopt;
    const double u = (y1 - x1) / denominator;
    const double s = y1 + u * (y2 - y1);
    if (!(s > 0.0) || !std::isfinite(s)) return std::nullopt;
    return 1.0 / s;
}

std::pair<double, StrengthReductionSearch::Pick> StrengthReductionSearch::next_inside(const Bracket& b, double tolerance,
                                                                                    bool guess_stood) const {
    const double low = b.stood->record.factor, high = b.fell->record.factor;
    // A trial this far inside either end, when it lands on the far side, closes the bracket.
    const double margin = 0.9 * tolerance * low;
    if (high - low > 2.0 * margin) {
        // The guess moves only with a new collapse: after a trial at it stood, one just above
        // (which closes the bracket when the guess was good); a guess the bracket has left
        // behind gives way to the middle.
        if (guess_stood) return {low + margin, Pick::AboveGuess};
        const std::optional<double> guess = estimated_factor();
        if (guess && *guess > low && *guess < high) return {std::clamp(*guess, low + margin, high - margin), Pick::Guess};
    }
    return {0.5 * (low + high), Pick::Middle};
}

// The critical pair: the last state that stood and the first that did not. The latter carries
// the mechanism engineers look at:
// - its displacement increment is, where that trial's last try failed as a mechanism
//   (Simulation::mechanism_motion: blocks sliding with nothing yielding, or an iterate that flowed
//   past the mechanism limit), the motion of that try: where the model goes at the reduced
//   strengths. A mechanism has a shape but no size, so it is scaled to the largest increment a
//   step may take (`max_displacement_ratio` of the model's size). Otherwise it is the
//   displacement from the next lower factor that stood to the last one, both in equilibrium
//   under the full load. That difference was the wedge's picture too once, but a wedge held by
//   friction until it slides stands nearly the same at both (its toe slips 10⁻⁶ m): it stood out
//   only while every step of a trial iterated on at loads it already carried, creeping below the
//   tolerance, so the picture depended on the number of steps a trial took;
// - its plastic strain increment is that from the next lower factor that stood to the last one,
//   so it concentrates on the slip surface (without a lower factor that stood, from the
//   construction's end). The trial that did not stand stopped at part of its load, so its own
//   state mixes load and strength.
void StrengthReductionSearch::save_critical_pair(const Bracket& b, RunOutput* output, double last_time) {
    int number = simulation_->state().step;
    if (b.stood) {
        VtuFields extra;
        extra.field_data.push_back({"strength_factor", 1, {b.stood->record.factor}});
        output->save_state(*simulation_, b.stood->state, ++number, last_time + b.stood->record.factor, extra);
    }
    if (!b.fell) return;
    VtuFields extra;
    extra.field_data.push_back({"strength_factor", 1, {b.fell->record.factor}});
    if (b.stood) {
        // (A trial's displacements are reported from its start: the construction's end.)
        const SimulationState* from = b.below ? &b.below->state : start_ ? &start_->state : nullptr;
        Eigen::VectorXd du = b.stood->state.reported_displacement();
        const double motion = largest_motion(b.fell->motion);
        if (motion > 0.0 && b.fell->motion.size() == du.size())
            du = (simulation_->displacement_limit() / motion) * b.fell->motion;
        else if (b.below)
            du -= b.below->state.reported_displacement();
        std::vector<double> plastic = b.stood->state.plastic_strain;
        if (from)
            for (std::size_t e = 0; e < plastic.size() && e < from->plastic_strain.size(); ++e)
                plastic[e] -= from->plastic_strain[e];
        VtuField increment{"displacement_increment", 3, {}};
        for (Eigen::Index i = 0; i + 1 < du.size(); i += 2)
            increment.values.insert(increment.values.end(), {du[i], du[i + 1], 0.0});
        VtuField strain{"plastic_strain_increment", 1, {}};
        strain.values = plastic;
        extra.point_data.push_back(std::move(increment));
        extra.cell_data.push_back(std::move(strain));
    }
    output->save_state(*simulation_, b.fell->state, ++number, last_time + b.fell->record.factor, extra);
}

RunEnd StrengthReductionSearch::ending(const Bracket& b, const AnalysisSettings& settings) const {
    if (b.cancelled)
        return {RunStatus::Cancelled, "cancelled by the user after " + std::to_string(factor_.table.size()) + " trials"};
    if (factor_.found)
        return {RunStatus::Completed, "factor of safety " + factor_text(factor_.value) + " (stands at " +
                                          factor_text(factor_.converged) + ", not at " +
                                          factor_text(factor_.not_converged) + "; " + std::to_string(factor_.trials) +
                                          " trials)"};
    if (b.stood && !b.fell)
        return {RunStatus::Failed, "the model still stands with its strengths divided by " +
                                       factor_text(b.stood->record.factor) + ": no factor of safety within the search"};
    if (b.fell && !b.stood)
        return {RunStatus::Failed, "the model does not stand even with its strengths divided by " +
                                       factor_text(b.fell->record.factor) + " (" + b.fell->record.message + ")"};
    return {RunStatus::Failed, "the search used its " + std::to_string(settings.max_trials) +
                                   " trials before the bracket [" + factor_text(factor_.converged) + ", " +
                                   factor_text(factor_.not_converged) + "] was within the tolerance"};
}

}  // namespace mcdda
