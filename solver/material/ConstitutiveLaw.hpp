#pragma once
/// \file ConstitutiveLaw.hpp
/// What element assembly needs from a material: its elastic stiffness, the return of a trial
/// stress onto what the material can carry, and the algorithmic tangent of that return. Mohr–
/// Coulomb (MohrCoulomb.hpp), Hoek–Brown (HoekBrown.hpp) and linear elasticity (ElasticLaw.hpp)
/// implement it; make_constitutive_law (MaterialLaws.hpp) picks one per material. Laws are
/// const: they hold no per-point state.

#include "model/Model.hpp"

#include <Eigen/Dense>

#include <memory>

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

class ConstitutiveLaw {
public:
    virtual ~ConstitutiveLaw() = default;

    /// Plane-strain elastic stiffness D in Voigt order (xx, yy, xy), engineering shear strain.
    virtual const Eigen::Matrix3d& elasticity() const = 0;

    /// The stress the material reaches from the elastic trial σtrial = σold + D Δε (plane strain,
    /// Δεzz = 0); with `tangent` not null also dσ/dΔε (3×3, Voigt order).
    virtual ReturnResult return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const = 0;

    /// False for a law that never leaves the elastic range.
    virtual bool may_yield() const = 0;

    /// True when the tangent is symmetric (associated flow): a Cholesky factor can use it.
    virtual bool symmetric_tangent() const = 0;
};

}  // namespace mcdda
