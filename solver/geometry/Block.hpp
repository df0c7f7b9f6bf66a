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
    /// rock (or floats in it). The block is not cut along it; the mesher makes it a crack: the
    /// mesh conforms to it and its nodes are doubled except at its tips, so that its two faces
    /// open and slide through contacts of the joint's material while the rock beyond the tips
    /// stays continuous.
    struct Crack {
        Point2 from, to;
        int joint = -1;  ///< index into Model::joints
    };
    std::vector<Crack> cracks;
};

}  // namespace mcdda
