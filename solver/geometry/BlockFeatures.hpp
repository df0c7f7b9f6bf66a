#pragma once
/// \file BlockFeatures.hpp
/// The smallest feature of a block: its shortest edge, or the closest approach of a vertex to
/// an edge it does not touch (a sliver, or a joint passing a hair's breadth from a corner).
/// Features many orders of magnitude below the model's size cannot be meshed: Delaunay
/// refinement near them runs out of floating-point resolution (crashes in CGAL's mesher,
/// endless refinement), so they are refused before meshing with their place named.

#include "geometry/Block.hpp"
#include "model/Diagnostic.hpp"

#include <optional>
#include <string>

namespace mcdda {

/// A feature of a block smaller than a tolerance.
struct SmallFeature {
    double size = 0.0;  ///< m
    Point2 where;       ///< a point on it
    std::string what;   ///< "an edge" or "a vertex ... from an edge it does not touch"
};

/// The first feature of `block` smaller than `tolerance` (m), if any. Cost about linear in the
/// block's vertex count (edges are binned in a grid).
std::optional<SmallFeature> find_small_feature(const Block& block, double tolerance);

/// Distance, as a fraction of the model's size (the diagonal of its bounding box,
/// Model::bounds), within which a joint passing a vertex is routed through it: 1e-6, a tenth of
/// a millimetre in a 100 m model (a rounding error, not a feature).
constexpr double smallest_feature_ratio = 1e-6;

/// Smallest feature a block may have, as a fraction of the model's size: 1e-5, a millimetre in a
/// 100 m model. A sliver that thin forces triangles of its width along its whole length (a joint
/// 0.09 mm from a 12 m boundary: 150,000 triangles where 2,000 were asked for).
constexpr double smallest_block_feature_ratio = 1e-5;

/// The sharpest corner a block may have, in degrees. Joints (or a joint and a region's boundary)
/// meeting at a smaller angle cut a sliver that neither the mesher nor the contacts handle in
/// bounded work: its tip forces refinement far below the size asked for (two joints crossing at
/// 0.003° across the Prandtl footing: 31,000 elements instead of 1,000), and every node of a thin
/// wedge lies within contact reach of its neighbours' faces, so the open–close iteration does not
/// settle (ten joints fanned 0.38° apart: 74 factorisations without finishing one step).
constexpr double sharpest_corner_deg = 1.0;

/// A corner of a block: its interior angle and vertex.
struct SharpCorner {
    double angle_deg = 180.0;
    Point2 where;
};
/// The sharpest corner of a block, over its outer ring and holes.
SharpCorner sharpest_corner(const Block& block);
/// The sharpest corner of a block if it is sharper than `limit_deg`.
std::optional<SharpCorner> find_sharp_corner(const Block& block, double limit_deg);

/// An error per block (the first few) with a feature below smallest_block_feature_ratio of the
/// model's size or a corner sharper than sharpest_corner_deg, naming the block, its region and
/// the place.
void check_block_features(const Model& model, const std::vector<Block>& blocks, std::vector<Diagnostic>& diagnostics);

}  // namespace mcdda
