#pragma once
/// \file ContactSet.hpp
/// The contacts of one try of a step and what the equilibrium iterations ask of them: geometry
/// and springs fixed at the step's start, forces and matrices at the increments d, and the
/// open–close update of their states after a solve (paper, Table 1: the open–close loop).

#include "contact/Contact.hpp"
#include "contact/ContactLaw.hpp"
#include "linalg/SymmetricSystem.hpp"

#include <Eigen/Dense>

#include <functional>
#include <utility>
#include <vector>

namespace mcdda {

class ContactSet {
public:
    /// `kinematics_of`: a contact's geometry at the step's start (deformed or undeformed shape).
    ContactSet(std::vector<Contact> contacts, const std::function<ContactKinematics(const Contact&)>& kinematics_of,
               const Model& model, const MeshTopology& topology, double penalty);

    const std::vector<Contact>& contacts() const { return contacts_; }
    std::size_t size() const { return contacts_.size(); }
    bool any_closed() const;
    /// Some contact slides against friction or cohesion (its shear force a load from its last
    /// normal force, not a spring).
    bool any_sliding_with_strength() const;
    int count(ContactState state) const;

    /// Contact forces f − K·d of the closed contacts at increments d, added to `force`.
    void add_forces(const Eigen::VectorXd& d, Eigen::VectorXd& force) const;
    /// The closed contacts' stiffness into the system's groups first_group + i.
    void add_matrices(SymmetricSystem& system, int first_group) const;

    /// What one open–close update found.
    struct Update {
        int changes = 0;             ///< significant state changes: the iteration must go on
        double friction_used = 0.0;  ///< friction force of contacts sliding before and after
        double friction_change = 0.0;  ///< how much of it the new normal forces changed
        double cycling_force = 0.0;  ///< the largest change of a cycling contact that was let pass
        double largest_force = 0.0;  ///< the largest contact force of the last solve
        /// The friction forces in use agree with the new normal forces (no friction round needed).
        bool friction_agrees() const { return friction_change <= friction_agreement * friction_used; }
    };
    /// Friction forces agree with the normal forces when the normal forces of the last solve
    /// change them by at most this share of the friction in use.
    static constexpr double friction_agreement = 1e-3;
    /// Checks every contact against increments d (update_contact_state). Changes by a force
    /// below a thousandth of the largest contact force are marginal: kept aside (undo_marginal)
    /// while the iteration goes on. A contact that changed more than twice in the try is
    /// cycling: it no longer holds the iteration open. In a static equilibrium analysis
    /// (`equilibrium_only`) a contact cycling between sticking and sliding rests at its strength,
    /// sliding: that state is statically admissible, while one held locked would carry more
    /// shear than friction can (a wedge that must slide would stand on such contacts).
    Update update_states(const Eigen::VectorXd& d, bool equilibrium_only);
    /// Returns the marginal changes of the last update to the states before it. With
    /// `cycling_too` false, the changes of cycling contacts that were let pass stay.
    void undo_marginal(bool cycling_too = true);
    /// Whether update_states(d) would make a significant change, without making it: an
    /// equilibrium iteration need not settle a displacement whose contact states change anyway.
    /// With `friction_too`, also whether the friction forces would not agree with the new normal
    /// forces (Update::friction_agrees): a friction round then follows from d just the same.
    bool would_change(const Eigen::VectorXd& d, bool equilibrium_only, bool friction_too) const;

private:
    Vector6 local(std::size_t i, const Eigen::VectorXd& d) const;
    /// The state change of contact i from `before` to `after` (its `flips`-th significant one in
    /// the try) under the cycling rule of update_states; `after` may be set to sliding.
    StateChange cycling_rule(const Contact& before, Contact& after, StateChange change, int flips,
                             bool equilibrium_only) const;

    std::vector<Contact> contacts_;
    std::vector<ContactKinematics> kinematics_;
    std::vector<ContactProperties> properties_;
    std::vector<int> flips_;  ///< significant changes of each contact in this try
    struct MarginalChange {
        std::size_t index;
        Contact before;
        bool cycling;  ///< a significant change of a cycling contact, let pass
    };
    std::vector<MarginalChange> marginal_;
};

}  // namespace mcdda
