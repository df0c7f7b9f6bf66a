#pragma once
/// \file Mesh.hpp
/// The finite-element mesh of all blocks: three-node triangles, nodes owned by exactly one block.

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
    /// Nodes of block b are [block_node_begin[b], block_node_begin[b+1]); the same for triangles.
    std::vector<int> block_node_begin{0};
    std::vector<int> block_triangle_begin{0};

    int block_count() const { return static_cast<int>(block_node_begin.size()) - 1; }
};

}  // namespace mcdda
