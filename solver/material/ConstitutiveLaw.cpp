#include "material/ConstitutiveLaw.hpp"

#include "material/Elasticity.hpp"
#include "material/ElasticLaw.hpp"
#include "material/MohrCoulomb.hpp"

namespace mcdda {

ElasticLaw::ElasticLaw(double young_modulus, double poisson_ratio)
    : elasticity_(plane_strain_elasticity(young_modulus, poisson_ratio)) {}

ReturnResult ElasticLaw::return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const {
    if (tangent) *tangent = elasticity_;
    ReturnResult r;
    r.stress = trial;
    return r;
}

std::unique_ptr<ConstitutiveLaw> make_constitutive_law(const Material& material, bool plasticity) {
    if (plasticity && material.plastic) return std::make_unique<MohrCoulomb>(material);
    return std::make_unique<ElasticLaw>(material.young_modulus, material.poisson_ratio);
}

}  // namespace mcdda
