#pragma once
/// \file PorePressure.hpp
/// The loads of ground water (Model.hpp, Water) in the effective-stress formulation: the blocks'
/// stresses are effective stresses σ′ = σ + u·m (tension positive, u compression positive,
/// m = (1, 1, 0)), so equilibrium of the total stress ∫Bᵀσ dV = f reads
///
///     ∫Bᵀσ′ dV = f + ∫Bᵀ m u dV,
///
/// and the water pressure u acts on every face of every block below the line: on the ground
/// surface under a lake (the ponded water's weight), on the faces of joints and cracks (pushing
/// them apart, so that the contact springs carry the effective normal force Coulomb's law
/// needs) and on the model's own edges (where the supports take it). Integrated by parts, the two
/// loads together are −∫N ∇u dV: buoyancy and seepage force. Both are integrated exactly for the
/// hydrostatic field of a straight line (the boundary by pieces between the line's kinks), so a
/// body under water with γsat and the dry body with γ′ = γsat − γw give the same effective stresses.

#include "fem/MeshTopology.hpp"
#include "mesh/Mesh.hpp"
#include "model/Model.hpp"

#include <Eigen/Dense>

#include <vector>

namespace mcdda {

/// Adds factor · (∫Bᵀ m u dV over the present elements + the water pressure on the boundary edges of
/// the present blocks) to `f` (N/m), on coordinates `nodes`. `active_elements` empty: all present.
void add_water_forces(const Water& water, const Mesh& mesh, const std::vector<Point2>& nodes,
                      const MeshTopology& topology, const std::vector<char>& active_elements, double factor,
                      Eigen::VectorXd& f);

/// Pore pressure of each element (Pa, compression positive): the mean over its integration
/// points, the value its effective stress (the mean of theirs) is to be compared with.
std::vector<double> element_pore_pressures(const Water& water, const Mesh& mesh, const std::vector<Point2>& nodes);

/// Position of integration point q of element e (TriangleElement.hpp's rule) on `nodes`.
Point2 integration_point(const Mesh& mesh, const std::vector<Point2>& nodes, int e, int q);

/// Integration points per element of `mesh` (1 for three-node, 3 for six-node triangles).
int integration_points(const Mesh& mesh);

}  // namespace mcdda
