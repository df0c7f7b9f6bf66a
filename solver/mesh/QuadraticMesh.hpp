#pragma once
/// \file QuadraticMesh.hpp
/// Six-node triangles from three-node ones: a node in the middle of every edge.

#include "mesh/Mesh.hpp"

#include <vector>

namespace mcdda {

/// Adds a node at the midpoint of every triangle edge and fills `mesh.midside`. Triangles sharing
/// an edge share its midside node; blocks never do, since they share no corner nodes. Block b's
/// nodes stay contiguous: its corner nodes in their old order, then its midside nodes in the
/// order their edges first appear among its triangles. Does nothing on a quadratic mesh. O(n).
/// Throws std::invalid_argument when a triangle uses a node outside its block's range.
void add_midside_nodes(Mesh& mesh);

/// Numbers the distinct corner edges of the triangles, {a, b} = {b, a}, in the order they first
/// appear: the result holds at 3e + k the number of edge k of triangle e (corners k, (k+1) % 3).
/// `edge_count` receives the number of distinct edges. O(n).
std::vector<int> number_edges(const Mesh& mesh, int& edge_count);

}  // namespace mcdda
