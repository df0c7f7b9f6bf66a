#pragma once
/// \file Contact.hpp
/// A DDA vertex–edge contact between two blocks and its state (Shi 1988): a boundary node of
/// one block against a boundary edge of another, with a normal and a shear penalty spring.

namespace mcdda {

enum class ContactState { Open, Sliding, Locked };

struct Contact {
    int node = -1;       ///< the vertex (a boundary node)
    int edge = -1;       ///< index into MeshTopology::edges (another block's boundary)
    int edge_block = -1; ///< block of the edge (a vertex keeps one contact per neighbouring block)
    ContactState state = ContactState::Open;
    int slip = 0;            ///< sliding direction along the edge, +1 or −1
    bool intact = true;      ///< cohesion and tensile strength still act (lost once opened or slid)
    double shear_spring = 0.0;  ///< committed elastic shear displacement of a locked contact (m)
    double slip_total = 0.0;    ///< relative shear displacement along the edge while closed, summed (m)
    /// The gap (≥ 0) when the contact was first found. An open contact's opening counts from it:
    /// a vertex at a joint junction may face another block's edge across a gap of the geometry
    /// (a corner, the model's edge), which is not the joint opening.
    double gap_found = 0.0;

    // Results of the last solve, for output and the next open–close check.
    double gap = 0.0;           ///< dn after the increment: > 0 open, < 0 penetration (m)
    double normal_force = 0.0;  ///< compression positive (N/m)
    double shear_force = 0.0;   ///< along the edge direction (N/m)
};

}  // namespace mcdda
