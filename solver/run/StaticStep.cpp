// A static step (Simulation.hpp's file comment): the step's load in increments, each tried and
// then accepted, applied in a smaller share, or retried with a smaller Δt; a static DDA step then
// relaxes to equilibrium at its loads.

#include "run/Simulation.hpp"
#include "run/Stopwatch.hpp"

#include "contact/ContactDetection.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

namespace mcdda {

namespace {

/// A plastic step of a model with contacts is a collapse only below this fraction of the set Δt.
constexpr double plastic_collapse_time_step = 1e-4;
constexpr int max_time_step_cuts = 30;
/// A Δt cut after which a try still moves more than this share of what the try before it moved
/// did not hold the model by inertia (time_step_futile).
constexpr double futile_cut_motion = 0.8;
/// Relaxation increments a static step may take, and how many may pass without halving the
/// out-of-balance ratio before the state counts as moving (a mechanism: the step ends unbalanced).
constexpr int max_relaxation_increments = 60;
constexpr int relaxation_window = 12;
/// Tries in a row that fail (even with more inertia) before the relaxation gives up: the state
/// is moving, and each failed try costs a whole set of equilibrium iterations. (Three were too
/// few: the staged tunnel on a coarse mesh then met its bolt stage unsettled and collapsed.)
constexpr int max_failed_relaxations = 6;
/// A relaxation increment whose largest displacement stays below this share of the displacement
/// limit doubles Δt whatever its open–close rounds (relax).
constexpr double relaxation_growth_share = 0.1;

std::string describe_position(double position) {
    const int step = static_cast<int>(std::floor(position + 1e-12));
    const double fraction = position - step;
    if (fraction < 1e-9) return "step " + std::to_string(step);
    return "step " + std::to_string(step + 1) + " at " + std::to_string(static_cast<int>(std::round(100 * fraction))) +
           " % of its load increment";
}

/// Byte for byte: equal bytes are equal values (a difference in padding only costs a detection).
template <class T>
bool same_bytes(const T* a, const T* b, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    return n == 0 || std::memcmp(a, b, n * sizeof(T)) == 0;
}
template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && same_bytes(a.data(), b.data(), a.size());
}

}  // namespace

std::vector<Contact> Simulation::detect_step_contacts(const Eigen::VectorXd& predicted) {
    const auto t0 = Clock::now();
    // Contact detection is a pure function of the geometry, the contacts carried over and these
    // settings; on a slope cut by a 10,000-vertex joint it cost 0.35 s per try, 14 tries of one
    // step from two states.
    const double search_distance = 2.5 * displacement_limit_;
    DetectionMemo& memo = detection_;
    const bool same = memo.search_distance == search_distance && memo.tolerance == contact_tolerance_ &&
                      same_bytes(memo.nodes, element_nodes()) && same_bytes(memo.previous, state_.contacts) &&
                      memo.predicted.size() == predicted.size() &&
                      same_bytes(memo.predicted.data(), predicted.data(), static_cast<std::size_t>(predicted.size()));
    if (!same) {
        memo.found = detect_contacts(element_nodes(), mesh_, topology_, search_distance, state_.contacts, predicted,
                                     contact_tolerance_);
        memo.nodes = element_nodes();
        memo.previous = state_.contacts;
        memo.predicted = predicted;
        memo.search_distance = search_distance;
        memo.tolerance = contact_tolerance_;
    }
    std::vector<Contact> contacts = memo.found;
    drop_absent(contacts);
    timings_.contact += seconds_since(t0);
    return contacts;
}

double Simulation::time_step_cut(const Attempt& attempt, double largest, double singular_factor) const {
    // Too large a step for the contact linearisation: Δt scaled so that the next one fits
    // (displacements grow with Δt²); contacts that do not settle: half.
    if (attempt.outcome == Outcome::Converged) return std::clamp(0.9 * std::sqrt(displacement_limit_ / largest), 0.1, 0.5);
    return attempt.outcome == Outcome::Singular ? singular_factor : 0.5;
}

Simulation::StaticResponse Simulation::judge_static(const Attempt& attempt, double increment, double dt,
                                                    double largest) const {
    const double floor = model_.analysis.min_load_fraction;
    const bool above_floor = increment > floor * (1.0 + 1e-9);
    const bool equilibrium_only = is_equilibrium_only();
    // The displacement limit keeps a step within reach of contact detection and of the geometry's
    // linearisation (Shi's g2). A small-strain static analysis needs neither: its contacts are
    // found on the undeformed shape whatever the step, and its equations are linear in the
    // geometry. There a converged increment stands however far it moved (near a collapse load the
    // plastic flow of a small load increment is large: refusing it until the increment was small
    // enough cost the Prandtl footing a third of its tries).
    const bool too_large =
        !equilibrium_only && attempt.outcome == Outcome::Converged && largest > displacement_limit_;
    // Static DDA (deformed geometry) has its mass term: a block set loose by a wrong guess of its
    // contacts' states (it flies off, or its iterations fail while some rock elsewhere yields)
    // is held by inertia at a smaller Δt and settles in the relaxation (relax), as in Shi's
    // static DDA. Only once Δt is tiny, or without contacts, is it a load question.
    const bool any_closed = std::any_of(attempt.contacts.begin(), attempt.contacts.end(),
                                        [](const Contact& c) { return c.state != ContactState::Open; });
    const bool contact_question =
        !equilibrium_only && (too_large || (attempt.outcome != Outcome::Converged && any_closed &&
                                            dt >= plastic_collapse_time_step * model_.analysis.time_step));
    // A matrix that is singular while the material yields is a mechanism forming: a load
    // question too (a block without supports and yielding nothing gets a smaller Δt below).
    const bool plastic_failure =
        !contact_question && (attempt.outcome == Outcome::NotConverged ||
                              (attempt.outcome == Outcome::Singular && attempt.yielding > 0));
    if (plastic_failure) return above_floor ? StaticResponse::SmallerLoad : StaticResponse::Collapse;
    // Contacts that do not settle, a block held by nothing but inertia, or a step too large for
    // the contact linearisation: a smaller Δt (Shi's static DDA). Plasticity is not involved.
    if (contact_question || (attempt.outcome == Outcome::Singular && attempt.yielding == 0) ||
        attempt.outcome == Outcome::Unsettled)
        return StaticResponse::SmallerTimeStep;
    return StaticResponse::Accept;
}

Simulation::Attempt Simulation::try_static_increment(double increment, bool load_question) {
    const double from = state_.step + state_.step_fraction;
    const double to = from + increment;
    const double time = state_.time + increment * model_.analysis.time_step;  // follows the load position
    iterating_.load_fraction = to - state_.step;
    std::vector<Contact> contacts = detect_step_contacts(Eigen::VectorXd());
    // The loads at the increment's start matter only when it is a part of what remains.
    const double lambda = increment / (1.0 - state_.step_fraction);
    Eigen::VectorXd start_external;
    if (lambda < 1.0) start_external = applied_forces(from, state_.time);
    return solve_increments(applied_forces(to, time), lambda < 1.0 ? &start_external : nullptr, lambda,
                            state_.time_step, std::move(contacts), prescribed_increments(to, time), load_question);
}

StepReport Simulation::advance_static() {
    if (const std::optional<double> ratio = at_rest_under_unchanged_loads()) return hold_static_step(*ratio);
    StepReport report;
    report.load_increments = 0;
    const double floor = model_.analysis.min_load_fraction;
    LoadSteps steps{1.0 - state_.step_fraction};
    while (true) {
        steps.increment = std::min(steps.increment, 1.0 - state_.step_fraction);
        const double dt = state_.time_step, from = state_.step + state_.step_fraction;
        Attempt attempt = try_static_increment(steps.increment, steps.time_step_futile);
        report.plastic_iterations += attempt.iterations;
        const double largest = attempt.outcome == Outcome::Converged ? largest_increment(attempt.d) : 0.0;
        StaticResponse response = judge_static(attempt, steps.increment, dt, largest);
        if (response == StaticResponse::SmallerTimeStep && time_step_futile(attempt, steps)) {
            // As for a plastic failure: a smaller load, and at the floor a collapse.
            response = steps.increment > floor * (1.0 + 1e-9) ? StaticResponse::SmallerLoad : StaticResponse::Collapse;
            attempt.why += ", and a smaller Δt does not help: halving it did not make the try move less,";
        }
        switch (response) {
            case StaticResponse::SmallerLoad:
                // Smaller load increments, never a smaller Δt: inertia must not carry the load.
                steps.failed_end = from + steps.increment;
                steps.increment = std::max(floor, 0.5 * steps.increment);
                steps.cut_motion = 0.0;  // motions at another load are not compared
                ++timings_.load_cuts;
                continue;
            case StaticResponse::Collapse:
                // The iterations spent count, whether or not the step was carried.
                timings_.iterations += report.plastic_iterations;
                timings_.max_iterations = std::max(timings_.max_iterations, report.plastic_iterations);
                throw PlasticCollapse("the load could not be carried beyond " + describe_position(from) + " (" +
                                          attempt.why + " for a load increment of " + std::to_string(steps.increment) +
                                          " of a step)",
                                      from, from + steps.increment, mechanism_motion(attempt));
            case StaticResponse::SmallerTimeStep:
                cut_static_time_step(attempt, largest, report, steps);
                continue;
            case StaticResponse::Accept: break;
        }
        steps.cut_motion = 0.0;  // the next try starts from another state
        if (accept_static(attempt, largest, dt, report, steps)) return report;
    }
}

// Where a failed try went is the mechanism when it moved blocks on their contacts with nothing
// yielding (within an open–close round the contact forces are linear in the displacement: a
// planar wedge's try slides the wedge as one body), or when its iterate flowed past the mechanism
// limit. A plastic iteration that stalled is not a mechanism: on the jointed tunnel's safety
// stage, at the factor just above the factor of safety, 5,178 integration points yielding, the
// stalled iterate had three nodes at a joint's end on the model's side move 150 times as far as
// the rock around the tunnel.
Eigen::VectorXd Simulation::mechanism_motion(const Attempt& attempt) {
    if (attempt.outcome != Outcome::NotConverged || !(attempt.mechanism || attempt.yielding == 0)) return {};
    return attempt.d;
}

bool Simulation::time_step_futile(const Attempt& attempt, LoadSteps& steps) {
    // Shi's answer to contacts that do not settle is more inertia: a smaller Δt makes a try move
    // less (as Δt² where inertia holds a block), so its contacts change less. Where halving Δt
    // left such a try moving as far as before, its motion is not inertia's to hold but the
    // load's (a stiff rock mass whose elastic motion dwarfs the mass term), and further cuts
    // only repeat the try: on a slope cut by a zigzag joint of 10,000 vertices, 14 halvings of Δt
    // (0.05 s to 3·10⁻⁶ s) left every try moving 0.16–0.28 m and every one failed as the first
    // had, and later in the step the motion after the first round stayed at 7 m over 9 more
    // halvings; the load halved, the motion halved. So the rest of the step halves the load
    // instead. Only tries whose every solve converged are compared: the iterates of a failed
    // solve run away as they please (a loose block of the staged tunnel "flew" 750 m and then
    // 190 m, and was held at a smaller Δt).
    if (steps.time_step_futile) return true;
    if (attempt.outcome != Outcome::Unsettled) {
        steps.cut_motion = 0.0;
        return false;
    }
    const bool futile = steps.cut_motion > 0.0 && attempt.motion > futile_cut_motion * steps.cut_motion;
    steps.cut_motion = attempt.motion;
    steps.time_step_futile = futile;
    return futile;
}

void Simulation::cut_static_time_step(const Attempt& attempt, double largest, StepReport& report, LoadSteps& steps) {
    const double largest_step = model_.analysis.time_step;
    last_singular_ = attempt.outcome == Outcome::Singular ? attempt.why : std::string();
    state_.time_step *= time_step_cut(attempt, largest, 0.5);
    report.time_step_cuts++;
    if (++steps.time_step_cuts > max_time_step_cuts || state_.time_step < 1e-9 * largest_step)
        throw std::runtime_error("the time step fell below its floor at step " + std::to_string(state_.step + 1) +
                                 (last_singular_.empty() ? " (contacts do not settle)" : ": " + last_singular_));
}

bool Simulation::accept_static(const Attempt& attempt, double largest, double dt, StepReport& report, LoadSteps& steps) {
    const double largest_step = model_.analysis.time_step, floor = model_.analysis.min_load_fraction;
    commit(attempt.d, dt, attempt.contacts, attempt.bolts);
    record_reactions(attempt.residual);
    ++report.load_increments;
    report.open_close_iterations += attempt.open_close_iterations;
    report.max_increment = std::max(report.max_increment, largest);
    state_.time += steps.increment * largest_step;
    state_.step_fraction += steps.increment;
    if (largest < 0.5 * displacement_limit_ && attempt.open_close_iterations <= 2)
        state_.time_step = std::min(largest_step, dt * 1.25);
    if (state_.step_fraction >= 1.0 - 1e-9) {
        state_.step += 1;
        state_.step_fraction = 0.0;
        report.time_step = dt;
        if (!is_equilibrium_only()) relax(report);
        finish_report(report, largest, attempt.residual);
        return true;
    }
    steps.increment = std::min(2.0 * steps.increment, 1.0 - state_.step_fraction);  // grow back after a cut
    // The load where a try failed is approached in two halves, not reached again at once from
    // the first success short of it (Salençon's excavation, elastic over its first half, failed
    // its second half just as it failed the whole).
    const double position = state_.step_fraction;
    const double failed_at = steps.failed_end - state_.step;  // within this step
    if (steps.failed_end >= 0.0 && position + steps.increment >= failed_at - 1e-9 && failed_at > position) {
        steps.increment = std::max(floor, 0.5 * (failed_at - position));
        steps.failed_end = -1.0;
    }
    return false;
}

// Shi's static DDA carries part of every increment by the mass term M/(βΔt²) and resets the
// velocities each step: the state an increment reaches balances the loads only together with
// that inertia, so how near equilibrium a run ended depended on how many steps it took (a block
// on an incline, "unbalanced" after 3 steps and in equilibrium after 10). A static step therefore
// ends by relaxing: increments at the step's loads from the state reached, Δt doubled after
// each that went easily (in a static analysis Δt only weighs the mass term: pseudo-time, so the
// iteration tends to the equilibrium solve), cut where a block moves too far, until the
// unbalanced-force ratio is within the equilibrium iterations' tolerance or stops falling.
void Simulation::relax(StepReport& report) {
    const double largest_step = model_.analysis.time_step;
    double dt = state_.time_step, best = std::numeric_limits<double>::infinity();
    int best_at = 0, failed = 0, futile_in_a_row = 0;
    for (int k = 0; k < max_relaxation_increments; ++k) {
        const double ratio = unbalanced_ratio();
        if (ratio <= model_.analysis.plastic_tolerance) break;
        if (ratio < 0.5 * best) {
            best = ratio;
            best_at = k;
        } else if (k - best_at >= relaxation_window) {
            break;
        }
        relaxing_ = true;
        Attempt attempt;
        try {
            attempt = solve_increments(applied_forces(state_.step, state_.time), nullptr, 1.0, dt,
                                       detect_step_contacts(Eigen::VectorXd()),
                                       prescribed_increments(state_.step, state_.time));
        } catch (...) {
            relaxing_ = false;
            throw;
        }
        relaxing_ = false;
        report.plastic_iterations += attempt.iterations;
        const double largest = attempt.outcome == Outcome::Converged ? largest_increment(attempt.d) : 0.0;
        if (attempt.outcome != Outcome::Converged || largest > displacement_limit_) {
            // More inertia: a smaller Δt. A state that cannot be moved at all stays as it is, and
            // so does one whose increments failed twice in a row, at Δt and at Δt / 2, for another
            // reason than moving too far (iterations that stalled, contacts that do not settle):
            // inertia holds blocks that move too far. A sliver of a fuzzed jointed tunnel stalled
            // at 0.07–0.09 of the force scale after 57 iterations at every Δt from 1 s to 1/32 s;
            // the slope cut by a 10,000-vertex zigzag joint flung blocks 68–650 m with contacts
            // that did not settle at every Δt from 0.05 s to 0.0016 s (59 factorisations).
            futile_in_a_row = attempt.outcome != Outcome::Converged ? futile_in_a_row + 1 : 0;
            dt *= time_step_cut(attempt, largest, 0.5);
            if (dt < 1e-9 * largest_step || ++failed >= max_failed_relaxations || futile_in_a_row >= 2) break;
            continue;
        }
        failed = 0;
        futile_in_a_row = 0;
        commit(attempt.d, dt, attempt.contacts, attempt.bolts);
        record_reactions(attempt.residual);
        ++report.relaxation_increments;
        report.max_increment = std::max(report.max_increment, largest);
        // An increment that went easily, or that moved far less than a step may: along a long
        // joint whose contacts change marginally every round a relaxation kept Δt small and crept
        // (the Lavarak cavern cut by a smooth 2,000-vertex joint: 58 increments of 4–9 rounds
        // each at Δt = 0.016 s, the out-of-balance ratio down by 7 % per increment).
        if (attempt.open_close_iterations <= 2 || largest < relaxation_growth_share * displacement_limit_) dt *= 2.0;
    }
    state_.time_step = std::min(largest_step, dt);
}

// A static step whose loads are those the last step ended at, from a state within the tolerance
// under them, has nothing to do. In static DDA it is a relaxation at those loads, and the
// relaxation stops at once there (relax); a small-strain step from a converged state is converged
// already. Tried anyway, it cost the iterations of a loaded step to creep on below the
// tolerance, so that the result depended on the number of steps: a rock mass of 10,201 blocks
// held at constant loads took 3–4 equilibrium iterations and half a factorisation per step, its
// sliding joints creeping 2.4 % of its largest displacement over 19 steps, and Salençon's tunnel
// 5 iterations per step at rest, its wall creeping 0.014 % over 18 steps.
// A construction stage's first step is always tried: the stage changes what is present. The
// steps of a strength reduction trial are no exception: on the slope wedge, trials that stand
// take 6–13 equilibrium iterations instead of 79–144, with the same factor, and their largest
// displacement no longer creeps up by 9 % as the factor nears the factor of safety (the
// wedge's mechanism, once drawn by that creep, is now the motion of the first trial that did not
// stand: StrengthReduction.cpp, save_critical_pair).
std::optional<double> Simulation::at_rest_under_unchanged_loads() {
    if (state_.step_fraction != 0.0 || state_.step <= stage_start_step_) return std::nullopt;
    const double from = state_.step, to = from + 1.0;
    const double time = state_.time + model_.analysis.time_step;
    if (prescribed_increments(to, time).lpNorm<Eigen::Infinity>() != 0.0) return std::nullopt;
    const Eigen::VectorXd now = applied_forces(from, state_.time);
    if (!same_bytes(now.data(), applied_forces(to, time).data(), static_cast<std::size_t>(now.size())))
        return std::nullopt;
    const double ratio = unbalanced_ratio();
    if (!(ratio <= model_.analysis.plastic_tolerance)) return std::nullopt;
    return ratio;
}

StepReport Simulation::hold_static_step(double ratio) {
    StepReport report;
    report.load_increments = 0;
    report.time_step = state_.time_step;
    ++timings_.steps_at_rest;
    state_.step += 1;
    state_.time += model_.analysis.time_step;
    // The stresses stay where they were: what was yielding stays on its yield surface.
    finish_report(report, 0.0, Eigen::VectorXd(), ratio);
    return report;
}

}  // namespace mcdda
