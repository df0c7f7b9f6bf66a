#pragma once
/// \file ContactDetection.hpp
/// Finds vertex–edge contact candidates between blocks with a uniform grid (O(n), never
/// all-pairs) and carries each contact's state over from the previous step.

#include "contact/Contact.hpp"
#include "fem/MeshTopology.hpp"
#include "mesh/Mesh.hpp"

#include <vector>

namespace mcdda {

/// Candidates for the current coordinates `nodes`: for every boundary node and every other block
/// with an edge within `search_distance`, the nearest such edge (ties: the one the node is least
/// inside of; Shi's entrance rule for vertex–vertex cases reduces to this choice). A candidate
/// starts locked when touching or penetrating, open otherwise, unless `previous` holds a contact
/// of the same node and block, whose state it keeps.
std::vector<Contact> detect_contacts(const std::vector<Point2>& nodes, const Mesh& mesh, const MeshTopology& topology,
                                     double search_distance, const std::vector<Contact>& previous);

/// Signed distance of `p` from the line of edge (a, b), positive on the right (outside the block
/// lying left of the edge).
double signed_gap(Point2 p, Point2 a, Point2 b);

}  // namespace mcdda
