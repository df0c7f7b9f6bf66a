#pragma once
/// \file BlockMesher.hpp
/// Meshes every block on its own with CGAL's constrained Delaunay refinement (Ruppert/Shewchuk):
/// a minimum-angle bound and the size field, keeping each block's boundary vertices.

#include "geometry/Block.hpp"
#include "mesh/Mesh.hpp"
#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <vector>

namespace mcdda {

/// Meshes `blocks` with `model.mesh`. Refuses (error diagnostic, empty mesh) when the size field
/// would give more than `model.mesh.max_elements` triangles.
Mesh mesh_blocks(const Model& model, const std::vector<Block>& blocks, std::vector<Diagnostic>& diagnostics);

/// Expected number of triangles for the model's size field over the blocks (an estimate).
double estimate_triangle_count(const Model& model, const std::vector<Block>& blocks);

}  // namespace mcdda
