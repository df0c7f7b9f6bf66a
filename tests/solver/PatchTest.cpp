// Patch tests of both element types (three-node and six-node triangles): a patch of distorted
// elements given the displacements of a uniform strain field has that strain's stress D·ε at
// every integration point and no out-of-balance force at its interior nodes. An element that
// passes converges to the exact solution as the mesh is refined; one that fails does not.

#include "TestModels.hpp"
#include "fem/ElementAssembly.hpp"
#include "fem/PlaneStrain.hpp"
#include "mesh/QuadraticMesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

/// A 2 m square cut into four triangles around an interior node off the centre.
Mesh patch(bool quadratic)
{
    Mesh m;
    m.nodes = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {0.7, 1.3}};
    m.node_block = {0, 0, 0, 0, 0};
    m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    m.triangle_block = {0, 0, 0, 0};
    m.triangle_material = {0, 0, 0, 0};
    m.block_node_begin = {0, 5};
    m.block_triangle_begin = {0, 4};
    if (quadratic) add_midside_nodes(m);
    return m;
}

void check_patch(bool quadratic)
{
    const Model model = test::elastic_model();
    const Mesh mesh = patch(quadratic);
    ASSERT_EQ(mesh.quadratic(), quadratic);
    ElementAssembly assembly(model, mesh);
    assembly.prepare(mesh.nodes, 0.0);
    // u = 1e-4 x + 2e-4 y, v = -3e-4 x + 5e-4 y: εxx = 1e-4, εyy = 5e-4, γxy = -1e-4.
    Eigen::VectorXd d(2 * mesh.nodes.size());
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        const Point2& p = mesh.nodes[i];
        d[2 * i] = 1e-4 * p.x + 2e-4 * p.y;
        d[2 * i + 1] = -3e-4 * p.x + 5e-4 * p.y;
    }
    const Vector3 strain(1e-4, 5e-4, -1e-4);
    const Vector3 exact = plane_strain_elasticity(2e9, 0.3) * strain;
    PointStates old;
    old.resize(static_cast<std::size_t>(assembly.element_count() * assembly.points_per_element()));
    std::vector<ReturnResult> returned;
    Eigen::VectorXd internal;
    const auto evaluation = assembly.evaluate(d, old, returned, internal, ElementMatrix::None, nullptr);
    ASSERT_EQ(returned.size(), old.stress.size());
    const double scale = exact.cwiseAbs().maxCoeff();
    for (const ReturnResult& r : returned) {
        EXPECT_NEAR(r.stress.xx, exact[0], 1e-9 * scale);
        EXPECT_NEAR(r.stress.yy, exact[1], 1e-9 * scale);
        EXPECT_NEAR(r.stress.xy, exact[2], 1e-9 * scale);
        EXPECT_NEAR(r.stress.zz, 0.3 * (exact[0] + exact[1]), 1e-9 * scale);  // plane strain
    }
    int interior = 0;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        const Point2& p = mesh.nodes[i];
        if (p.x <= 0.0 || p.x >= 2.0 || p.y <= 0.0 || p.y >= 2.0) continue;  // on the patch's boundary
        ++interior;
        EXPECT_NEAR(internal[2 * i], 0.0, 1e-9 * evaluation.force_scale) << "node " << i;
        EXPECT_NEAR(internal[2 * i + 1], 0.0, 1e-9 * evaluation.force_scale) << "node " << i;
    }
    EXPECT_EQ(interior, quadratic ? 5 : 1);  // the interior node, and the midsides of its four edges
    EXPECT_GT(evaluation.force_scale, 0.0);
}

}  // namespace

TEST(PatchTest, ThreeNodeTrianglesRepresentUniformStrainExactly) { check_patch(false); }

TEST(PatchTest, SixNodeTrianglesRepresentUniformStrainExactly) { check_patch(true); }
