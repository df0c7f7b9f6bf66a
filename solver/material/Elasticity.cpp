#include "material/Elasticity.hpp"

namespace mcdda {

Eigen::Matrix3d plane_strain_elasticity(double E, double nu) {
    const double f = E / ((1.0 + nu) * (1.0 - 2.0 * nu));
    Eigen::Matrix3d D;
    D << f * (1.0 - nu), f * nu, 0.0,
         f * nu, f * (1.0 - nu), 0.0,
         0.0, 0.0, f * (1.0 - 2.0 * nu) / 2.0;
    return D;
}

}  // namespace mcdda
