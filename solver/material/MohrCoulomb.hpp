#pragma once
/// \file MohrCoulomb.hpp
/// Mohr–Coulomb perfect plasticity with non-associated flow and an optional tension cut-off, in
/// plane strain with σzz kept. The return mapping is exact and works in principal stresses (de
/// Souza Neto, Perić & Owen, Computational Methods for Plasticity, ch. 8): the trial stress is
/// projected, along the elastic image of the flow directions, onto the plane, an edge or the apex
/// of the yield surface, whichever is consistent. A const object: it owns no per-point state.
///
/// Sign convention: tension positive. Yield (paper eq. 20, here doubled):
///   f = (σ1 − σ3) + (σ1 + σ3) sin φ − 2 c cos φ ≤ 0,  σ1 ≥ σ2 ≥ σ3 including σzz,
/// plastic potential g: the same with ψ; tension cut-off σ1 ≤ σt when σt > 0.

#include "model/Model.hpp"

#include <Eigen/Dense>

#include <array>

namespace mcdda {

/// A plane-strain stress state: σxx, σyy, τxy, σzz (Pa, tension positive).
struct PlaneStress {
    double xx = 0.0, yy = 0.0, xy = 0.0, zz = 0.0;
};

/// What the return mapping did.
struct ReturnResult {
    PlaneStress stress;                  ///< returned stress (the trial stress when elastic)
    bool plastic = false;                ///< the trial stress was outside the yield surface
    double equivalent_plastic_strain = 0.0;  ///< √(2/3 Δεp:Δεp) of this return
    int active_surfaces = 0;             ///< 1 plane, 2 edge, 3 apex (or cut-off combinations)
};

class MohrCoulomb {
public:
    MohrCoulomb(double young_modulus, double poisson_ratio, double cohesion, double friction_angle,
                double dilation_angle, double tensile_strength);
    explicit MohrCoulomb(const Material& m);

    /// Yield function of a stress (Pa): > 0 outside the surface. Includes the cut-off, if any,
    /// as max(f_MC, σ1 − σt) scaled to the same units.
    double yield(const PlaneStress& s) const;

    /// Returns the trial stress onto the yield surface (or leaves it when inside).
    ReturnResult return_map(const PlaneStress& trial) const;
    // TEMPORARY shim until the tangent lands: elastic tangent.
    ReturnResult return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const {
        if (tangent) {
            const double l = lambda_, g = shear_modulus_;
            *tangent << l + 2 * g, l, 0, l, l + 2 * g, 0, 0, 0, g;
        }
        return return_map(trial);
    }

    /// Principal stresses (σ1 ≥ σ2 ≥ σ3) of a plane-strain state.
    static std::array<double, 3> principal(const PlaneStress& s);

    /// A tolerance (Pa) below which f counts as zero: 1e-10 of the material's stress scale.
    double tolerance() const { return tolerance_; }

private:
    double lambda_, shear_modulus_;
    double cohesion_, sin_phi_, cos_phi_, sin_psi_;
    double tensile_strength_;
    double tolerance_;
};

}  // namespace mcdda
