// Supports and loads on the mesh (fem/BoundaryConditions.hpp): a roller fixes exactly the nodes
// along it in its directions; gravity and an edge pressure give nodal forces that add up to the
// weight and to pressure × length, on three- and six-node meshes alike.

#include "TestModels.hpp"
#include "fem/BoundaryConditions.hpp"
#include "fem/MeshTopology.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::preprocess_text;
using mcdda::test::square_model_json;

namespace {

void check_supports_and_loads(const std::string& element)
{
    // The 10 m square of 2500 kg/m³ on a roller along its base fixed in y only, under g and a
    // 50 kPa pressure on its top edge.
    const Preprocessed p = preprocess_text(
        square_model_json(),
        {"/rollers/0/fixed=\"y\"", R"(/rollers/-={"name": "side", "from": [0, 0], "to": [0, 10], "fixed": "x"})",
         "/gravity=[0, -9.81]", R"(/edge_pressures=[{"name": "top", "from": [0, 10], "to": [10, 10], "pressure": 5e4}])",
         "/mesh/element=\"" + element + "\""});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    const MeshTopology topology = build_topology(p.mesh, p.blocks);
    std::vector<Diagnostic> problems;
    const BoundaryConditions bc = locate_boundary_conditions(p.model, p.mesh, topology, problems);
    EXPECT_TRUE(problems.empty()) << all_messages(problems);
    int fixed = 0;
    for (std::size_t n = 0; n < p.mesh.nodes.size(); ++n) {
        const Point2& q = p.mesh.nodes[n];
        EXPECT_EQ(bc.fixed(static_cast<int>(n), 1), q.y == 0.0) << "node " << n << " at (" << q.x << ", " << q.y << ")";
        EXPECT_EQ(bc.fixed(static_cast<int>(n), 0), q.x == 0.0) << "node " << n;
        fixed += (q.y == 0.0) + (q.x == 0.0);
    }
    EXPECT_EQ(bc.equation_count, static_cast<int>(2 * p.mesh.nodes.size()) - fixed);
    const Eigen::VectorXd f = external_forces(p.model, p.mesh, p.mesh.nodes, topology, bc, 1.0, 1.0);
    double fx = 0.0, fy = 0.0;
    for (std::size_t n = 0; n < p.mesh.nodes.size(); ++n) {
        fx += f[static_cast<Eigen::Index>(2 * n)];
        fy += f[static_cast<Eigen::Index>(2 * n + 1)];
    }
    // Weight ρ g A plus p L, both downwards.
    EXPECT_NEAR(fx, 0.0, 1e-6);
    EXPECT_NEAR(fy, -(2500.0 * 9.81 * 100.0 + 5e4 * 10.0), 1e-6 * 7.5e5);
}

}  // namespace

TEST(BoundaryConditions, RollersFixTheirNodesAndLoadsAddUp) { check_supports_and_loads("t3"); }

TEST(BoundaryConditions, SixNodeMeshesToo) { check_supports_and_loads("t6"); }
