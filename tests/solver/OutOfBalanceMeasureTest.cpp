// The lengths ElementAssembly gives nodal forces (dof_length), by which the equilibrium
// iterations of a pure equilibrium problem measure out-of-balance forces as stresses: they tile
// the area, and a uniform stress reads the same on a mesh twice as fine, where nodal forces and
// the largest of them halve.

#include "TestModels.hpp"
#include "fem/ElementAssembly.hpp"
#include "mesh/QuadraticMesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

/// A 4 m square of n × n cells, each cut into two triangles.
Mesh grid(int n, bool quadratic) {
    Mesh m;
    const double h = 4.0 / n;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.nodes.push_back({i * h, j * h});
    const auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    m.node_block.assign(m.nodes.size(), 0);
    m.triangle_block.assign(m.triangles.size(), 0);
    m.triangle_material.assign(m.triangles.size(), 0);
    m.block_node_begin = {0, static_cast<int>(m.nodes.size())};
    m.block_triangle_begin = {0, static_cast<int>(m.triangles.size())};
    if (quadratic) add_midside_nodes(m);
    return m;
}

/// The largest nodal force and the stress scale of a uniform strain on grid(n).
ElementAssembly::Evaluation uniform_strain(const Model& model, int n, bool quadratic, double* area = nullptr) {
    const Mesh mesh = grid(n, quadratic);
    ElementAssembly assembly(model, mesh);
    assembly.prepare(mesh.nodes, 0.0);
    Eigen::VectorXd d(2 * mesh.nodes.size());
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        d[2 * i] = 1e-4 * mesh.nodes[i].x + 2e-4 * mesh.nodes[i].y;
        d[2 * i + 1] = -3e-4 * mesh.nodes[i].x + 5e-4 * mesh.nodes[i].y;
    }
    PointStates old;
    old.resize(static_cast<std::size_t>(assembly.element_count() * assembly.points_per_element()));
    std::vector<ReturnResult> returned;
    Eigen::VectorXd internal;
    if (area) *area = assembly.dof_length().squaredNorm() / 2.0;  // each node's length appears twice
    return assembly.evaluate(d, old, returned, internal, ElementMatrix::None, nullptr);
}

void check(bool quadratic) {
    const Model model = test::elastic_model();
    double area = 0.0;
    const ElementAssembly::Evaluation coarse = uniform_strain(model, 4, quadratic, &area);
    const ElementAssembly::Evaluation fine = uniform_strain(model, 8, quadratic);
    EXPECT_NEAR(area, 16.0, 1e-12);  // the nodes' shares tile the square
    EXPECT_NEAR(fine.force_scale, 0.5 * coarse.force_scale, 1e-9 * coarse.force_scale);
    EXPECT_NEAR(fine.stress_scale, coarse.stress_scale, 1e-9 * coarse.stress_scale);
    // A stress of the order of the strain's (D ε ≈ 1.5 MPa), not a force.
    EXPECT_GT(coarse.stress_scale, 0.3e6);
    EXPECT_LT(coarse.stress_scale, 30e6);
}

}  // namespace

TEST(OutOfBalanceMeasure, ThreeNodeStressScaleIsTheSameOnAFinerMesh) { check(false); }
TEST(OutOfBalanceMeasure, SixNodeStressScaleIsTheSameOnAFinerMesh) { check(true); }
