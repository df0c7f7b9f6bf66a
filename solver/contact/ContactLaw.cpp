#include "contact/ContactLaw.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

ContactKinematics contact_kinematics(const Contact& c, const std::vector<Point2>& nodes, const MeshTopology& topology) {
    ContactKinematics k;
    const BoundaryEdge& e = topology.edges[c.edge];
    k.nodes[0] = c.node;
    k.nodes[1] = e.from;
    k.nodes[2] = e.to;
    const Point2 p = nodes[c.node], a = nodes[e.from], b = nodes[e.to];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double l = std::hypot(dx, dy);
    const double tx = dx / l, ty = dy / l;
    k.gap = ((p.x - a.x) * dy - (p.y - a.y) * dx) / l;
    k.xi = std::clamp(((p.x - a.x) * tx + (p.y - a.y) * ty) / l, 0.0, 1.0);
    // dn = ((P − A) × (B − A)) / l with l held constant over the step (Shi).
    k.normal << dy / l, -dx / l, (p.y - b.y) / l, (b.x - p.x) / l, (a.y - p.y) / l, (p.x - a.x) / l;
    k.shear << tx, ty, -(1.0 - k.xi) * tx, -(1.0 - k.xi) * ty, -k.xi * tx, -k.xi * ty;
    double length = 0.0, equal = 0.0, along = 0.0;
    for (int edge : {topology.edge_into[c.node], topology.edge_out_of[c.node]})
        if (edge >= 0) {
            const BoundaryEdge& n = topology.edges[edge];
            const double ex = nodes[n.to].x - nodes[n.from].x, ey = nodes[n.to].y - nodes[n.from].y;
            const double h = std::hypot(ex, ey);
            equal += 0.5 * h;
            // A half-edge of a six-node edge gives h/3 to its corner end and 2h/3 to its midside
            // end; an edge of a three-node mesh h/2 to each.
            const int other = n.from == c.node ? n.to : n.from;
            const double part = topology.midside_node[c.node] ? 2.0 * h / 3.0 : topology.midside_node[other] ? h / 3.0 : 0.5 * h;
            length += part;
            // Strength acts over the faces in contact: at the end of a joint (where it meets the
            // slope face or a tension crack) the vertex's other edge turns away from the edge it
            // touches and bonds nothing. Within 20° of it counts (a polyline joint's kinks).
            if (h > 0.0 && std::fabs(ex * ty - ey * tx) <= 0.34 * h) along += part;
        }
    k.share = equal > 0.0 ? length / equal : 1.0;
    // Two blocks meeting along a joint contact each other twice (the vertices of each against the
    // edges of the other), so each contact stands for half its vertex's share of the joint:
    // cohesion and tensile strength are then counted once over the joint's length.
    k.length = 0.5 * along;
    return k;
}

ContactProperties contact_properties(const Contact& c, const ContactKinematics& k, const Model& model,
                                     const MeshTopology& topology, double penalty) {
    const int joint = topology.edges[c.edge].joint;
    int material = joint >= 0 ? model.joints[joint].joint_material : -1;
    if (material < 0) material = model.default_joint_material;
    ContactProperties p;
    const JointMaterial* jm = material >= 0 ? &model.joint_materials[material] : nullptr;
    p.normal_stiffness = jm && jm->normal_stiffness > 0.0 ? jm->normal_stiffness : penalty;
    // Without a given value, ks follows kn as an elastic interface with ν ≈ 0.25 would: kn/2.5.
    p.shear_stiffness = jm && jm->shear_stiffness > 0.0 ? jm->shear_stiffness : p.normal_stiffness / 2.5;
    p.normal_stiffness *= k.share;
    p.shear_stiffness *= k.share;
    if (jm) {
        p.tan_friction = std::tan(jm->friction_angle);
        if (c.intact) {
            p.cohesion_force = jm->cohesion * k.length;
            p.tensile_force = jm->tensile_strength * k.length;
        }
    }
    return p;
}

void contact_terms(const Contact& c, const ContactKinematics& k, const ContactProperties& p, Matrix6& stiffness,
                   Vector6& force) {
    stiffness.setZero();
    force.setZero();
    if (c.state == ContactState::Open) return;
    // Normal spring: energy ½ kn (gap + n·d)².
    stiffness += p.normal_stiffness * k.normal * k.normal.transpose();
    force -= p.normal_stiffness * k.gap * k.normal;
    if (c.state == ContactState::Locked) {
        // Shear spring from the committed shear displacement.
        stiffness += p.shear_stiffness * k.shear * k.shear.transpose();
        force -= p.shear_stiffness * c.shear_spring * k.shear;
    } else {
        // Sliding: Coulomb friction as a load opposing the slip, from the last normal force.
        const double limit = std::max(0.0, c.normal_force) * p.tan_friction + p.cohesion_force;
        force -= c.slip * limit * k.shear;
    }
}

StateChange update_contact_state(Contact& c, const ContactKinematics& k, const ContactProperties& p, const Vector6& d,
                                 double force_tolerance, double* change_force) {
    c.gap = k.gap + k.normal.dot(d);
    const double slip_increment = k.shear.dot(d);
    // The force by which the old state was wrong decides whether the change matters.
    auto change = [&](double force) {
        if (change_force) *change_force = force;
        return force < force_tolerance ? StateChange::Marginal : StateChange::Significant;
    };
    if (change_force) *change_force = 0.0;
    if (c.state == ContactState::Open) {
        c.normal_force = 0.0;
        c.shear_force = 0.0;
        if (c.gap >= 0.0) return StateChange::None;
        // Closing: locked unless the slip over the step already beats friction (a node that a
        // sliding block runs onto closes sliding).
        c.shear_spring = 0.0;
        c.normal_force = -p.normal_stiffness * c.gap;
        const double limit = c.normal_force * p.tan_friction + p.cohesion_force;
        c.shear_force = p.shear_stiffness * slip_increment;
        // A contact without any shear strength (smooth: no friction, no cohesion) cannot stick.
        if (std::fabs(c.shear_force) > limit || limit <= 0.0) {
            c.state = ContactState::Sliding;
            c.slip = slip_increment > 0.0 ? 1 : -1;
            c.shear_force = c.slip * limit;
        } else {
            c.state = ContactState::Locked;
        }
        return change(-c.gap * p.normal_stiffness);
    }
    c.normal_force = -p.normal_stiffness * c.gap;
    if (c.normal_force < -p.tensile_force) {  // pulled apart beyond the tensile strength
        // Opening also drops the shear force the contact carried: a locked contact that holds a
        // block against sliding is no negligible change however small its gap.
        const double shear_carried = c.state == ContactState::Locked
                                         ? std::fabs(p.shear_stiffness * (c.shear_spring + slip_increment))
                                         : p.cohesion_force;
        c.state = ContactState::Open;
        c.normal_force = c.shear_force = 0.0;
        return change(std::max(c.gap * p.normal_stiffness, shear_carried));
    }
    const double limit = std::max(0.0, c.normal_force) * p.tan_friction + p.cohesion_force;
    if (c.state == ContactState::Locked) {
        c.shear_force = p.shear_stiffness * (c.shear_spring + slip_increment);
        if (std::fabs(c.shear_force) <= limit) return StateChange::None;
        c.state = ContactState::Sliding;
        c.slip = c.shear_force > 0.0 ? 1 : -1;
        // Judged by force, not displacement: the stiff shear spring turns any excess into a tiny
        // displacement, yet the solution with it locked is wrong by the whole excess force.
        if (change_force) *change_force = std::fabs(c.shear_force) - limit;
        return StateChange::Significant;
    }
    c.shear_force = c.slip * limit;
    if (slip_increment * c.slip >= 0.0) return StateChange::None;
    if (limit <= 0.0) {  // smooth: the direction of slip carries no force, nothing to stick
        c.slip = -c.slip;
        return StateChange::None;
    }
    // The slip reversed: the contact sticks.
    c.state = ContactState::Locked;
    c.shear_spring = 0.0;
    return change(std::fabs(slip_increment) * p.shear_stiffness);
}

void commit_contact(Contact& c, const ContactKinematics& k, const Vector6& d, bool plastic_slip) {
    if (c.state != ContactState::Open) c.slip_total += k.shear.dot(d);
    if (c.state == ContactState::Locked) c.shear_spring += k.shear.dot(d);
    else c.shear_spring = 0.0;
    if (c.state == ContactState::Open || (c.state == ContactState::Sliding && !plastic_slip)) c.intact = false;
}

}  // namespace mcdda
