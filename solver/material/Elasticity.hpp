#pragma once
/// \file Elasticity.hpp
/// Linear isotropic elasticity in plane strain: the stiffness every law starts from. Voigt order
/// (xx, yy, xy) with engineering shear strain γxy; stress tension positive.

#include <Eigen/Dense>

namespace mcdda {

/// Plane-strain elasticity matrix D (paper eq. 10–11), Pa.
Eigen::Matrix3d plane_strain_elasticity(double young_modulus, double poisson_ratio);

}  // namespace mcdda
