#pragma once
/// \file BoltLink.hpp
/// A rock bolt as the solver sees it (Shi's bolt in DDA, UDEC's cable without grout): an axial
/// spring between two anchor points, each moving with the corner nodes of the element it lies
/// in. Its elongation over a step is linear in the displacement increments, g·d, with g the
/// unit direction spread over the anchors' nodes by their (linear) shape functions.

#include "fem/MeshTopology.hpp"
#include "mesh/Mesh.hpp"
#include "model/Model.hpp"

#include <Eigen/Dense>

#include <array>
#include <optional>
#include <vector>

namespace mcdda {

/// A point fixed in an element: its corner nodes and their weights (barycentric coordinates).
struct BoltAnchor {
    int element = -1;
    std::array<int, 3> nodes{-1, -1, -1};
    std::array<double, 3> weights{0.0, 0.0, 0.0};
};

/// The element of `mesh` (among those flagged in `active`, all when empty) containing `p`, on
/// coordinates `nodes`; nothing when `p` lies in no element.
std::optional<BoltAnchor> locate_anchor(const Mesh& mesh, const std::vector<Point2>& nodes, Point2 p,
                                        const std::vector<char>& active = {});

/// One step's linearisation of a bolt: elongation = g·d over the six anchor nodes, in the order
/// (from-anchor corners, to-anchor corners), each node x then y.
struct BoltLink {
    std::array<int, 6> nodes{};
    Eigen::Matrix<double, 12, 1> g;
    double stiffness = 0.0;  ///< EA / L (N/m per m thickness)
    double force = 0.0;      ///< axial force at the start of the step, tension positive (N/m)
    /// Large displacements: the tensioned bolt's force turns with it. Its lateral stiffness
    /// N/L acts on the sideways relative displacement h·d (the truss's geometric stiffness);
    /// taken with the step's start direction alone, a pendulum hanging on a bolt overshoots
    /// and swings ever wider under static DDA's large steps.
    Eigen::Matrix<double, 12, 1> h;
    double geometric = 0.0;  ///< N / L (N/m per m thickness); 0 in small-strain analyses
    int bolt = -1;           ///< the Model::bolts entry it stands for

    /// Axial force after increments `d` (full displacement vector, 2 per node).
    double force_after(const Eigen::VectorXd& d) const;
    /// Adds the bolt's pull on its anchors after increments `d` to `force` (out-of-balance sense:
    /// a bolt in tension pulls its ends together).
    void add_forces(const Eigen::VectorXd& d, Eigen::VectorXd& force) const;
    /// The linearised stiffness over the twelve degrees of freedom (column-major).
    Eigen::Matrix<double, 12, 12> matrix() const { return stiffness * g * g.transpose() + geometric * h * h.transpose(); }
};

/// The link of a bolt anchored at `from` and `to` on coordinates `nodes` (its direction and
/// length there), spring EA / `length`, carrying `force`; with its geometric stiffness when
/// `large_displacements`.
BoltLink make_bolt_link(const BoltAnchor& from, const BoltAnchor& to, const std::vector<Point2>& nodes,
                        double axial_stiffness, double length, double force, bool large_displacements);

/// The anchor's position on coordinates `nodes`.
Point2 anchor_position(const BoltAnchor& a, const std::vector<Point2>& nodes);

}  // namespace mcdda
