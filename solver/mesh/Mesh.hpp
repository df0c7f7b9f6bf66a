#pragma once
/// \file Mesh.hpp
/// The finite-element mesh of all blocks: three- or six-node triangles (straight edges), nodes
/// owned by exactly one block.

#include "model/Model.hpp"

#include <array>
#include <vector>

namespace mcdda {

struct Mesh {
    std::vector<Point2> nodes;                 ///< coordinates (m)
    std::vector<int> node_block;               ///< block of each node
    std::vector<std::array<int, 3>> triangles; ///< node indices, counter-clockwise
    std::vector<int> triangle_block;           ///< block of each triangle
    std::vector<int> triangle_material;        ///< material of each triangle
    /// Six-node triangles only (empty for three-node meshes): midside[e][k] is the node in the
    /// middle of edge k of triangle e, between corners k and (k+1) % 3. Midside nodes are shared
    /// by the two triangles of a block that share the edge, never between blocks.
    std::vector<std::array<int, 3>> midside;
    /// Nodes of block b are [block_node_begin[b], block_node_begin[b+1]); the same for triangles.
    std::vector<int> block_node_begin{0};
    std::vector<int> block_triangle_begin{0};

    int block_count() const { return static_cast<int>(block_node_begin.size()) - 1; }
    bool quadratic() const { return !midside.empty(); }
};

}  // namespace mcdda
