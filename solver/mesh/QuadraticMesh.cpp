#include "mesh/QuadraticMesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mcdda {

std::vector<int> number_edges(const Mesh& mesh, int& edge_count) {
    const std::size_t n = mesh.nodes.size(), t = mesh.triangles.size();
    // Each edge is filed under its lower node (a counting sort), each node's list sorted by the
    // upper node: O(n log d) for node degrees d, with no hashing and no allocation per edge.
    std::vector<int> start(n + 1, 0);
    for (const auto& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++start[std::min(tri[k], tri[(k + 1) % 3]) + 1];
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<int> upper(3 * t), cursor(start.begin(), start.end() - 1);
    for (const auto& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = tri[k], b = tri[(k + 1) % 3];
            upper[cursor[std::min(a, b)]++] = std::max(a, b);
        }
    for (std::size_t i = 0; i < n; ++i) std::sort(upper.begin() + start[i], upper.begin() + start[i + 1]);

    // The first filed copy of an edge stands for it; numbers follow the triangles' order.
    std::vector<int> number_at(3 * t, -1), id(3 * t);
    edge_count = 0;
    for (std::size_t e = 0; e < t; ++e)
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.triangles[e][k], b = mesh.triangles[e][(k + 1) % 3];
            const int lo = std::min(a, b);
            const auto at = std::lower_bound(upper.begin() + start[lo], upper.begin() + start[lo + 1], std::max(a, b));
            int& number = number_at[at - upper.begin()];
            if (number < 0) number = edge_count++;
            id[3 * e + k] = number;
        }
    return id;
}

void add_midside_nodes(Mesh& mesh) {
    if (mesh.quadratic()) return;
    const int blocks = mesh.block_count();
    if (mesh.block_triangle_begin.size() != mesh.block_node_begin.size() ||
        mesh.block_node_begin.back() != static_cast<int>(mesh.nodes.size()) ||
        mesh.block_triangle_begin.back() != static_cast<int>(mesh.triangles.size()))
        throw std::invalid_argument("add_midside_nodes: the block ranges do not cover the mesh");
    // The renumbering below relies on blocks sharing no nodes.
    for (int b = 0; b < blocks; ++b)
        for (int e = mesh.block_triangle_begin[b]; e < mesh.block_triangle_begin[b + 1]; ++e)
            for (int node : mesh.triangles[e])
                if (node < mesh.block_node_begin[b] || node >= mesh.block_node_begin[b + 1])
                    throw std::invalid_argument("add_midside_nodes: triangle " + std::to_string(e) + " of block " +
                                                std::to_string(b) + " uses node " + std::to_string(node) +
                                                " outside the block");
    if (mesh.triangles.empty()) return;

    int edge_count = 0;
    const std::vector<int> edge = number_edges(mesh, edge_count);
    // Numbered in order of first appearance, with no edge shared between blocks, block b's edges
    // are [edge_begin[b], edge_begin[b+1]).
    std::vector<int> edge_begin(blocks + 1, 0);
    for (int b = 0; b < blocks; ++b) {
        edge_begin[b + 1] = edge_begin[b];
        for (int i = 3 * mesh.block_triangle_begin[b]; i < 3 * mesh.block_triangle_begin[b + 1]; ++i)
            edge_begin[b + 1] = std::max(edge_begin[b + 1], edge[i] + 1);
    }

    // Corner node i of block b moves up by the midside nodes of the blocks before it, to
    // i + edge_begin[b]; the midside node of edge g then lands at old block_node_begin[b+1] + g,
    // right after the block's corners.
    const std::size_t total = mesh.nodes.size() + edge_count;
    std::vector<Point2> nodes(total);
    std::vector<int> node_block(total);
    mesh.midside.resize(mesh.triangles.size());
    for (int b = 0; b < blocks; ++b) {
        const int end = mesh.block_node_begin[b + 1];
        for (int i = mesh.block_node_begin[b]; i < end; ++i) {
            nodes[i + edge_begin[b]] = mesh.nodes[i];
            node_block[i + edge_begin[b]] = b;
        }
        for (int g = edge_begin[b]; g < edge_begin[b + 1]; ++g) node_block[end + g] = b;
        for (int e = mesh.block_triangle_begin[b]; e < mesh.block_triangle_begin[b + 1]; ++e) {
            auto& tri = mesh.triangles[e];
            for (int k = 0; k < 3; ++k) {
                const Point2& p = mesh.nodes[tri[k]];
                const Point2& q = mesh.nodes[tri[(k + 1) % 3]];
                const int m = end + edge[3 * e + k];
                nodes[m] = {0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
                mesh.midside[e][k] = m;
            }
        }
        for (int e = mesh.block_triangle_begin[b]; e < mesh.block_triangle_begin[b + 1]; ++e)
            for (int& node : mesh.triangles[e]) node += edge_begin[b];
    }
    for (int b = 0; b <= blocks; ++b) mesh.block_node_begin[b] += edge_begin[b];
    mesh.nodes = std::move(nodes);
    mesh.node_block = std::move(node_block);
}

}  // namespace mcdda
