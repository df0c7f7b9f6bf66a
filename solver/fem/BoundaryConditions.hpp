#pragma once
/// \file BoundaryConditions.hpp
/// Supports, loads and measurement points of the model located on the mesh: which degrees of
/// freedom are fixed (eliminated exactly), which nodes and edges carry loads.

#include "fem/MeshTopology.hpp"
#include "mesh/Mesh.hpp"
#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <Eigen/Dense>

#include <vector>

namespace mcdda {

struct BoundaryConditions {
    /// Per degree of freedom (2·node + direction): its equation number, or −1 when fixed.
    std::vector<int> equation;
    int equation_count = 0;

    struct NodalLoad {
        int node = -1;
        int load = -1;  ///< index into Model::point_loads
    };
    struct PressureEdge {
        int edge = -1;  ///< index into MeshTopology::edges
        int load = -1;  ///< index into Model::edge_pressures
    };
    std::vector<NodalLoad> point_loads;
    std::vector<PressureEdge> pressure_edges;
    std::vector<int> measurement_nodes;  ///< one node per Model::measurement_points entry
    std::vector<std::vector<int>> roller_nodes;  ///< per Model::rollers entry, the nodes it holds

    bool fixed(int node, int direction) const { return equation[2 * node + direction] < 0; }
};

/// Before meshing: rollers and edge pressures that lie along no boundary of the cut blocks are
/// errors naming the item (the check `mcdda check` makes; locate_boundary_conditions makes the
/// same one on the mesh).
void check_supports_on_blocks(const Model& model, const std::vector<Block>& blocks, std::vector<Diagnostic>& diagnostics);

/// Locates supports, loads and measurement points. Supports and loads that catch no node are
/// errors naming the item.
BoundaryConditions locate_boundary_conditions(const Model& model, const Mesh& mesh, const MeshTopology& topology,
                                              std::vector<Diagnostic>& diagnostics);

/// Factor of load table `table` (−1: constant 1) at the given step and time. The step may be
/// fractional: static analyses apply a step's load in smaller increments when it does not
/// converge at once.
double load_factor(const Model& model, int table, double step, double time);

/// External nodal forces (N/m) at `step`/`time` on the current coordinates `nodes`: point loads,
/// edge pressures (normal to the current edge, pushing into the material) and gravity, each
/// distributed consistently with the element (three-node: ½ per edge node, A/3 per corner;
/// six-node: 1/6, 4/6, 1/6 along an edge, A/3 per midside node and none at the corners).
/// Gravity acts on the elements flagged in `active_elements` (empty: on all).
Eigen::VectorXd external_forces(const Model& model, const Mesh& mesh, const std::vector<Point2>& nodes,
                                const MeshTopology& topology, const BoundaryConditions& bc, double step, double time,
                                const std::vector<char>& active_elements = {});

}  // namespace mcdda
