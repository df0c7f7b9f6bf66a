#pragma once
/// \file MeshTopology.hpp
/// What the solver needs to know about the mesh beyond its triangles: the boundary edges of
/// every block (where contacts, pressures and rollers act) and point look-ups.
///
/// On a six-node mesh every boundary edge (i, j) of a block with midside node m appears as two
/// half-edges (i, m) and (m, j), so midside nodes are boundary vertices like corners and the
/// boundary rings run corner, midside, corner, ...

#include "geometry/Block.hpp"
#include "mesh/Mesh.hpp"

#include <vector>

namespace mcdda {

/// A boundary edge of a block, directed so that the block lies on its left. On a six-node mesh
/// it is a half-edge: one end a corner node, the other the midside node of the triangle edge.
struct BoundaryEdge {
    int from = -1, to = -1;  ///< node indices
    int block = -1;
    int joint = -1;          ///< joint of the block ring edge or crack it lies on (−1: none)
    bool crack = false;      ///< a face of a crack inside the block (Block::cracks)
};

struct MeshTopology {
    std::vector<BoundaryEdge> edges;  ///< block by block: block b's are [block_edge_begin[b], block_edge_begin[b + 1])
    std::vector<int> block_edge_begin;
    /// For each node: the boundary edges ending at / starting from it (−1 for interior nodes).
    std::vector<int> edge_into, edge_out_of;
    std::vector<int> boundary_nodes;  ///< nodes on some block boundary
    /// For each node: 1 if it is a midside node (all 0 on three-node meshes). Loads on half-edges
    /// need it for the consistent quadratic weights: a uniform pressure p on a half-edge of length
    /// h puts p·h/3 on its corner end and 2p·h/3 on its midside end (1/6, 2/3, 1/6 of the whole
    /// edge's force), not p·h/2 on each.
    std::vector<char> midside_node;
    double model_size = 1.0;          ///< diagonal of the mesh's bounding box (m)

    bool on_boundary(int node) const { return edge_out_of[node] >= 0; }
};

/// Finds the boundary edges of every block, tagging them with the joints of `blocks` (both halves
/// of a six-node edge with the tag of the whole edge). The faces of a crack, whose nodes the
/// mesher doubled, are boundary edges of their block like its outline, tagged as crack faces.
/// O(n log n) in the number of triangles.
MeshTopology build_topology(const Mesh& mesh, const std::vector<Block>& blocks);

/// Index of the node nearest to `p` (the lowest index among equally near ones).
int nearest_node(const Mesh& mesh, Point2 p);

}  // namespace mcdda
