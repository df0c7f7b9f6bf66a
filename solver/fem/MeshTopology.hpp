#pragma once
/// \file MeshTopology.hpp
/// What the solver needs to know about the mesh beyond its triangles: the boundary edges of
/// every block (where contacts, pressures and rollers act) and point look-ups.

#include "geometry/Block.hpp"
#include "mesh/Mesh.hpp"

#include <vector>

namespace mcdda {

/// A boundary edge of a block, directed so that the block lies on its left.
struct BoundaryEdge {
    int from = -1, to = -1;  ///< node indices
    int block = -1;
    int joint = -1;          ///< joint of the block ring edge it lies on (−1: none)
};

struct MeshTopology {
    std::vector<BoundaryEdge> edges;
    /// For each node: the boundary edges ending at / starting from it (−1 for interior nodes).
    std::vector<int> edge_into, edge_out_of;
    std::vector<int> boundary_nodes;  ///< nodes on some block boundary
    std::vector<char> midside_node;   ///< per node: 1 for a six-node triangle's midside node
    double model_size = 1.0;          ///< diagonal of the mesh's bounding box (m)

    bool on_boundary(int node) const { return edge_out_of[node] >= 0; }
};

/// Finds the boundary edges of every block, tagging them with the joints of `blocks`.
MeshTopology build_topology(const Mesh& mesh, const std::vector<Block>& blocks);

/// Index of the node nearest to `p` (the lowest index among equally near ones).
int nearest_node(const Mesh& mesh, Point2 p);

/// Distance from `p` to the segment [a, b].
double distance_to_segment(Point2 p, Point2 a, Point2 b);

}  // namespace mcdda
