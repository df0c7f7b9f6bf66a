#pragma once
/// \file MaterialLaws.hpp
/// Every constitutive law a material may name, and the law of a material.

#include "material/MaterialLaw.hpp"

#include <string>
#include <vector>

namespace mcdda {

/// The laws, in the order forms offer them; the first is the default of a material that names none.
const std::vector<const MaterialLaw*>& material_laws();

/// The law with key `key`; nullptr when there is none.
const MaterialLaw* find_material_law(const std::string& key);

/// The keys of every law, quoted and separated by commas, for messages: "\"mohr-coulomb\", …".
std::string material_law_keys();

/// The constitutive law that computes a material's stresses: its own law, or linear elasticity
/// when `plasticity` is off. The material must have passed the checks (check/ModelValidator).
std::unique_ptr<ConstitutiveLaw> make_constitutive_law(const Material& material, bool plasticity);

}  // namespace mcdda
