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

#include "material/ConstitutiveLaw.hpp"
#include "material/MaterialLaw.hpp"
#include "model/Model.hpp"

#include <Eigen/Dense>

#include <array>

namespace mcdda {

class MohrCoulomb final : public ConstitutiveLaw {
public:
    MohrCoulomb(double young_modulus, double poisson_ratio, double cohesion, double friction_angle,
                double dilation_angle, double tensile_strength);
    explicit MohrCoulomb(const Material& m);

    /// Yield function of a stress (Pa): > 0 outside the surface. Includes the cut-off, if any,
    /// as max(f_MC, σ1 − σt) scaled to the same units.
    double yield(const PlaneStress& s) const;

    /// Returns the trial stress onto the yield surface (or leaves it when inside).
    ReturnResult return_map(const PlaneStress& trial) const;

    /// The same return; when `tangent` is not null it also receives the algorithmic (consistent)
    /// tangent dσ/dΔε, 3×3 in Voigt order (xx, yy, xy) with engineering shear strain, for a
    /// plane-strain increment (Δεzz = 0) of σtrial = σold + D Δε. It is the plane-strain D when
    /// elastic, symmetric for ψ = φ and not symmetric otherwise (the caller symmetrises, if it must).
    ReturnResult return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const override;

    const Eigen::Matrix3d& elasticity() const override { return plane_strain_; }
    bool may_yield() const override { return true; }
    bool symmetric_tangent() const override { return sin_psi_ == sin_phi_; }

    /// Principal stresses (σ1 ≥ σ2 ≥ σ3) of a plane-strain state.
    static std::array<double, 3> principal(const PlaneStress& s);

    /// A tolerance (Pa) below which f counts as zero: 1e-10 of the material's stress scale.
    double tolerance() const { return tolerance_; }

private:
    /// A yield plane in sorted principal-stress space (σ1 ≥ σ2 ≥ σ3): f = n·σ − k, flow along m;
    /// Dm = D m, the stress correction per unit multiplier.
    struct Plane {
        Eigen::Vector3d n, m, Dm;
        double k = 0.0;
    };

    /// An active set of planes whose system n_r·D m_c is regular, with its inverse (the top-left
    /// size × size block). The system depends on the material only, so it is inverted once.
    struct ActiveSet {
        int size = 0;
        std::array<int, 3> planes{};
        Eigen::Matrix3d inverse;
    };

    double lambda_, shear_modulus_;
    double cohesion_, sin_phi_, cos_phi_, sin_psi_;
    double tensile_strength_;
    double tolerance_;
    Eigen::Matrix3d elasticity_;   ///< D in principal space: λ11ᵀ + 2G I
    Eigen::Matrix3d plane_strain_; ///< D in Voigt order (xx, yy, xy)
    Eigen::Matrix3d compliance_;   ///< D⁻¹
    std::array<Plane, 6> planes_;  ///< Mohr–Coulomb 1–3, 1–2, 2–3, then the cut-off σ1, σ2, σ3
    int plane_count_ = 3;          ///< 6 with a cut-off
    std::array<ActiveSet, 41> sets_;  ///< the regular sets of ≤ 3 planes, by size, then by mask
    int set_count_ = 0;
};

/// Its declaration: "mohr-coulomb", with "cohesion", "friction_angle", "dilation_angle" and
/// "tensile_strength".
const MaterialLaw& mohr_coulomb_law();

}  // namespace mcdda
