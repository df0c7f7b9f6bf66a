// Earthquakes in a dynamic analysis (Model.hpp, BaseMotion): the record of a rigid base as the
// inertial load −M·a of an analysis relative to the base, the dashpots and incident wave of a
// compliant base and absorbing boundaries, and Rayleigh damping.

#include "run/Simulation.hpp"

#include "model/Defaults.hpp"

#include <cmath>

namespace mcdda {

void Simulation::set_up_shaking() {
    const BaseMotion& b = base_model_.base_motion;
    if (!b.present()) return;
    const int records[2] = {b.x, b.y};
    for (int dir = 0; dir < 2; ++dir)
        if (records[dir] >= 0) {
            shaking_[dir] = GroundShaking(base_model_.ground_motions[records[dir]]);
            shaken_[dir] = true;
        }
}

Simulation::BaseState Simulation::base_state(double time) const {
    BaseState s;
    const double t = record_time(time);
    if (t < 0.0) return s;
    for (int dir = 0; dir < 2; ++dir)
        if (shaken_[dir]) {
            s.acceleration[dir] = shaking_[dir].acceleration(t);
            s.velocity[dir] = shaking_[dir].velocity(t);
            s.displacement[dir] = shaking_[dir].displacement(t);
        }
    return s;
}

void Simulation::set_stage_dashpots() {
    held_for_good_.clear();
    if (model_.analysis.kind != AnalysisSettings::Kind::Dynamic) {
        dashpots_ = ViscousBoundary();
        return;
    }
    if (shaking_start_ < 0.0) {
        shaking_start_ = state_.time;
        shaking_start_displacement_ = state_.displacement;
    }
    dashpots_ = ViscousBoundary(model_, mesh_, topology_, element_active_);
    // The supports the dashpots replace carried the weight: their forces stay as loads (FLAC's
    // and UDEC's practice), or the model would sink through the base.
    held_for_good_.assign(state_.displacement.size(), 0);
    for (const ViscousBoundary::Dashpot& d : dashpots_.dashpots()) held_for_good_[2 * d.node] = held_for_good_[2 * d.node + 1] = 1;
    pattern_stale_ = true;
}

Eigen::VectorXd Simulation::displacement_since_shaking() const {
    if (shaking_start_displacement_.size() != state_.displacement.size())
        return Eigen::VectorXd::Zero(state_.displacement.size());
    Eigen::VectorXd u = state_.displacement - shaking_start_displacement_;
    if (base_model_.base_motion.kind != BaseMotion::Kind::Compliant) return u;
    // A compliant base moves with the wave: measured from its mean.
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    int count = 0;
    for (const ViscousBoundary::Dashpot& d : dashpots_.dashpots())
        if (d.input) {
            mean += Eigen::Vector2d(u[2 * d.node], u[2 * d.node + 1]);
            ++count;
        }
    if (count == 0) return u;
    mean /= count;
    for (Eigen::Index n = 0; 2 * n + 1 < u.size(); ++n) {
        u[2 * n] -= mean.x();
        u[2 * n + 1] -= mean.y();
    }
    return u;
}

void Simulation::add_base_loads(double time, Eigen::VectorXd& f) const {
    if (!relative_to_base() || model_.analysis.kind != AnalysisSettings::Kind::Dynamic) return;
    const Eigen::Vector2d a = base_state(time).acceleration;
    if (a.isZero()) return;
    elements_.add_rigid_body_inertia(element_nodes(), a, f);
}

void Simulation::prepare_damping(double dt) {
    viscous_try_ = false;
    if (model_.analysis.kind != AnalysisSettings::Kind::Dynamic) return;
    const NewmarkParameters p = newmark_for(state_.step, model_.analysis.newmark_gamma);
    velocity_rate_ = newmark_velocity_rate(p, dt);
    velocity_rest_ = (1.0 - p.gamma / p.beta) * state_.velocity + dt * (1.0 - p.gamma / (2.0 * p.beta)) * state_.acceleration;
    const AnalysisSettings& a = model_.analysis;
    if (a.damping_ratio > 0.0) {
        // Rayleigh: ξ at ω (least there), or at ω1 and ω2.
        const double w1 = 2.0 * pi * a.damping_frequency;
        const double w2 = a.damping_frequency_2 > 0.0 ? 2.0 * pi * a.damping_frequency_2 : w1;
        const double alpha = 2.0 * a.damping_ratio * w1 * w2 / (w1 + w2), beta = 2.0 * a.damping_ratio / (w1 + w2);
        elements_.set_damping(alpha, beta, velocity_rate_, velocity_rest_);
    }
    if (!dashpots_.empty()) {
        viscous_try_ = true;
        incident_ = base_model_.base_motion.kind == BaseMotion::Kind::Compliant ? base_state(state_.time + dt).velocity
                                                                                 : Eigen::Vector2d::Zero();
    }
}

}  // namespace mcdda
