#pragma once
/// \file ElasticLaw.hpp
/// Linear elasticity in plane strain: the trial stress is the stress, the tangent is D. The law
/// "elastic" (also what `"plastic": false` reads as) and every material of an analysis with
/// plasticity off.

#include "material/ConstitutiveLaw.hpp"
#include "material/MaterialLaw.hpp"

namespace mcdda {

class ElasticLaw final : public ConstitutiveLaw {
public:
    ElasticLaw(double young_modulus, double poisson_ratio);

    const Eigen::Matrix3d& elasticity() const override { return elasticity_; }
    ReturnResult return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const override;
    bool may_yield() const override { return false; }
    bool symmetric_tangent() const override { return true; }

private:
    Eigen::Matrix3d elasticity_;
};

/// Its declaration: no fields of its own.
const MaterialLaw& elastic_law();

}  // namespace mcdda
