// Cracks inside blocks: the mesh conforms to a joint that ends in the rock, its nodes are doubled
// except at its tips, the faces are boundary edges tagged with the joint, and the contact search
// pairs each face with the other.

#include "TestModels.hpp"
#include "contact/ContactDetection.hpp"
#include "fem/MeshTopology.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::preprocess_text;
using mcdda::test::square_model_json;

namespace {

Preprocessed mesh_with(const std::string& joints, const std::string& element = "t3") {
    return preprocess_text(square_model_json(), {"/joints=" + joints, "/mesh/element=\"" + element + "\""});
}

/// How many nodes sit at each point of the mesh (rounded to a nanometre).
std::map<std::pair<long long, long long>, int> nodes_at(const Mesh& mesh) {
    std::map<std::pair<long long, long long>, int> count;
    for (const Point2& p : mesh.nodes) ++count[{std::llround(p.x * 1e9), std::llround(p.y * 1e9)}];
    return count;
}

int count_at(const Mesh& mesh, Point2 p) {
    const auto all = nodes_at(mesh);
    const auto it = all.find({std::llround(p.x * 1e9), std::llround(p.y * 1e9)});
    return it == all.end() ? 0 : it->second;
}

}  // namespace

TEST(CrackMesh, AFloatingCrackDoublesItsNodesButNotItsTips) {
    const Preprocessed p = mesh_with(R"([{"name": "crack", "points": [[3,5],[7,5]], "joint_material": "joint"}])");
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    ASSERT_EQ(p.mesh.block_count(), 1);
    EXPECT_EQ(count_at(p.mesh, {3, 5}), 1);  // tips
    EXPECT_EQ(count_at(p.mesh, {7, 5}), 1);
    int doubled = 0, single = 0;
    for (const auto& [where, n] : nodes_at(p.mesh)) {
        const double x = where.first * 1e-9, y = where.second * 1e-9;
        if (std::fabs(y - 5.0) < 1e-9 && x > 3.0 + 1e-9 && x < 7.0 - 1e-9) (n == 2 ? doubled : single)++;
        else EXPECT_EQ(n, 1) << "at (" << x << ", " << y << ")";
    }
    EXPECT_GE(doubled, 9) << "the mesh refines towards the tips (a tenth of the crack there)";
    EXPECT_EQ(single, 0);
    // The faces are boundary edges of the block, tagged with the joint, each node on two of them.
    const MeshTopology t = build_topology(p.mesh, p.blocks);
    double face_length = 0.0;
    for (const BoundaryEdge& e : t.edges)
        if (e.crack) {
            EXPECT_EQ(e.joint, 0);
            face_length += std::hypot(p.mesh.nodes[e.to].x - p.mesh.nodes[e.from].x, p.mesh.nodes[e.to].y - p.mesh.nodes[e.from].y);
        }
    EXPECT_NEAR(face_length, 8.0, 1e-9);  // both faces of the 4 m crack
    // At a tip the two faces meet in one node: the face edge into it and the one out of it are
    // both crack faces, and they start on the two faces' own nodes at the same place.
    for (const Point2 tip : {Point2{3, 5}, Point2{7, 5}}) {
        const int node = nearest_node(p.mesh, tip);
        ASSERT_GE(t.edge_into[node], 0);
        ASSERT_GE(t.edge_out_of[node], 0);
        const BoundaryEdge& in = t.edges[t.edge_into[node]];
        const BoundaryEdge& out = t.edges[t.edge_out_of[node]];
        EXPECT_TRUE(in.crack && out.crack);
        EXPECT_NE(in.from, out.to);
        EXPECT_NEAR(p.mesh.nodes[in.from].x, p.mesh.nodes[out.to].x, 1e-12);
        EXPECT_NEAR(p.mesh.nodes[in.from].y, p.mesh.nodes[out.to].y, 1e-12);
    }
}

TEST(CrackMesh, ACrackFromTheOutlineOpensAtItsMouthAndTwoCrossingCracksMakeFourCorners) {
    const Preprocessed p = mesh_with(R"([{"name": "edge crack", "points": [[-1,5],[4,5]], "joint_material": "joint"},
                                         {"name": "a", "points": [[5,6],[9,6]]}, {"name": "b", "points": [[7,4],[7,8]]}])");
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_EQ(count_at(p.mesh, {0, 5}), 2);  // the mouth on the outline
    EXPECT_EQ(count_at(p.mesh, {4, 5}), 1);  // its tip
    EXPECT_EQ(count_at(p.mesh, {7, 6}), 4);  // the crossing
    for (const Point2 tip : {Point2{5, 6}, Point2{9, 6}, Point2{7, 4}, Point2{7, 8}}) EXPECT_EQ(count_at(p.mesh, tip), 1);
}

TEST(CrackMesh, SixNodeTrianglesGiveEachFaceItsOwnMidsideNodes) {
    const Preprocessed p = mesh_with(R"([{"name": "crack", "points": [[3,5],[7,5]]}])", "t6");
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    ASSERT_TRUE(p.mesh.quadratic());
    const MeshTopology t = build_topology(p.mesh, p.blocks);
    int midside_on_faces = 0;
    for (const BoundaryEdge& e : t.edges)
        if (e.crack && t.midside_node[e.to]) ++midside_on_faces;
    // Every midside node of a face lies on the crack and has its twin on the other face.
    EXPECT_GT(midside_on_faces, 0);
    for (int node = 0; node < static_cast<int>(p.mesh.nodes.size()); ++node)
        if (t.midside_node[node] && std::fabs(p.mesh.nodes[node].y - 5.0) < 1e-9 && p.mesh.nodes[node].x > 3 &&
            p.mesh.nodes[node].x < 7)
            EXPECT_EQ(count_at(p.mesh, p.mesh.nodes[node]), 2);
}

TEST(CrackMesh, EachFaceNodeFindsTheOtherFaceAndNothingElseOfItsBlock) {
    const Preprocessed p = mesh_with(R"([{"name": "crack", "points": [[3,5],[7,5]], "joint_material": "joint"}])");
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    const MeshTopology t = build_topology(p.mesh, p.blocks);
    const std::vector<Contact> contacts = detect_contacts(p.mesh.nodes, p.mesh, t, 0.05, {}, Eigen::VectorXd(), 0.0);
    int face_nodes = 0;
    for (int node : t.boundary_nodes)
        if (std::fabs(p.mesh.nodes[node].y - 5.0) < 1e-9 && p.mesh.nodes[node].x > 3 + 1e-9 &&
            p.mesh.nodes[node].x < 7 - 1e-9)
            ++face_nodes;
    ASSERT_GT(face_nodes, 0);
    EXPECT_EQ(static_cast<int>(contacts.size()), face_nodes);  // one per face node; none at the tips
    for (const Contact& c : contacts) {
        const BoundaryEdge& e = t.edges[c.edge];
        EXPECT_TRUE(e.crack);
        EXPECT_EQ(c.edge_block, 0);
        EXPECT_EQ(c.state, ContactState::Locked);  // touching: starts locked (and intact)
        // The edge is on the other face: the node is none of its ends, and the node's own face
        // runs the opposite way (each face has its side of the block on its left).
        EXPECT_NE(e.from, c.node);
        EXPECT_NE(e.to, c.node);
        const BoundaryEdge& own = t.edges[t.edge_out_of[c.node]];
        const double along = (p.mesh.nodes[own.to].x - p.mesh.nodes[own.from].x) * (p.mesh.nodes[e.to].x - p.mesh.nodes[e.from].x);
        EXPECT_LT(along, 0.0);
    }
}
