#pragma once
/// \file ViscousBoundary.hpp
/// Viscous (Lysmer–Kuhlemeyer 1969) dashpots on the model's boundary: an absorbing boundary
/// takes the traction −(ρVp vn n + ρVs vs s) of the material beside it, so that a wave hitting
/// it leaves instead of reflecting; a compliant base takes besides the input 2(ρVp (vᵢ·n) n +
/// ρVs (vᵢ·s) s) of an incident wave of velocity vᵢ (the record's), which makes the traction
/// 2C·vᵢ − C·v. Lumped to the nodes with the edge's load shares (½ each; 1/6, 2/3, 1/6 on
/// six-node edges), like pressures.

#include "fem/MeshTopology.hpp"
#include "mesh/Mesh.hpp"
#include "model/Model.hpp"

#include <Eigen/Dense>

#include <vector>

namespace mcdda {

class ViscousBoundary {
public:
    struct Dashpot {
        int node = -1;
        Eigen::Matrix2d c = Eigen::Matrix2d::Zero();  ///< N·s/m per metre thickness
        /// The compliant base's share of c, through which the incident wave enters (a corner
        /// shared with an absorbing side takes the input through the base's dashpots only).
        Eigen::Matrix2d input_c = Eigen::Matrix2d::Zero();
        bool input = false;                          ///< on the compliant base
    };

    ViscousBoundary() = default;
    /// The dashpots of `model`'s absorbing boundaries and compliant base on the elements present
    /// (`active`, empty: all), with the materials of `mesh.triangle_material`.
    ViscousBoundary(const Model& model, const Mesh& mesh, const MeshTopology& topology, const std::vector<char>& active);

    bool empty() const { return dashpots_.empty(); }
    const std::vector<Dashpot>& dashpots() const { return dashpots_; }

    /// Adds the dashpot forces to `r` for increments d: the nodes' velocity at the end of the
    /// step is rate·d + v_rest (Newmark), the incident wave's `incident`.
    void add_forces(const Eigen::VectorXd& d, double rate, const Eigen::VectorXd& v_rest, const Eigen::Vector2d& incident,
                    Eigen::VectorXd& r) const;

private:
    std::vector<Dashpot> dashpots_;
};

}  // namespace mcdda
