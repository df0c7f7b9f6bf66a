#pragma once
/// \file ContactDetection.hpp
/// Finds vertex–edge contact candidates between blocks with a uniform grid (O(n), never
/// all-pairs) and carries each contact's state over from the previous step.

#include "contact/Contact.hpp"
#include "fem/MeshTopology.hpp"
#include "mesh/Mesh.hpp"

#include <Eigen/Dense>

#include <vector>

namespace mcdda {

/// Candidates for the current coordinates `nodes`: for every boundary node and every other block
/// (and, for a node on a crack face, its own block's crack faces) with an edge within
/// `search_distance`, the nearest such edge (ties: the one the node is least
/// inside of) that the vertex faces (the edge's outward normal and the vertex's point against each
/// other: a simplified form of Shi's entrance rule for vertex–vertex cases) and projects onto,
/// unless a third block lies between them (the segment from the node to the edge crosses one of
/// its edges).
/// A contact of the same node and block in `previous` keeps its state. A new one starts open
/// when apart; when touching it starts sliding if the expected slip over the step
/// (`expected_increment`, velocity × Δt; empty in static analysis) exceeds `tolerance`, locked
/// otherwise: a node that a sliding block passes over must not first lock it in place.
std::vector<Contact> detect_contacts(const std::vector<Point2>& nodes, const Mesh& mesh, const MeshTopology& topology,
                                     double search_distance, const std::vector<Contact>& previous,
                                     const Eigen::VectorXd& expected_increment, double tolerance);

/// Signed distance of `p` from the line of edge (a, b), positive on the right (outside the block
/// lying left of the edge).
double signed_gap(Point2 p, Point2 a, Point2 b);

}  // namespace mcdda
