#include "contact/ContactSet.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {
/// A state change by a force below this share of the largest contact force is marginal.
constexpr double marginal_force_share = 1e-3;

/// Adds a contact sliding before and after an update to the friction in use and to how much the
/// update's normal force changes it.
void add_friction(const Contact& before, const Contact& after, double tan_friction, double& used, double& change) {
    if (before.state != ContactState::Sliding || after.state != ContactState::Sliding) return;
    const double normal_used = std::max(0.0, before.normal_force);
    used += normal_used * tan_friction;
    change += std::fabs(std::max(0.0, after.normal_force) - normal_used) * tan_friction;
}
}  // namespace

ContactSet::ContactSet(std::vector<Contact> contacts,
                       const std::function<ContactKinematics(const Contact&)>& kinematics_of, const Model& model,
                       const MeshTopology& topology, double penalty)
    : contacts_(std::move(contacts)), flips_(contacts_.size(), 0) {
    kinematics_.reserve(contacts_.size());
    properties_.reserve(contacts_.size());
    for (const Contact& c : contacts_) {
        kinematics_.push_back(kinematics_of(c));
        properties_.push_back(contact_properties(c, kinematics_.back(), model, topology, penalty));
    }
}

bool ContactSet::any_closed() const {
    return std::any_of(contacts_.begin(), contacts_.end(), [](const Contact& c) { return c.state != ContactState::Open; });
}

bool ContactSet::any_sliding_with_strength() const {
    for (std::size_t i = 0; i < contacts_.size(); ++i)
        if (contacts_[i].state == ContactState::Sliding &&
            (properties_[i].tan_friction > 0.0 || properties_[i].cohesion_force > 0.0))
            return true;
    return false;
}

int ContactSet::count(ContactState state) const {
    return static_cast<int>(
        std::count_if(contacts_.begin(), contacts_.end(), [state](const Contact& c) { return c.state == state; }));
}

Vector6 ContactSet::local(std::size_t i, const Eigen::VectorXd& d) const {
    Vector6 v;
    for (int a = 0; a < 3; ++a)
        for (int dir = 0; dir < 2; ++dir) v[2 * a + dir] = d[2 * kinematics_[i].nodes[a] + dir];
    return v;
}

void ContactSet::add_forces(const Eigen::VectorXd& d, Eigen::VectorXd& force) const {
    Matrix6 kc;
    Vector6 fc;
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
        if (contacts_[i].state == ContactState::Open) continue;
        contact_terms(contacts_[i], kinematics_[i], properties_[i], kc, fc);
        fc.noalias() -= kc * local(i, d);
        for (int a = 0; a < 3; ++a)
            for (int dir = 0; dir < 2; ++dir) force[2 * kinematics_[i].nodes[a] + dir] += fc[2 * a + dir];
    }
}

void ContactSet::add_matrices(SymmetricSystem& system, int first_group) const {
    Matrix6 kc;
    Vector6 fc;
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
        if (contacts_[i].state == ContactState::Open) continue;
        contact_terms(contacts_[i], kinematics_[i], properties_[i], kc, fc);
        system.add(first_group + static_cast<int>(i), kc.data());
    }
}

ContactSet::Update ContactSet::update_states(const Eigen::VectorXd& d, bool equilibrium_only) {
    Update u;
    marginal_.clear();
    for (const Contact& c : contacts_) u.largest_force = std::max(u.largest_force, std::fabs(c.normal_force));
    const double force_tolerance = marginal_force_share * u.largest_force;
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
        const Contact before = contacts_[i];
        double change_force = 0.0;
        const StateChange found =
            update_contact_state(contacts_[i], kinematics_[i], properties_[i], local(i, d), force_tolerance, &change_force);
        const int flips = found == StateChange::Significant ? ++flips_[i] : flips_[i];
        const StateChange change = cycling_rule(before, contacts_[i], found, flips, equilibrium_only);
        if (found == StateChange::Significant && change == StateChange::Marginal)
            u.cycling_force = std::max(u.cycling_force, change_force);
        if (change == StateChange::Significant) ++u.changes;
        if (change == StateChange::Marginal) marginal_.push_back({i, before, found == StateChange::Significant});
        add_friction(before, contacts_[i], properties_[i].tan_friction, u.friction_used, u.friction_change);
    }
    return u;
}

StateChange ContactSet::cycling_rule(const Contact& before, Contact& after, StateChange change, int flips,
                                     bool equilibrium_only) const {
    // Cycling (stick–slip or open–close at its limit): its last change is kept only if the
    // try ends without other changes.
    if (change != StateChange::Significant || flips <= 2) return change;
    const bool stick_slip = before.state != ContactState::Open && after.state != ContactState::Open;
    if (equilibrium_only && stick_slip && after.state == ContactState::Locked) {
        after.state = ContactState::Sliding;
        after.slip = before.slip;
        after.shear_spring = before.shear_spring;
        return StateChange::None;
    }
    return equilibrium_only && stick_slip ? change : StateChange::Marginal;
}

bool ContactSet::would_change(const Eigen::VectorXd& d, bool equilibrium_only, bool friction_too) const {
    double largest = 0.0;
    for (const Contact& c : contacts_) largest = std::max(largest, std::fabs(c.normal_force));
    double friction_used = 0.0, friction_change = 0.0;  // as update_states sums them
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
        const Contact& before = contacts_[i];
        Contact after = before;
        const StateChange found =
            update_contact_state(after, kinematics_[i], properties_[i], local(i, d), marginal_force_share * largest);
        const int flips = flips_[i] + (found == StateChange::Significant ? 1 : 0);
        if (cycling_rule(before, after, found, flips, equilibrium_only) == StateChange::Significant) return true;
        add_friction(before, after, properties_[i].tan_friction, friction_used, friction_change);
    }
    return friction_too && friction_change > friction_agreement * friction_used;
}

void ContactSet::undo_marginal(bool cycling_too) {
    for (const MarginalChange& m : marginal_) {
        if (m.cycling && !cycling_too) continue;
        Contact& c = contacts_[m.index];
        c.state = m.before.state;
        c.slip = m.before.slip;
        c.shear_spring = m.before.shear_spring;
    }
}

}  // namespace mcdda
