#include "material/ElasticLaw.hpp"

#include "material/Elasticity.hpp"

namespace mcdda {

ElasticLaw::ElasticLaw(double young_modulus, double poisson_ratio)
    : elasticity_(plane_strain_elasticity(young_modulus, poisson_ratio)) {}

ReturnResult ElasticLaw::return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const {
    if (tangent) *tangent = elasticity_;
    ReturnResult r;
    r.stress = trial;
    return r;
}

const MaterialLaw& elastic_law() {
    static const MaterialLaw law{
        "elastic", MCDDA_TRANSLATABLE("ModelFields", "Linear elastic"),
        MCDDA_TRANSLATABLE("ModelFields", "Stays elastic whatever the stress: a lining, a footing, a stiff inclusion"),
        {}, nullptr, nullptr, nullptr,
        [](const Material& m) -> std::unique_ptr<ConstitutiveLaw> {
            return std::make_unique<ElasticLaw>(m.young_modulus, m.poisson_ratio);
        },
    };
    return law;
}

}  // namespace mcdda
