// A dynamic step (Simulation.hpp's file comment): one Δt, cut (Shi) until the step's contacts
// settle and its displacements stay within the limit.

#include "run/Simulation.hpp"

#include <algorithm>

namespace mcdda {

namespace {

/// A plastic step of a model with contacts is a collapse only below this fraction of the set Δt.
constexpr double plastic_collapse_time_step = 1e-4;
constexpr int max_time_step_cuts = 30;

}  // namespace

StepReport Simulation::advance_dynamic() {
    StepReport report;
    const double largest_step = model_.analysis.time_step;
    for (int cut = 0; cut <= max_time_step_cuts; ++cut) {
        const double dt = state_.time_step;
        Attempt attempt = solve_increments(applied_forces(state_.step + 1, state_.time + dt), nullptr, 1.0, dt,
                                           detect_step_contacts(state_.velocity * dt),
                                           prescribed_increments(state_.step + 1, state_.time + dt));
        report.plastic_iterations += attempt.iterations;
        if (attempt.outcome == Outcome::NotConverged) {
            // Between blocks, rock asked to carry too much is often a wrong contact guess at this
            // Δt (a joint that should open or slide); a smaller Δt lets the contacts sort
            // themselves out. Without contacts, or once Δt is tiny, it is a collapse.
            const bool any_contact = std::any_of(attempt.contacts.begin(), attempt.contacts.end(),
                                                 [](const Contact& c) { return c.state != ContactState::Open; });
            if (!any_contact || dt < plastic_collapse_time_step * largest_step)
                throw PlasticCollapse("the load could not be carried at step " + std::to_string(state_.step + 1) +
                                          " (" + attempt.why + ")",
                                      state_.step, state_.step + 1, mechanism_motion(attempt));
        }
        if (attempt.outcome == Outcome::Singular) last_singular_ = attempt.why;
        const double largest = attempt.outcome == Outcome::Converged ? largest_increment(attempt.d) : 0.0;
        if (attempt.outcome != Outcome::Converged || largest > displacement_limit_) {
            // Too large a step, or contacts that do not settle: a smaller Δt (Shi).
            state_.time_step = dt * time_step_cut(attempt, largest, 0.1);
            report.time_step_cuts++;
            if (state_.time_step < 1e-9 * largest_step)
                throw std::runtime_error("the time step fell below 1e-9 of its set value at step " +
                                         std::to_string(state_.step + 1) +
                                         (last_singular_.empty() ? " (contacts do not settle)" : ": " + last_singular_));
            last_singular_.clear();
            continue;
        }
        commit(attempt.d, dt, attempt.contacts, attempt.bolts);
        record_reactions(attempt.residual);
        state_.step += 1;
        state_.time += dt;
        report.time_step = dt;
        report.open_close_iterations = attempt.open_close_iterations;
        finish_report(report, largest, attempt.residual);
        // Grow Δt back towards its set value while steps are comfortably small.
        if (largest < 0.5 * displacement_limit_ && attempt.open_close_iterations <= 2)
            state_.time_step = std::min(largest_step, dt * 1.25);
        return report;
    }
    throw std::runtime_error("step " + std::to_string(state_.step + 1) + " could not be completed after " +
                             std::to_string(max_time_step_cuts) + " cuts of the time step");
}

}  // namespace mcdda
