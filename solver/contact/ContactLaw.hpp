#pragma once
/// \file ContactLaw.hpp
/// Penalty springs and Coulomb friction of a vertex–edge contact, linearised in the step's
/// displacement increments (Shi 1988), and the open–close check of DDA.

#include "contact/Contact.hpp"
#include "fem/MeshTopology.hpp"
#include "model/Model.hpp"

#include <Eigen/Dense>

#include <vector>

namespace mcdda {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

/// Strength and stiffness acting at one contact (N/m, N per m thickness).
struct ContactProperties {
    double normal_stiffness = 0.0;
    double shear_stiffness = 0.0;
    double tan_friction = 0.0;
    double cohesion_force = 0.0;  ///< cj × contact length
    double tensile_force = 0.0;   ///< tj × contact length
};

/// Geometry of a contact at the start of the step. Degrees of freedom in the order
/// (vertex x, y, edge start x, y, edge end x, y).
struct ContactKinematics {
    int nodes[3] = {-1, -1, -1};
    double gap = 0.0;   ///< dn at the start of the step (m)
    double xi = 0.0;    ///< projection of the vertex on the edge, clamped to [0, 1]
    double length = 0.0;///< joint length the contact stands for: half the vertex's share of its two boundary edges (m)
    /// The vertex's share of its boundary edges relative to an equal split: 1 on three-node
    /// meshes; on six-node meshes 2/3 at a corner and 4/3 at a midside node (the weights
    /// 1/6, 2/3, 1/6 of a quadratic edge). Springs scale with it, so a joint under uniform
    /// pressure loads the elements as that pressure would.
    double share = 1.0;
    Vector6 normal;     ///< dn(d) = gap + normal·d
    Vector6 shear;      ///< relative tangential displacement = shear·d
};

ContactKinematics contact_kinematics(const Contact& c, const std::vector<Point2>& nodes, const MeshTopology& topology);

/// The properties of the joint the contact's edge lies on (or the default joint material).
ContactProperties contact_properties(const Contact& c, const ContactKinematics& k, const Model& model,
                                     const MeshTopology& topology, double penalty);

/// Stiffness and force of the contact in its current state: K·d = f enters the global system.
void contact_terms(const Contact& c, const ContactKinematics& k, const ContactProperties& p, Matrix6& stiffness,
                   Vector6& force);

/// How much a contact's state changed after a solve.
enum class StateChange {
    None,
    Marginal,     ///< changed, but by a negligible force: no new iteration needed
    Significant,  ///< the open–close iteration must go on
};

/// After a solve with increments `d` (the contact's six values): records forces and changes the
/// state where the springs disagree with it (penetration → close, tension → open, shear beyond
/// Coulomb → slide, slip reversal → lock). Opening, closing or sticking whose spring force
/// (stiffness × gap, penetration or slip) is below `force_tolerance` (N/m) is marginal: without
/// this the iteration chatters on contacts that carry almost nothing, whose gaps flip sign at
/// round-off level. Starting to slide is always significant. `change_force`, when given, receives
/// the force (N/m) by which the old state was wrong (0 without a change).
StateChange update_contact_state(Contact& c, const ContactKinematics& k, const ContactProperties& p, const Vector6& d,
                                 double force_tolerance, double* change_force = nullptr);

/// Commits an accepted step: the locked spring's shear displacement is kept, strength lost once
/// the contact opened or slid (UDEC's Coulomb slip joint). `plastic_slip`: a contact that slid
/// keeps its cohesion and tensile strength, only opening loses them — the perfectly plastic joint
/// of limit equilibrium that a strength reduction compares with (with brittle joints its factor
/// would depend on how many steps the held load is solved in: each step unzips a little more).
void commit_contact(Contact& c, const ContactKinematics& k, const Vector6& d, bool plastic_slip = false);

}  // namespace mcdda
