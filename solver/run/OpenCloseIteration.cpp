// One try of a load increment (Simulation.hpp's file comment, step 2): the open–close loop
// around the equilibrium iterations, with bolts that break on the way.

#include "run/Simulation.hpp"
#include "run/Stopwatch.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <sstream>

namespace mcdda {

namespace {

/// A contact that keeps opening and closing in a static equilibrium step with more than this share
/// of the largest contact force in play holds a block that cannot be held (the wedge's crest
/// contact: about the largest contact force; a chattering corner contact in the jointed tunnel:
/// 0.4 % of it, not a mechanism).
constexpr double cycling_limit = 0.05;
/// Rounds of friction forces brought into agreement with the normal forces (see open_close).
constexpr int max_friction_rounds = 10;
/// A round that changes more than twice as many contacts as an earlier round of its try, and
/// more than this many and this share of them, ends the try unsettled (gives_up_unsettled).
constexpr double unsettled_round_rise = 2.0;
constexpr int unsettled_round_floor = 100;
constexpr int unsettled_round_share = 100;  // 1 %
/// Where a smaller Δt has been shown not to help, a round whose increment moves a node more than
/// this many times the per-step displacement limit ends the try unsettled (open_close).
constexpr double beyond_reach_limits = 20.0;

}  // namespace

ContactSet Simulation::contact_set(std::vector<Contact> contacts) {
    const auto t0 = Clock::now();
    ContactSet set(std::move(contacts), [this](const Contact& c) { return kinematics_of(c); }, model_, topology_,
                   penalty_);
    timings_.contact += seconds_since(t0);
    return set;
}

Eigen::VectorXd Simulation::prepare_try(const Eigen::VectorXd& external, double dt, Attempt& attempt) {
    const auto t0 = Clock::now();
    bolt_broken_try_.assign(base_model_.bolts.size(), 0);
    attempt.bolts = bolt_links();
    rebuild_pattern_if_needed(attempt.contacts, attempt.bolts);
    const double beta = newmark_for(state_.step, model_.analysis.newmark_gamma).beta;
    // Shi's static DDA keeps the mass term M/(βΔt²) (velocities reset every step): it holds
    // blocks that only contacts restrain while they settle. A small-strain static analysis is a
    // pure equilibrium problem: no load may be carried by inertia there.
    elements_.prepare(element_nodes(), is_equilibrium_only() ? 0.0 : 1.0 / (beta * dt * dt));
    prepare_damping(dt);
    Eigen::VectorXd loads = external;
    if (model_.analysis.kind == AnalysisSettings::Kind::Dynamic)
        elements_.add_inertia_load(state_.velocity, state_.acceleration, beta, dt, loads);
    timings_.assembly += seconds_since(t0);
    return loads;
}

Simulation::Attempt Simulation::solve_increments(const Eigen::VectorXd& external, const Eigen::VectorXd* start_external,
                                                 double lambda, double dt, std::vector<Contact> contacts,
                                                 const Eigen::VectorXd& prescribed, bool ends_beyond_reach) {
    Attempt attempt;
    attempt.ends_beyond_reach = ends_beyond_reach;
    attempt.contacts = std::move(contacts);
    Eigen::VectorXd loads = prepare_try(external, dt, attempt);
    ContactSet set = contact_set(std::move(attempt.contacts));
    // Supports that move (displacement control) take their increments from the start; the
    // corrections never change them (they are not equations).
    Eigen::VectorXd d = prescribed;
    Eigen::VectorXd shift = Eigen::VectorXd::Zero(d.size());  // the part of the start's unbalance left for later
    if (start_external && lambda < 1.0) {
        // Only the share λ of the out-of-balance force at the start of the increment is applied
        // (an excavation's release, the rest of an unconverged step): the remainder stays as a
        // load that the next increment removes.
        shift = -(1.0 - lambda) * residual(Eigen::VectorXd::Zero(d.size()), *start_external, set, attempt.bolts,
                                           returned_, ElementMatrix::None);
        loads += shift;
    }
    open_close(d, loads, shift, set, attempt);
    viscous_try_ = false;
    // On the updated shape an increment that turns an element inside out is no solution, however
    // well it balances: the element's area, and with it its stiffness and mass, would change sign
    // (a soft block pushed at a finely meshed corner accepted one, and every later matrix failed
    // as "not positive definite"). Like a try that does not converge, it calls for a smaller
    // step (docs/penalty-and-time-step.md).
    if (attempt.outcome == Outcome::Converged) {
        if (const int e = inverted_element(d); e >= 0) {
            Point2 centre{0.0, 0.0};
            for (int a = 0; a < 3; ++a) {
                centre.x += element_nodes()[mesh_.triangles[e][a]].x / 3.0;
                centre.y += element_nodes()[mesh_.triangles[e][a]].y / 3.0;
            }
            std::ostringstream why;
            why.precision(4);
            why << "the increment turns the element at (" << centre.x << ", " << centre.y << ") inside out";
            attempt.outcome = Outcome::NotConverged;
            attempt.why = why.str();
        }
    }
    attempt.contacts = set.contacts();
    return attempt;
}

bool Simulation::held_factor_usable(const ContactSet& contacts, const std::vector<BoltLink>& bolts) const {
    // The factor of the last converged increment, when nothing it depends on has changed: the
    // element matrices of a small-strain static analysis stay on the undeformed shape with no
    // mass term, so only the closed contacts and (for Newton) the tangent differ. The elastic
    // iteration needs the exact elastic matrix; Newton takes the last tangent as its first
    // matrix and refactorises when it contracts slowly (equilibrate). A held elastic matrix
    // depends on nothing a try changes, so it also survives a try that failed (the smaller load
    // increment after it starts with it); a tangent only after a converged try.
    return is_equilibrium_only() && system_.has_factor() &&
           held_.closed == closed_signature(contacts.contacts(), bolts) &&
           (held_.tangent ? held_.usable && uses_newton() : true);
}

bool Simulation::equilibrate_or_fail(Eigen::VectorXd& d, const Eigen::VectorXd& loads, const ContactSet& contacts,
                                     bool& factor_valid, Attempt& attempt) {
    try {
        if (equilibrate(d, loads, contacts, attempt.bolts, factor_valid, attempt)) return true;
        attempt.outcome = Outcome::NotConverged;
        attempt.d = d;
    } catch (const SingularSystem& e) {
        attempt.outcome = Outcome::Singular;
        attempt.why = e.what();
        // Without a mass term, a block held only by sliding contacts is a mechanism: the load is
        // not carried (a smaller Δt would change nothing).
        const int sliding = contacts.count(ContactState::Sliding);
        if (is_equilibrium_only() && sliding > 0) {
            attempt.outcome = Outcome::NotConverged;
            attempt.why = "blocks slide freely: friction and cohesion of the " + std::to_string(sliding) +
                          " sliding contacts cannot hold them (the stiffness matrix is singular)";
        }
    }
    return false;
}

bool Simulation::break_overloaded_bolts(const Eigen::VectorXd& d, Attempt& attempt) {
    bool broke = false;
    for (const BoltLink& b : attempt.bolts) {
        const double strength = base_model_.bolts[b.bolt].strength;
        if (strength > 0.0 && b.force_after(d) > strength) {
            bolt_broken_try_[b.bolt] = 1;
            broke = true;
        }
    }
    if (broke) attempt.bolts = bolt_links();
    return broke;
}

void Simulation::open_close(Eigen::VectorXd& d, const Eigen::VectorXd& loads, const Eigen::VectorXd& shift,
                            ContactSet& contacts, Attempt& attempt) {
    const int max_iterations = model_.analysis.max_open_close_iterations;
    const bool equilibrium_only = is_equilibrium_only();
    bool factor_valid = held_factor_usable(contacts, attempt.bolts);
    held_.usable = false;  // until this try converges
    int friction_rounds = 0;
    int fewest_changes = std::numeric_limits<int>::max();  // of the rounds after the first
    int& iterations = attempt.open_close_iterations;
    iterations = 1;
    bool must_settle = false;  // the next round settles whatever happens
    while (iterations <= max_iterations) {
        // A round whose contact states then change need not settle its displacement: the next
        // round starts from it. The last round allowed settles whatever happens, as its few
        // changes may be accepted. (Static DDA settled every round while its staged tunnel's
        // verdict at a loose floor wedge hung on rounding: docs/benchmarks.md, "Fill-reducing
        // ordering, and rounds that need not settle", and "Static DDA's solves at last".) Nor
        // need one whose friction forces are then brought into agreement with its normal forces,
        // unless that round is the last friction round allowed (its friction is accepted as it is).
        attempt.may_stop_unsettled = iterations < max_iterations && !must_settle;
        attempt.may_stop_for_friction = friction_rounds < max_friction_rounds;
        must_settle = false;
        if (!equilibrate_or_fail(d, loads, contacts, factor_valid, attempt)) return;
        attempt.d = d;
        const double motion = largest_increment(d);
        attempt.motion = std::max(attempt.motion, motion);
        attempt.residual -= shift;  // reactions balance the loads actually applied
        // Where a smaller Δt has been shown not to help (the rest of the step halves the load:
        // StaticStep.cpp, time_step_futile), a round that moved a node many times as far as a
        // step may has set blocks loose far beyond the contacts found for the step (detection
        // looks 2.5 limits out), and no try that moves more than one limit is accepted. On a
        // slope cut by a 10,000-vertex rough joint the tries at a sixteenth of the step's load
        // and less moved 6–8 m (65–95 limits) in their second round and up to 850–2,600 m
        // later, each ending unsettled after all ten rounds. Not before Δt has failed: there the
        // rounds of a loose block do come back, held by the mass term (on the slope wedge, tries
        // whose rounds had moved up to 78,000 limits settled within one and were accepted).
        if (attempt.ends_beyond_reach && motion > beyond_reach_limits * displacement_limit_) {
            attempt.outcome = Outcome::Unsettled;
            attempt.why = "contacts do not settle";
            return;
        }
        // A bolt pulled beyond its strength breaks, and the try goes on without it.
        if (break_overloaded_bolts(d, attempt)) {
            rebuild_pattern_if_needed(contacts.contacts(), attempt.bolts);
            factor_valid = false;
            ++iterations;
            continue;
        }
        const auto t0 = Clock::now();
        const ContactSet::Update update = contacts.update_states(d, equilibrium_only);
        // Marginal changes are undone while the iteration goes on: a solution that made
        // significant changes is not trusted for them (acting on them lets one wrong guess
        // cascade through a block), and the friction rounds below must use the states K was
        // factorised with. They are kept when the try ends here.
        if (update.changes > 0) contacts.undo_marginal();
        timings_.contact += seconds_since(t0);
        if (update.changes > 0 && gives_up_unsettled(update.changes, contacts.size(), iterations, fewest_changes)) {
            attempt.outcome = Outcome::Unsettled;
            attempt.why = "contacts do not settle";
            return;
        }
        if (update.changes > 0) {
            // At the iteration limit a handful of changes among many contacts is accepted (they
            // take effect next step); more means the step is too large: Δt is cut (Shi).
            if (iterations == max_iterations &&
                update.changes <= std::max(2, static_cast<int>(contacts.size() / 500)))
                return;  // the factor is of states that changed: not held
            factor_valid = false;
            ++iterations;
            continue;
        }
        // A round that stopped before it settled is not accepted as it stands (should the update
        // find nothing to change after all): the same states settle from there.
        if (attempt.stopped_unsettled && update.friction_agrees()) {
            contacts.undo_marginal();
            must_settle = true;
            continue;
        }
        // Friction of sliding contacts was taken from the normal forces of the previous solve;
        // repeat until they agree (with the same factor).
        if (update.friction_agrees() || ++friction_rounds > max_friction_rounds) {
            // A relaxation increment leaves its contacts as it solved them. The marginal changes
            // this last update made (each by less than a thousandth of the largest contact
            // force) are kept at the end of other tries, so that states follow a moving model;
            // kept here they unbalance the state the relaxation is to bring into balance, which
            // is judged block by block: on ten thousand blocks 2–4·10⁴ N against the solve's
            // 10⁻⁷ N, and the relaxation chased its own changes through all its increments
            // (docs/benchmarks.md, "Ten thousand blocks").
            if (relaxing_) contacts.undo_marginal(/*cycling_too=*/false);
            settle_try(update, equilibrium_only, attempt);
            return;
        }
        contacts.undo_marginal();
    }
    attempt.outcome = Outcome::Unsettled;
    attempt.why = "contacts do not settle";
}

bool Simulation::gives_up_unsettled(int changes, std::size_t contacts, int round, int& fewest_changes) const {
    // Where a smaller Δt is the answer to contacts that do not settle (Shi's DDA), a round that
    // changes twice as many contacts as an earlier one did, and many of them (more than 100 and
    // 1 % of all), shows the try is not settling: Δt is cut now rather than after the rounds
    // left. The first round starts from the step's states and changes many as a rule. On a
    // slope cut by a 10,000-vertex zigzag joint (33,000 contacts) every try but the last doubled
    // its changes again, by 500 to 1,400, at its eighth round and ran on to its tenth; the
    // small models' tries (a block on an incline: 17 contacts, up to 15 changes) and the staged
    // tunnel's (1,800 contacts) never meet the rule (docs/benchmarks.md).
    if (round < 2 || is_equilibrium_only()) return false;
    const bool rising = changes > unsettled_round_rise * static_cast<double>(fewest_changes) &&
                        changes > std::max(unsettled_round_floor, static_cast<int>(contacts / unsettled_round_share));
    fewest_changes = std::min(fewest_changes, changes);
    return rising;
}

void Simulation::settle_try(const ContactSet::Update& update, bool equilibrium_only, Attempt& attempt) {
    // With no mass term nothing but the contacts' states can hold a block: a contact let pass
    // while it keeps opening and closing with a large force in play (one that opens while it
    // holds a block) means no consistent set of states balances the load here.
    if (equilibrium_only && update.cycling_force > cycling_limit * update.largest_force) {
        attempt.outcome = Outcome::NotConverged;
        std::ostringstream why;
        why << "no equilibrium of the contacts: contacts keep opening and closing with up to "
            << update.cycling_force / 1e3 << " kN/m in play against a limit of "
            << cycling_limit * update.largest_force / 1e3 << " kN/m (blocks move apart: friction and cohesion cannot hold them)";
        attempt.why = why.str();
        return;
    }
    held_.usable = true;
}

}  // namespace mcdda
