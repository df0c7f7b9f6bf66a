#pragma once
/// \file Block.hpp
/// A block: one connected piece of a region after the joints have cut it (DDA's block).

#include "model/Model.hpp"

#include <vector>

namespace mcdda {

/// What a block's boundary edge lies on; contacts on it take their strength from here.
struct EdgeTag {
    int joint = -1;   ///< index into Model::joints, or −1 when the edge is not on a joint
    int region_boundary = -1;  ///< region whose outer boundary or hole the edge lies on, or −1
};

/// One block: outer ring counter-clockwise, holes clockwise; tags[i][k] describes the edge from
/// vertex k to vertex k+1 of ring i (ring 0 = outer, 1.. = holes).
struct Block {
    int region = -1;
    int material = -1;
    Ring outer;
    std::vector<Ring> holes;
    std::vector<std::vector<EdgeTag>> tags;
    double area = 0.0;  ///< m²
    /// A straight piece of a joint trace inside the block that separates nothing: it ends in the
    /// rock (or floats in it), so the block is not cut along it and the analysis does not use it.
    struct JointPiece {
        Point2 from, to;
        int joint = -1;  ///< index into Model::joints
    };
    std::vector<JointPiece> unused_joint_pieces;
};

}  // namespace mcdda
