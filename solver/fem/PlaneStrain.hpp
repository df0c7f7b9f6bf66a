#pragma once
/// \file PlaneStrain.hpp
/// The three-node triangle (CST) in plane strain, thickness 1: B, stiffness, mass, stresses (D is
/// material/Elasticity.hpp).
/// Voigt order (xx, yy, xy) with engineering shear strain γxy; stress tension positive.

#include "material/Elasticity.hpp"  // D, for the element matrices
#include "model/Model.hpp"

#include <Eigen/Dense>

namespace mcdda {

using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using StrainMatrix = Eigen::Matrix<double, 3, 6>;

/// Area and strain–displacement matrix of a triangle (nodes counter-clockwise).
struct TriangleShape {
    double area = 0.0;  ///< m², positive for counter-clockwise nodes
    StrainMatrix B;     ///< ε = B·(u1, v1, u2, v2, u3, v3)
};

TriangleShape triangle_shape(const Point2& a, const Point2& b, const Point2& c);

/// Consistent mass of one direction, ρA/12·[[2,1,1],[1,2,1],[1,1,2]], per unit density·area.
inline double consistent_mass_factor(int i, int j) { return (i == j ? 2.0 : 1.0) / 12.0; }

}  // namespace mcdda
