#include "material/MaterialLaws.hpp"

#include "material/ElasticLaw.hpp"
#include "material/HoekBrown.hpp"
#include "material/MohrCoulomb.hpp"

#include <limits>

namespace mcdda {

const std::vector<const MaterialLaw*>& material_laws() {
    // One line per law; the first is the default.
    static const std::vector<const MaterialLaw*> laws{
        &mohr_coulomb_law(),
        &hoek_brown_law(),
        &elastic_law(),
    };
    return laws;
}

const MaterialLaw* find_material_law(const std::string& key) {
    for (const MaterialLaw* law : material_laws())
        if (key == law->key) return law;
    return nullptr;
}

std::string material_law_keys() {
    std::string keys;
    for (const MaterialLaw* law : material_laws()) keys += (keys.empty() ? "\"" : ", \"") + std::string(law->key) + "\"";
    return keys;
}

double law_value(const Material& material, const NumberField& field) {
    return material.parameter(field.key, field.default_value.value_or(std::numeric_limits<double>::quiet_NaN()));
}

std::unique_ptr<ConstitutiveLaw> make_constitutive_law(const Material& material, bool plasticity) {
    const MaterialLaw* law = find_material_law(material.law);
    if (plasticity && law && law->create) return law->create(material);
    return std::make_unique<ElasticLaw>(material.young_modulus, material.poisson_ratio);
}

}  // namespace mcdda
