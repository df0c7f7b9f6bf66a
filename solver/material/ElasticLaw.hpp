#pragma once
/// \file ElasticLaw.hpp
/// Linear elasticity in plane strain: the trial stress is the stress, the tangent is D. For
/// materials marked `"plastic": false` and for analyses with plasticity off.

#include "material/ConstitutiveLaw.hpp"

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

}  // namespace mcdda
