// Six-node triangles: midside nodes shared within a block and never across blocks, block node
// ranges kept contiguous, boundary half-edges in the topology and quadratic cells in VTU files.

#include "TestModels.hpp"
#include "fem/MeshTopology.hpp"
#include "io/VtuWriter.hpp"
#include "mesh/BlockMesher.hpp"
#include "mesh/MeshStatistics.hpp"
#include "mesh/QuadraticMesh.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::preprocess_text;
using mcdda::test::square_model_json;
namespace fs = std::filesystem;

namespace {

using Edge = std::pair<int, int>;
Edge key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// The square model's blocks meshed with three-node triangles by the project's mesher, whatever
/// element the model would choose: the tests add the midside nodes themselves.
Preprocessed linear_mesh(const std::vector<std::string>& overrides) {
    Preprocessed p = preprocess_text(square_model_json(), overrides, PreprocessStage::Cut);
    if (!p.ok) return p;
    p.mesh = mesh_blocks(p.model, p.blocks, p.diagnostics);
    p.statistics = compute_statistics(p.mesh, p.blocks);
    p.ok = !p.mesh.triangles.empty() && !p.mesh.quadratic();
    return p;
}

/// A square cut in two by a horizontal joint.
Preprocessed two_blocks() { return linear_mesh({"/joints=[{\"points\": [[0,5],[10,5]]}]", "/mesh/size=1.5"}); }

/// A square with a round hole, cut below the hole by a joint: one of the two blocks has a hole.
Preprocessed block_with_hole() {
    return linear_mesh({"/regions/0/holes=[{\"circle\": {\"center\": [5,5], \"radius\": 2, \"segments\": 24}}]",
                        "/joints=[{\"points\": [[0,1.5],[10,1.5]]}]", "/mesh/size=1.2"});
}

/// Where corner node i of the linear mesh went in the quadratic one.
int moved(const Mesh& linear, const Mesh& quadratic, int i) {
    const int b = linear.node_block[i];
    return i + quadratic.block_node_begin[b] - linear.block_node_begin[b];
}

void expect_valid_quadratic(const Mesh& linear, const Mesh& q) {
    ASSERT_TRUE(q.quadratic());
    ASSERT_EQ(q.midside.size(), q.triangles.size());
    ASSERT_EQ(q.block_count(), linear.block_count());
    EXPECT_EQ(q.triangle_block, linear.triangle_block);
    EXPECT_EQ(q.triangle_material, linear.triangle_material);
    EXPECT_EQ(q.block_triangle_begin, linear.block_triangle_begin);

    // One new node per distinct edge of a block (blocks share no nodes, so no edges either).
    std::set<Edge> edges;
    for (const auto& t : linear.triangles)
        for (int k = 0; k < 3; ++k) edges.insert(key(t[k], t[(k + 1) % 3]));
    EXPECT_EQ(q.nodes.size(), linear.nodes.size() + edges.size());
    ASSERT_EQ(q.node_block.size(), q.nodes.size());

    // Block ranges: contiguous, the corners in their old order first, then the midside nodes.
    EXPECT_EQ(q.block_node_begin.front(), 0);
    EXPECT_EQ(q.block_node_begin.back(), static_cast<int>(q.nodes.size()));
    std::set<int> corners;
    for (int b = 0; b < q.block_count(); ++b) {
        const int corner_count = linear.block_node_begin[b + 1] - linear.block_node_begin[b];
        ASSERT_LE(q.block_node_begin[b] + corner_count, q.block_node_begin[b + 1]);
        for (int n = q.block_node_begin[b]; n < q.block_node_begin[b + 1]; ++n) EXPECT_EQ(q.node_block[n], b);
        for (int i = 0; i < corner_count; ++i) {
            const Point2 &was = linear.nodes[linear.block_node_begin[b] + i], &is = q.nodes[q.block_node_begin[b] + i];
            EXPECT_EQ(was.x, is.x);
            EXPECT_EQ(was.y, is.y);
        }
        for (int e = q.block_triangle_begin[b]; e < q.block_triangle_begin[b + 1]; ++e)
            for (int k = 0; k < 3; ++k) {
                const int c = q.triangles[e][k], m = q.midside[e][k];
                EXPECT_EQ(c, moved(linear, q, linear.triangles[e][k]));
                EXPECT_GE(c, q.block_node_begin[b]);
                EXPECT_LT(c, q.block_node_begin[b] + corner_count);
                EXPECT_GE(m, q.block_node_begin[b] + corner_count) << "midside nodes follow the corners";
                EXPECT_LT(m, q.block_node_begin[b + 1]);
                corners.insert(c);
            }
    }

    // Midpoints, shared by the triangles on an edge, one per edge, never in two blocks.
    std::map<Edge, int> midside_of;
    std::map<int, std::set<int>> blocks_of;
    for (std::size_t e = 0; e < q.triangles.size(); ++e)
        for (int k = 0; k < 3; ++k) {
            const int a = q.triangles[e][k], b = q.triangles[e][(k + 1) % 3], m = q.midside[e][k];
            EXPECT_FALSE(corners.count(m));
            EXPECT_NEAR(q.nodes[m].x, 0.5 * (q.nodes[a].x + q.nodes[b].x), 1e-12);
            EXPECT_NEAR(q.nodes[m].y, 0.5 * (q.nodes[a].y + q.nodes[b].y), 1e-12);
            EXPECT_EQ(midside_of.emplace(key(a, b), m).first->second, m) << "the triangles on an edge share its midside node";
            blocks_of[m].insert(q.triangle_block[e]);
        }
    EXPECT_EQ(midside_of.size(), edges.size());
    EXPECT_EQ(blocks_of.size(), edges.size()) << "a midside node serves more than one edge";
    for (const auto& [m, blocks] : blocks_of) {
        EXPECT_EQ(blocks.size(), 1u) << "midside node " << m << " is shared between blocks";
        EXPECT_EQ(q.node_block[m], *blocks.begin());
    }
    // Blocks meeting along a joint may have midside nodes at the same place, but each its own.
    std::map<std::pair<double, double>, std::set<int>> at;
    for (const auto& [m, blocks] : blocks_of) at[{q.nodes[m].x, q.nodes[m].y}].insert(m);
    for (const auto& [place, nodes] : at) {
        std::set<int> owners;
        for (int m : nodes) owners.insert(q.node_block[m]);
        EXPECT_EQ(owners.size(), nodes.size());
    }
}

/// Following edge_out_of from any boundary node comes back to it; the links agree both ways.
void expect_closed_rings(const MeshTopology& t, const Mesh& mesh) {
    for (std::size_t k = 0; k < t.edges.size(); ++k) {
        const BoundaryEdge& e = t.edges[k];
        EXPECT_EQ(t.edge_out_of[e.from], static_cast<int>(k));
        EXPECT_EQ(t.edge_into[e.to], static_cast<int>(k));
        EXPECT_EQ(mesh.node_block[e.from], e.block);
        EXPECT_EQ(mesh.node_block[e.to], e.block);
    }
    for (int start : t.boundary_nodes) {
        int node = start;
        std::size_t steps = 0;
        do {
            ASSERT_GE(t.edge_out_of[node], 0) << "ring broken at node " << node;
            node = t.edges[t.edge_out_of[node]].to;
        } while (node != start && ++steps <= t.edges.size());
        EXPECT_EQ(node, start) << "the ring from node " << start << " does not close";
    }
}

void expect_half_edges(const Preprocessed& p, const Mesh& q) {
    const MeshTopology linear = build_topology(p.mesh, p.blocks);
    const MeshTopology t = build_topology(q, p.blocks);
    ASSERT_EQ(t.edges.size(), 2 * linear.edges.size());
    ASSERT_EQ(t.midside_node.size(), q.nodes.size());
    EXPECT_EQ(linear.midside_node, std::vector<char>(p.mesh.nodes.size(), 0));
    EXPECT_EQ(t.boundary_nodes.size(), linear.boundary_nodes.size() + linear.edges.size());
    expect_closed_rings(linear, p.mesh);
    expect_closed_rings(t, q);

    std::set<int> midside;
    for (const auto& m : q.midside) midside.insert(m.begin(), m.end());
    for (std::size_t n = 0; n < q.nodes.size(); ++n)
        EXPECT_EQ(t.midside_node[n] != 0, midside.count(static_cast<int>(n)) > 0) << "node " << n;
    // One corner and one midside end, in the direction of a triangle's counter-clockwise corner →
    // midside → corner path, so that the block lies on the left.
    std::set<Edge> ccw;
    for (std::size_t e = 0; e < q.triangles.size(); ++e)
        for (int k = 0; k < 3; ++k) {
            ccw.insert({q.triangles[e][k], q.midside[e][k]});
            ccw.insert({q.midside[e][k], q.triangles[e][(k + 1) % 3]});
        }
    for (const BoundaryEdge& e : t.edges) {
        EXPECT_NE(t.midside_node[e.from], t.midside_node[e.to]) << "one corner, one midside end";
        EXPECT_TRUE(ccw.count({e.from, e.to})) << e.from << " → " << e.to << " has the block on its right";
    }

    // Every linear edge (i, j) became (i', m), (m, j') with the block and the joint of (i, j).
    int on_joints = 0;
    for (const BoundaryEdge& e : linear.edges) {
        const int from = moved(p.mesh, q, e.from), to = moved(p.mesh, q, e.to);
        ASSERT_GE(t.edge_out_of[from], 0);
        const BoundaryEdge& first = t.edges[t.edge_out_of[from]];
        ASSERT_EQ(first.from, from);
        ASSERT_TRUE(t.midside_node[first.to]);
        const BoundaryEdge& second = t.edges[t.edge_out_of[first.to]];
        EXPECT_EQ(second.to, to);
        for (const BoundaryEdge* half : {&first, &second}) {
            EXPECT_EQ(half->block, e.block);
            EXPECT_EQ(half->joint, e.joint);
        }
        on_joints += e.joint >= 0;
    }
    EXPECT_GT(on_joints, 0) << "the model's joint should tag some edges";
}

/// A structured grid per block, nx × ny cells of two triangles, block b shifted right by b.
Mesh grid_mesh(int blocks, int nx, int ny) {
    Mesh m;
    for (int b = 0; b < blocks; ++b) {
        const int base = static_cast<int>(m.nodes.size());
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                m.nodes.push_back({b + static_cast<double>(i) / nx, static_cast<double>(j) / ny});
                m.node_block.push_back(b);
            }
        auto node = [&](int i, int j) { return base + j * (nx + 1) + i; };
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                m.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
                m.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
                for (int k = 0; k < 2; ++k) {
                    m.triangle_block.push_back(b);
                    m.triangle_material.push_back(0);
                }
            }
        m.block_node_begin.push_back(static_cast<int>(m.nodes.size()));
        m.block_triangle_begin.push_back(static_cast<int>(m.triangles.size()));
    }
    return m;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The numbers of the DataArray called `name`.
std::vector<long> data_array(const std::string& text, const std::string& name) {
    const std::size_t tag = text.find("Name=\"" + name + "\"");
    if (tag == std::string::npos) return {};
    const std::size_t begin = text.find('>', tag) + 1, end = text.find("</DataArray>", begin);
    std::istringstream in(text.substr(begin, end - begin));
    std::vector<long> values;
    for (long v; in >> v;) values.push_back(v);
    return values;
}

}  // namespace

TEST(QuadraticMesh, TwoBlocksCutByAJoint) {
    const Preprocessed p = two_blocks();
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    ASSERT_EQ(p.mesh.block_count(), 2);
    Mesh q = p.mesh;
    add_midside_nodes(q);
    expect_valid_quadratic(p.mesh, q);
    expect_half_edges(p, q);
}

TEST(QuadraticMesh, BlockWithAHole) {
    const Preprocessed p = block_with_hole();
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    ASSERT_EQ(p.mesh.block_count(), 2);
    ASSERT_EQ(p.blocks[0].holes.size() + p.blocks[1].holes.size(), 1u);
    Mesh q = p.mesh;
    add_midside_nodes(q);
    expect_valid_quadratic(p.mesh, q);
    expect_half_edges(p, q);
}

TEST(QuadraticMesh, LinearTopologyIsUnchanged) {
    // The edges a single triangle of the block uses, in triangle order, as build_topology found
    // them with a std::map per block before six-node meshes came.
    for (const Preprocessed& p : {two_blocks(), block_with_hole()}) {
        ASSERT_TRUE(p.ok);
        const Mesh& m = p.mesh;
        std::vector<BoundaryEdge> expected;
        for (int b = 0; b < m.block_count(); ++b) {
            std::map<Edge, int> count;
            for (int e = m.block_triangle_begin[b]; e < m.block_triangle_begin[b + 1]; ++e)
                for (int k = 0; k < 3; ++k) ++count[key(m.triangles[e][k], m.triangles[e][(k + 1) % 3])];
            for (int e = m.block_triangle_begin[b]; e < m.block_triangle_begin[b + 1]; ++e)
                for (int k = 0; k < 3; ++k) {
                    const int i = m.triangles[e][k], j = m.triangles[e][(k + 1) % 3];
                    if (count[key(i, j)] == 1) expected.push_back({i, j, b, -1});
                }
        }
        const MeshTopology t = build_topology(m, p.blocks);
        ASSERT_EQ(t.edges.size(), expected.size());
        for (std::size_t k = 0; k < expected.size(); ++k) {
            EXPECT_EQ(t.edges[k].from, expected[k].from);
            EXPECT_EQ(t.edges[k].to, expected[k].to);
            EXPECT_EQ(t.edges[k].block, expected[k].block);
        }
    }
}

TEST(QuadraticMesh, SecondCallChangesNothing) {
    const Preprocessed p = block_with_hole();
    ASSERT_TRUE(p.ok);
    Mesh once = p.mesh;
    add_midside_nodes(once);
    Mesh twice = once;
    add_midside_nodes(twice);
    EXPECT_EQ(twice.nodes.size(), once.nodes.size());
    for (std::size_t n = 0; n < once.nodes.size(); ++n) {
        EXPECT_EQ(twice.nodes[n].x, once.nodes[n].x);
        EXPECT_EQ(twice.nodes[n].y, once.nodes[n].y);
    }
    EXPECT_EQ(twice.node_block, once.node_block);
    EXPECT_EQ(twice.triangles, once.triangles);
    EXPECT_EQ(twice.midside, once.midside);
    EXPECT_EQ(twice.block_node_begin, once.block_node_begin);
}

TEST(QuadraticMesh, StructuredGridCounts) {
    // nx × ny cells of two triangles have nx(ny+1) + ny(nx+1) + nx·ny edges.
    const int blocks = 3, nx = 40, ny = 25;
    const Mesh linear = grid_mesh(blocks, nx, ny);
    Mesh q = linear;
    add_midside_nodes(q);
    const int edges = nx * (ny + 1) + ny * (nx + 1) + nx * ny;
    EXPECT_EQ(q.nodes.size(), linear.nodes.size() + static_cast<std::size_t>(blocks * edges));
    for (int b = 0; b <= blocks; ++b) EXPECT_EQ(q.block_node_begin[b], b * ((nx + 1) * (ny + 1) + edges));
    expect_valid_quadratic(linear, q);
    // The blocks touch (x = 1, 2) but own their nodes: each block's boundary is its own ring.
    const MeshTopology t = build_topology(q, {});
    EXPECT_EQ(t.edges.size(), static_cast<std::size_t>(blocks * 4 * (nx + ny)));
    expect_closed_rings(t, q);
}

TEST(QuadraticMesh, RefusesTrianglesAcrossBlocks) {
    Mesh m = grid_mesh(2, 2, 2);
    m.triangles[0][0] = m.block_node_begin[1];  // block 0 uses a node of block 1
    EXPECT_THROW(add_midside_nodes(m), std::invalid_argument);
    EXPECT_FALSE(m.quadratic());
    Mesh empty;
    add_midside_nodes(empty);
    EXPECT_TRUE(empty.nodes.empty());
}

TEST(QuadraticMesh, StatisticsCountMidsideNodesAndMeasureCorners) {
    const Preprocessed p = two_blocks();
    ASSERT_TRUE(p.ok);
    Mesh q = p.mesh;
    add_midside_nodes(q);
    const MeshStatistics s = compute_statistics(q, p.blocks);
    EXPECT_EQ(s.nodes, static_cast<int>(q.nodes.size()));
    EXPECT_EQ(s.elements, p.statistics.elements);
    EXPECT_DOUBLE_EQ(s.min_angle_deg, p.statistics.min_angle_deg);
    EXPECT_DOUBLE_EQ(s.max_angle_deg, p.statistics.max_angle_deg);
    EXPECT_NEAR(s.total_area, 100.0, 1e-9);
    EXPECT_EQ(s.min_angle_histogram, p.statistics.min_angle_histogram);
}

TEST(QuadraticMesh, VtuHasQuadraticTriangles) {
    const Preprocessed p = two_blocks();
    ASSERT_TRUE(p.ok);
    Mesh q = p.mesh;
    add_midside_nodes(q);
    const fs::path dir = fs::temp_directory_path() / "mcdda-quadratic-vtu-test";
    fs::create_directories(dir);
    const std::size_t cells = q.triangles.size();
    for (const Mesh* mesh : std::vector<const Mesh*>{&p.mesh, &q}) {
        const std::string path = (dir / "mesh.vtu").string();
        write_vtu(path, *mesh);
        const std::string text = read_text(path);
        const long per_cell = mesh->quadratic() ? 6 : 3;
        EXPECT_NE(text.find("NumberOfPoints=\"" + std::to_string(mesh->nodes.size()) + "\""), std::string::npos);
        EXPECT_NE(text.find("NumberOfCells=\"" + std::to_string(cells) + "\""), std::string::npos);
        const std::vector<long> connectivity = data_array(text, "connectivity");
        const std::vector<long> offsets = data_array(text, "offsets");
        const std::vector<long> types = data_array(text, "types");
        ASSERT_EQ(connectivity.size(), per_cell * cells);
        ASSERT_EQ(offsets.size(), cells);
        ASSERT_EQ(types.size(), cells);
        for (std::size_t e = 0; e < cells; ++e) {
            EXPECT_EQ(offsets[e], per_cell * static_cast<long>(e + 1));
            EXPECT_EQ(types[e], mesh->quadratic() ? 22 : 5);
            // VTK's order: corners, then the midside nodes of edges 0-1, 1-2, 2-0.
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(connectivity[per_cell * e + k], mesh->triangles[e][k]);
                if (mesh->quadratic()) {
                    EXPECT_EQ(connectivity[per_cell * e + 3 + k], mesh->midside[e][k]);
                }
            }
        }
    }
    fs::remove_all(dir);
}
