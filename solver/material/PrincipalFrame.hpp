#pragma once
/// \file PrincipalFrame.hpp
/// The principal frame of a plane-strain stress, for return mappings of isotropic laws that work
/// on sorted principal stresses σ1 ≥ σ2 ≥ σ3 (σzz included): the sort, the way back to x, y, z
/// and the Voigt tangent from the derivative of the return in principal space. With isotropic
/// elasticity the return keeps the principal directions, so only the values change. Shared by
/// MohrCoulomb and HoekBrown; header-only, so that either law inlines it.

#include "material/ConstitutiveLaw.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace mcdda {

struct PrincipalFrame {
    /// cos²θ, sin²θ and sinθ cosθ of the major in-plane direction θ from x, from the Mohr circle;
    /// θ = 0 for an isotropic in-plane stress.
    double c2 = 1.0, s2 = 0.0, cs = 0.0;
    double values[3] = {0.0, 0.0, 0.0};  ///< a (major in-plane), b (minor in-plane), z
    int order[3] = {0, 1, 2};            ///< sorted slot i holds values[order[i]]
    Eigen::Vector3d sorted;              ///< σ1 ≥ σ2 ≥ σ3

    explicit PrincipalFrame(const PlaneStress& trial) {
        const double centre = 0.5 * (trial.xx + trial.yy);
        const double half_difference = 0.5 * (trial.xx - trial.yy);
        const double radius = std::hypot(half_difference, trial.xy);
        const double cos_2theta = radius > 0.0 ? half_difference / radius : 1.0;
        const double sin_2theta = radius > 0.0 ? trial.xy / radius : 0.0;
        c2 = 0.5 * (1 + cos_2theta);
        s2 = 0.5 * (1 - cos_2theta);
        cs = 0.5 * sin_2theta;
        values[0] = centre + radius;
        values[1] = centre - radius;
        values[2] = trial.zz;
        // Sorted descending, ties kept in a, b, z order (a ≥ b always, so only z moves).
        if (values[2] > values[0]) {
            order[0] = 2;
            order[1] = 0;
            order[2] = 1;
        } else if (values[2] > values[1]) {
            order[1] = 2;
            order[2] = 1;
        }
        sorted = Eigen::Vector3d(values[order[0]], values[order[1]], values[order[2]]);
    }

    /// The stress whose sorted principal values are `principal`, in this frame; `returned`
    /// receives them in the a, b, z slots (for tangent()).
    PlaneStress stress(const Eigen::Vector3d& principal, double returned[3]) const {
        for (int i = 0; i < 3; ++i) returned[order[i]] = principal[i];
        PlaneStress s;
        s.xx = returned[0] * c2 + returned[1] * s2;
        s.yy = returned[0] * s2 + returned[1] * c2;
        s.xy = (returned[0] - returned[1]) * cs;
        s.zz = returned[2];
        return s;
    }

    /// dσ/dΔε (3×3, Voigt order xx, yy, xy, engineering shear) of a plane-strain increment from
    /// the derivative of the return in sorted principal space, dσ/ds; `returned` as stress() gave
    /// it, `elasticity` the principal-space D = λ11ᵀ + 2G I, `tolerance` the law's stress zero.
    Eigen::Matrix3d tangent(const Eigen::Matrix3d& sorted_derivative, const double returned[3],
                            const Eigen::Matrix3d& elasticity, double shear_modulus, double tolerance) const {
        // dσ/ds in the a, b, z slots.
        Eigen::Matrix3d P;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) P(order[i], order[j]) = sorted_derivative(i, j);
        // In the eigenbasis (a, b, ab): the principal values respond through P D (Δεz = 0), the
        // shear through the turn of the principal axes, dτab = (σa − σb)/(sa − sb) · G dγab;
        // at coinciding a, b that ratio's limit is P_aa − P_ab.
        const Eigen::Matrix3d PD = P * elasticity;
        const double gap = values[0] - values[1];
        const double spin = gap > 1e-9 * (std::fabs(values[0]) + std::fabs(values[1])) + tolerance
                                ? (returned[0] - returned[1]) / gap
                                : 0.5 * (P(0, 0) - P(0, 1) + P(1, 1) - P(1, 0));
        Eigen::Matrix3d eigen_tangent;
        eigen_tangent << PD(0, 0), PD(0, 1), 0.0, PD(1, 0), PD(1, 1), 0.0, 0.0, 0.0, spin * shear_modulus;
        // Strain into the eigenbasis (engineering shear); stress back with its transpose.
        Eigen::Matrix3d R;
        R << c2, s2, cs, s2, c2, -cs, -2 * cs, 2 * cs, c2 - s2;
        return R.transpose() * eigen_tangent * R;
    }
};

}  // namespace mcdda
