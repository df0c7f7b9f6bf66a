// The contacts of one try (contact/ContactSet.hpp) on two blocks: a 10 m square cut by a
// horizontal joint at y = 5. Detection finds the joint's contacts touching; pressing the upper
// block down gives contact forces that push it back up and balance; pulling it away opens them.

#include "TestModels.hpp"
#include "contact/ContactDetection.hpp"
#include "contact/ContactSet.hpp"
#include "fem/MeshTopology.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

struct TwoBlocks {
    Preprocessed p;
    MeshTopology topology;
    std::vector<Contact> contacts;
};

TwoBlocks two_blocks() {
    TwoBlocks t;
    t.p = test::preprocess_text(test::square_model_json(), {"/joints=[{\"name\": \"j\", \"points\": [[0,5],[10,5]]}]"});
    EXPECT_TRUE(t.p.ok) << test::all_messages(t.p.diagnostics);
    t.topology = build_topology(t.p.mesh, t.p.blocks);
    t.contacts = detect_contacts(t.p.mesh.nodes, t.p.mesh, t.topology, 0.05, {}, Eigen::VectorXd(), 1e-9);
    return t;
}

/// Increments moving every node of the upper block (joint nodes included) by (ux, uy).
Eigen::VectorXd upper_block_moves(const TwoBlocks& t, double ux, double uy) {
    const Mesh& mesh = t.p.mesh;
    int upper = -1;
    for (std::size_t n = 0; n < mesh.nodes.size() && upper < 0; ++n)
        if (mesh.nodes[n].y > 5.5) upper = mesh.node_block[n];
    Eigen::VectorXd d = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(mesh.nodes.size()));
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
        if (mesh.node_block[n] == upper) {
            d[2 * n] = ux;
            d[2 * n + 1] = uy;
        }
    return d;
}

ContactSet contact_set_of(const TwoBlocks& t) {
    return ContactSet(t.contacts, [&](const Contact& c) { return contact_kinematics(c, t.p.mesh.nodes, t.topology); },
                      t.p.model, t.topology, 4e9);
}

}  // namespace

TEST(ContactSet, TheJointsContactsStartClosedAndCarryNothing) {
    const TwoBlocks t = two_blocks();
    ASSERT_EQ(t.p.blocks.size(), 2u);
    ASSERT_GE(t.contacts.size(), 10u);  // every joint vertex of either block against the other
    const ContactSet set = contact_set_of(t);
    EXPECT_TRUE(set.any_closed());
    EXPECT_EQ(set.count(ContactState::Open), 0);
    Eigen::VectorXd force = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(t.p.mesh.nodes.size()));
    set.add_forces(upper_block_moves(t, 0.0, 0.0), force);
    EXPECT_LT(force.cwiseAbs().maxCoeff(), 1e-6);
}

TEST(ContactSet, PressingTheBlocksTogetherPushesThemApartInBalance) {
    const TwoBlocks t = two_blocks();
    const ContactSet set = contact_set_of(t);
    const Eigen::VectorXd d = upper_block_moves(t, 0.0, -1e-4);
    Eigen::VectorXd force = Eigen::VectorXd::Zero(d.size());
    set.add_forces(d, force);
    double up = 0.0, down = 0.0, sum_x = 0.0, sum_y = 0.0;
    for (Eigen::Index n = 0; 2 * n < d.size(); ++n) {
        sum_x += force[2 * n];
        sum_y += force[2 * n + 1];
        if (d[2 * n + 1] < 0.0) up += force[2 * n + 1];  // on the pressed (upper) block
        else down += force[2 * n + 1];
    }
    EXPECT_GT(up, 0.0);
    EXPECT_LT(down, 0.0);
    EXPECT_NEAR(sum_y, 0.0, 1e-9 * up);  // action and reaction
    EXPECT_NEAR(sum_x, 0.0, 1e-9 * up);
    // Penalty springs: about 4e9 N/m × 1e-4 m per contact.
    EXPECT_NEAR(up / set.count(ContactState::Locked), 4e5, 2e5);
}

TEST(ContactSet, PullingTheBlocksApartOpensEveryContactAndUndoKeepsNothingMarginal) {
    const TwoBlocks t = two_blocks();
    ContactSet set = contact_set_of(t);
    const ContactSet::Update u = set.update_states(upper_block_moves(t, 0.0, 1e-2), false);
    EXPECT_EQ(u.changes, static_cast<int>(t.contacts.size()));
    EXPECT_EQ(set.count(ContactState::Open), static_cast<int>(t.contacts.size()));
    EXPECT_FALSE(set.any_closed());
    set.undo_marginal();  // the changes were significant: nothing to undo
    EXPECT_EQ(set.count(ContactState::Open), static_cast<int>(t.contacts.size()));
    Eigen::VectorXd force = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(t.p.mesh.nodes.size()));
    set.add_forces(upper_block_moves(t, 0.0, -1e-4), force);
    EXPECT_EQ(force.cwiseAbs().maxCoeff(), 0.0);  // open contacts add nothing
}

TEST(ContactSet, WouldChangeForeseesTheUpdateWithoutMakingIt) {
    const TwoBlocks t = two_blocks();
    ContactSet set = contact_set_of(t);
    // Pressed together a little: every contact stays closed, nothing to change.
    const Eigen::VectorXd pressed = upper_block_moves(t, 0.0, -1e-6);
    EXPECT_FALSE(set.would_change(pressed, false, false));
    EXPECT_EQ(set.update_states(pressed, false).changes, 0);
    // Pulled apart: they would all open, and asking leaves them closed.
    const Eigen::VectorXd pulled = upper_block_moves(t, 0.0, 1e-2);
    EXPECT_TRUE(set.would_change(pulled, false, false));
    EXPECT_TRUE(set.would_change(pulled, true, false));
    EXPECT_EQ(set.count(ContactState::Open), 0);
    EXPECT_GT(set.update_states(pulled, false).changes, 0);
    EXPECT_EQ(set.count(ContactState::Open), static_cast<int>(t.contacts.size()));
    // Open and still apart: no change foreseen, none made.
    EXPECT_FALSE(set.would_change(pulled, false, true));
    EXPECT_EQ(set.update_states(pulled, false).changes, 0);
}

TEST(ContactSet, WouldChangeForeseesAFrictionRoundOnlyWhenAskedTo) {
    const TwoBlocks t = two_blocks();
    ContactSet set = contact_set_of(t);
    // Pressed and sheared far beyond the joint's 30° of friction: the contacts slide, with friction
    // forces from the normal forces of this solve.
    const ContactSet::Update slid = set.update_states(upper_block_moves(t, 1e-2, -1e-4), false);
    ASSERT_GT(slid.changes, 0);
    const int sliding = set.count(ContactState::Sliding);
    ASSERT_GT(sliding, 0);
    // Pressed twice as hard, still sliding: no state changes, but the friction in use is half
    // what the new normal forces call for, so a friction round would follow.
    const Eigen::VectorXd harder = upper_block_moves(t, 1e-2, -2e-4);
    EXPECT_FALSE(set.would_change(harder, false, false));
    EXPECT_TRUE(set.would_change(harder, false, true));
    const ContactSet::Update round = set.update_states(harder, false);
    EXPECT_EQ(round.changes, 0);
    EXPECT_EQ(set.count(ContactState::Sliding), sliding);
    EXPECT_GT(round.friction_used, 0.0);
    EXPECT_FALSE(round.friction_agrees());
    // The same increments again: the friction now agrees, and nothing is foreseen.
    EXPECT_FALSE(set.would_change(harder, false, true));
    EXPECT_TRUE(set.update_states(harder, false).friction_agrees());
}
