// The contact law at one contact (contact/ContactLaw.hpp): the springs and friction load that
// contact_terms() puts into the system in each state, and the open–close decisions of
// update_contact_state(): penetration closes, tension beyond the tensile strength opens, shear
// beyond Coulomb slides, a slip reversal sticks, and tiny forces are marginal changes.

#include "contact/ContactLaw.hpp"

#include <gtest/gtest.h>

using namespace mcdda;

namespace {

/// A vertex over a horizontal edge: d = (vertex ux, uy, edge start ux, uy, edge end ux, uy);
/// the gap grows with the vertex's uy and shrinks with the edge's, the shear follows ux.
ContactKinematics horizontal(double gap)
{
    ContactKinematics k;
    k.gap = gap;
    k.xi = 0.5;
    k.length = 1.0;
    k.normal << 0, 1, 0, -0.5, 0, -0.5;
    k.shear << 1, 0, -0.5, 0, -0.5, 0;
    return k;
}

ContactProperties properties()
{
    ContactProperties p;
    p.normal_stiffness = 1e9;
    p.shear_stiffness = 4e8;
    p.tan_friction = 0.5;
    p.cohesion_force = 1e3;
    p.tensile_force = 2e3;
    return p;
}

Vector6 vertex_moves(double ux, double uy)
{
    Vector6 d = Vector6::Zero();
    d << ux, uy, 0, 0, 0, 0;
    return d;
}

}  // namespace

TEST(ContactLaw, AnOpenContactAddsNothing) {
    Contact c;
    Matrix6 K;
    Vector6 f;
    contact_terms(c, horizontal(-1e-3), properties(), K, f);  // even when penetrating: open until checked
    EXPECT_EQ(K.norm(), 0.0);
    EXPECT_EQ(f.norm(), 0.0);
}

TEST(ContactLaw, ALockedContactIsANormalAndAShearSpring) {
    Contact c;
    c.state = ContactState::Locked;
    c.shear_spring = 2e-6;
    const ContactKinematics k = horizontal(-1e-6);
    const ContactProperties p = properties();
    Matrix6 K;
    Vector6 f;
    contact_terms(c, k, p, K, f);
    EXPECT_NEAR((K - (p.normal_stiffness * k.normal * k.normal.transpose() +
                      p.shear_stiffness * k.shear * k.shear.transpose())).norm(), 0.0, 1e-6);
    EXPECT_TRUE(K.isApprox(K.transpose()));
    // Solving K d = f for the vertex alone (edge held) removes the penetration and the shear
    // spring's displacement: the springs' energy is least there.
    const Eigen::Matrix2d Kv = K.topLeftCorner<2, 2>();
    const Eigen::Vector2d dv = Kv.ldlt().solve(f.head<2>());
    EXPECT_NEAR(dv.y(), 1e-6, 1e-15);   // the gap closes to 0
    EXPECT_NEAR(dv.x(), -2e-6, 1e-15);  // the committed shear spring relaxes
}

TEST(ContactLaw, ASlidingContactCarriesCoulombFrictionAgainstItsSlip) {
    Contact c;
    c.state = ContactState::Sliding;
    c.slip = +1;
    c.normal_force = 1e4;
    const ContactKinematics k = horizontal(0.0);
    const ContactProperties p = properties();
    Matrix6 K;
    Vector6 f;
    contact_terms(c, k, p, K, f);
    EXPECT_NEAR((K - p.normal_stiffness * k.normal * k.normal.transpose()).norm(), 0.0, 1e-6);  // no shear spring
    const double limit = 1e4 * 0.5 + 1e3;  // N tanφ + c
    EXPECT_NEAR(f[0], -limit, 1e-9);       // on the vertex, against +x slip
    EXPECT_NEAR(f[2] + f[4], limit, 1e-9); // and the reaction on the edge
}

TEST(ContactLaw, PenetrationClosesLockedOrSliding) {
    const ContactProperties p = properties();
    const ContactKinematics k = horizontal(0.0);
    Contact small;
    EXPECT_EQ(update_contact_state(small, k, p, vertex_moves(1e-9, -1e-5), 1.0), StateChange::Significant);
    EXPECT_EQ(small.state, ContactState::Locked);
    EXPECT_NEAR(small.normal_force, 1e4, 1e-6);  // kn × 1e-5
    Contact large;  // shear 4e8 × 1e-4 = 4e4 > 1e4 × 0.5 + 1e3
    update_contact_state(large, k, p, vertex_moves(1e-4, -1e-5), 1.0);
    EXPECT_EQ(large.state, ContactState::Sliding);
    EXPECT_EQ(large.slip, 1);
    EXPECT_NEAR(large.shear_force, 6e3, 1e-6);
    Contact apart;
    EXPECT_EQ(update_contact_state(apart, k, p, vertex_moves(0, 1e-5), 1.0), StateChange::None);
    EXPECT_EQ(apart.state, ContactState::Open);
}

TEST(ContactLaw, TensionBeyondTheTensileStrengthOpens) {
    const ContactProperties p = properties();
    const ContactKinematics k = horizontal(0.0);
    Contact c;
    c.state = ContactState::Locked;
    update_contact_state(c, k, p, vertex_moves(0, 1e-6), 1.0);  // pulled by 1e3 < 2e3: holds
    EXPECT_EQ(c.state, ContactState::Locked);
    EXPECT_EQ(update_contact_state(c, k, p, vertex_moves(0, 3e-6), 1.0), StateChange::Significant);  // 3e3 > 2e3
    EXPECT_EQ(c.state, ContactState::Open);
    EXPECT_EQ(c.normal_force, 0.0);
}

TEST(ContactLaw, ShearBeyondCoulombSlidesAndAReversalSticks) {
    const ContactProperties p = properties();
    const ContactKinematics k = horizontal(-1e-5);  // 1e4 N/m of compression: limit 6e3
    Contact c;
    c.state = ContactState::Locked;
    EXPECT_EQ(update_contact_state(c, k, p, vertex_moves(1e-5, 0), 1.0), StateChange::None);  // 4e3 < 6e3
    EXPECT_EQ(update_contact_state(c, k, p, vertex_moves(-2e-5, 0), 1.0), StateChange::Significant);  // 8e3
    EXPECT_EQ(c.state, ContactState::Sliding);
    EXPECT_EQ(c.slip, -1);
    EXPECT_EQ(update_contact_state(c, k, p, vertex_moves(-1e-6, 0), 1.0), StateChange::None);  // slides on
    EXPECT_NEAR(c.shear_force, -6e3, 1e-6);  // at the Coulomb limit
    update_contact_state(c, k, p, vertex_moves(1e-6, 0), 1.0);  // moving back: sticks
    EXPECT_EQ(c.state, ContactState::Locked);
    EXPECT_EQ(c.shear_spring, 0.0);
}

TEST(ContactLaw, ChangesCarryingAlmostNothingAreMarginal) {
    const ContactProperties p = properties();
    Contact c;  // closes by a penetration of 1e-12 m: 1e-3 N/m, below a 1 N/m tolerance
    EXPECT_EQ(update_contact_state(c, horizontal(0.0), p, vertex_moves(0, -1e-12), 1.0), StateChange::Marginal);
    EXPECT_NE(c.state, ContactState::Open);
}

TEST(ContactLaw, OpeningALockedContactThatHoldsShearIsNoMarginalChange) {
    // A contact pulled open by a hair while its shear spring holds 4e3 N/m: the opening drops
    // that force, so it matters however small the gap (a wedge would otherwise stand on it).
    ContactProperties p = properties();
    p.tensile_force = 0.0;
    Contact c;
    c.state = ContactState::Locked;
    c.shear_spring = 1e-5;  // 4e8 × 1e-5 = 4e3 N/m
    double force = -1.0;
    EXPECT_EQ(update_contact_state(c, horizontal(0.0), p, vertex_moves(0, 1e-12), 10.0, &force),
              StateChange::Significant);
    EXPECT_EQ(c.state, ContactState::Open);
    EXPECT_NEAR(force, 4e3, 1e-6);
    // A change's force is reported: sliding beyond the limit by the excess.
    Contact d;
    d.state = ContactState::Locked;
    update_contact_state(d, horizontal(-1e-5), p, vertex_moves(2e-5, 0), 1.0, &force);  // 8e3 against 6e3
    EXPECT_EQ(d.state, ContactState::Sliding);
    EXPECT_NEAR(force, 2e3, 1e-6);
}

TEST(ContactLaw, CommittingAStepKeepsTheLockedSpringAndLosesStrengthOnceSlid) {
    const ContactKinematics k = horizontal(0.0);
    Contact c;
    c.state = ContactState::Locked;
    commit_contact(c, k, vertex_moves(3e-6, 0));
    EXPECT_NEAR(c.shear_spring, 3e-6, 1e-18);
    EXPECT_TRUE(c.intact);
    c.state = ContactState::Sliding;
    commit_contact(c, k, vertex_moves(1e-6, 0));
    EXPECT_EQ(c.shear_spring, 0.0);
    EXPECT_FALSE(c.intact);
    EXPECT_NEAR(c.slip_total, 4e-6, 1e-18);
}
