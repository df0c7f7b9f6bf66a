#pragma once
/// \file HoekBrown.hpp
/// The generalised Hoek–Brown criterion (Hoek, Carranza-Torres & Corkum, Hoek–Brown failure
/// criterion – 2002 edition, Proc. NARMS-TAC 2002) as perfect plasticity in plane strain with σzz
/// kept, a plastic potential linear in the principal stresses (Carranza-Torres & Fairhurst, Int. J.
/// Rock Mech. Min. Sci. 36 (1999) 777–809) and an optional tension cut-off. The return mapping is
/// exact and works in sorted principal stresses, as for Mohr–Coulomb (Clausen & Damkilde, An exact
/// implementation of the Hoek–Brown criterion for elasto-plastic finite element calculations, Int.
/// J. Rock Mech. Min. Sci. 45 (2008) 831–847): the trial stress goes, along the elastic image of
/// the flow directions, onto the curved surface, one of its edges, its apex or the cut-off,
/// whichever is consistent. A const object: it owns no per-point state.
///
/// Sign convention: tension positive. With σ1 ≥ σ2 ≥ σ3 (σzz included) the compressive major and
/// minor stresses are σ1c = −σ3 and σ3c = −σ1, and σ1c − σ3c − σci (mb σ3c/σci + s)^a ≤ 0 reads
///   f = (σ1 − σ3) − σci (s − mb σ1/σci)^a ≤ 0,   σ1 ≤ s σci/mb (the apex, in hydrostatic tension);
/// plastic potential g = σ1c − Kψ σ3c = Kψ σ1 − σ3, Kψ = (1 + sin ψ)/(1 − sin ψ), so the flow is
/// never associated; tension cut-off σ1 ≤ σt when 0 < σt < s σci/mb.

#include "material/ConstitutiveLaw.hpp"
#include "material/MaterialLaw.hpp"

#include <Eigen/Dense>

#include <array>

namespace mcdda {

/// The rock-mass constants of the generalised criterion.
struct HoekBrownParameters {
    double mb = 1.0;  ///< reduced value of the intact-rock constant mi
    double s = 1.0;   ///< 1 for intact rock
    double a = 0.5;   ///< 0.5 for intact rock, up to 2/3 for very poor rock masses
};

/// mb, s and a from the Geological Strength Index, the intact-rock constant mi and the
/// disturbance factor D (Hoek, Carranza-Torres & Corkum 2002):
///   mb = mi exp((GSI − 100)/(28 − 14D)),  s = exp((GSI − 100)/(9 − 3D)),
///   a = 1/2 + (exp(−GSI/15) − exp(−20/3))/6.
/// Throws std::invalid_argument unless 0 ≤ GSI ≤ 100, mi > 0 and 0 ≤ D ≤ 1.
HoekBrownParameters hoek_brown_parameters(double gsi, double mi, double disturbance);

/// The tensile strength s σci/mb (Pa, positive): the hydrostatic tension of the apex, which
/// Hoek et al. (2002) also take as the uniaxial tensile strength (their σt = −s σci/mb).
double hoek_brown_tensile_strength(double sigma_ci, double mb, double s);

class HoekBrown final : public ConstitutiveLaw {
public:
    /// `uniaxial_strength` σci (Pa) of the intact rock; `dilation_angle` ψ (rad, 0 ≤ ψ < π/2);
    /// `tensile_strength` a cut-off σt on σ1 (Pa): 0, or anything not below s σci/mb, keeps the
    /// Hoek–Brown apex alone. Throws std::invalid_argument for parameters out of range (E ≤ 0,
    /// ν outside (−1, 0.5), σci ≤ 0, mb ≤ 0, s outside [0, 1], a outside (0, 1], ψ outside
    /// [0, π/2), σt < 0).
    HoekBrown(double young_modulus, double poisson_ratio, double uniaxial_strength,
              const HoekBrownParameters& parameters, double dilation_angle, double tensile_strength);

    /// Yield function of a stress (Pa): > 0 outside the surface. Beyond the apex (σ1 > s σci/mb,
    /// where the criterion is not defined) it is (σ1 − σ3) + (σ1 − s σci/mb); with a cut-off it is
    /// max(f, σ1 − σt).
    double yield(const PlaneStress& s) const;

    /// Returns the trial stress onto the yield surface (or leaves it when inside).
    ReturnResult return_map(const PlaneStress& trial) const;

    /// The same return; when `tangent` is not null it also receives the algorithmic (consistent)
    /// tangent dσ/dΔε, 3×3 in Voigt order (xx, yy, xy) with engineering shear strain, for a
    /// plane-strain increment (Δεzz = 0) of σtrial = σold + D Δε: the plane-strain D when elastic,
    /// not symmetric otherwise. Never throws; finite trial stresses give finite results.
    ReturnResult return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const override;

    const Eigen::Matrix3d& elasticity() const override { return plane_strain_; }
    bool may_yield() const override { return true; }
    bool symmetric_tangent() const override { return false; }

    /// The largest σ1 the material carries (Pa): the cut-off when there is one, the apex otherwise.
    double tensile_limit() const { return cut_off_ > 0.0 ? cut_off_ : apex_; }

    /// A tolerance (Pa) below which f counts as zero: 1e-10 of the material's stress scale.
    double tolerance() const { return tolerance_; }

private:
    /// A return onto an edge or corner whose stress components `rows` are fixed (the cut-off, and
    /// the Hoek–Brown condition where σ1 is fixed by it): the multipliers of the flows solve a
    /// linear system that depends on the material only, inverted once.
    struct Corner {
        int size = 0;
        std::array<int, 3> rows{};
        Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< the fixed values, by row
        Eigen::Matrix3d flows = Eigen::Matrix3d::Zero();   ///< flow directions m, by column
        Eigen::Matrix3d inverse = Eigen::Matrix3d::Zero(); ///< (rows of D M)⁻¹, size × size
        Eigen::Matrix3d derivative = Eigen::Matrix3d::Zero();  ///< dσ/ds = I − D M A⁻¹ Nᵀ
    };

    /// One way of returning a trial stress, in sorted principal space.
    struct Return {
        Eigen::Vector3d stress = Eigen::Vector3d::Zero(), flow = Eigen::Vector3d::Zero();
        Eigen::Matrix3d derivative = Eigen::Matrix3d::Zero();  ///< dσ/ds, when asked for
        int size = 0;
    };

    /// 0 the main surface (σ1, σ3), 1 the edge σ1 = σ2, 2 the edge σ2 = σ3.
    bool smooth_return(int kind, const Eigen::Vector3d& s, bool derivative, Return& out) const;
    bool corner_return(const Corner& corner, const Eigen::Vector3d& s, Return& out) const;
    /// max(f, σ1 − σt) of sorted principal stresses.
    double violation(const Eigen::Vector3d& x) const;
    /// Ordered (σ1 ≥ σ2 ≥ σ3) and on or inside every surface, to the return's rounding.
    bool admissible(const Eigen::Vector3d& x) const;

    double lambda_, shear_modulus_;
    double sigma_ci_;
    HoekBrownParameters hb_;
    double k_psi_;
    double apex_;         ///< s σci/mb
    double cut_off_;      ///< σt when below the apex, else 0 (none)
    double tolerance_;
    Eigen::Matrix3d elasticity_;    ///< D in principal space: λ11ᵀ + 2G I
    Eigen::Matrix3d plane_strain_;  ///< D in Voigt order (xx, yy, xy)
    Eigen::Matrix3d compliance_;    ///< D⁻¹
    /// Per smooth kind: the flow Γ m̄ + δ d with δ = w·s fixed by the edge, D m̄, D d.
    std::array<Eigen::Vector3d, 3> mean_flow_, fixed_flow_, weight_, d_mean_flow_, d_fixed_flow_;
    std::array<Corner, 8> corners_;  ///< with a cut-off: by size, then as Mohr–Coulomb orders its planes
    int corner_count_ = 0;
};

/// Its declaration: "hoek-brown", with "uniaxial_strength", "gsi", "mi", "disturbance",
/// "dilation_angle" and "tensile_strength".
const MaterialLaw& hoek_brown_law();

}  // namespace mcdda
