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

/// Smallest feature a block may have, as a fraction of the model's size (the diagonal of its
/// bounding box, Model::bounds): 1e-6, a tenth of a millimetre in a 100 m model.
constexpr double smallest_feature_ratio = 1e-6;

/// An error per block (the first few) with a feature below smallest_feature_ratio of the
/// model's size, naming the block, its region and the place.
void check_block_features(const Model& model, const std::vector<Block>& blocks, std::vector<Diagnostic>& diagnostics);

}  // namespace mcdda
