#pragma once
/// \file MaterialLaw.hpp
/// What a constitutive law declares about itself, so that the model reader, writer and checker,
/// the strength reduction and the desktop program's Material form handle every law the same way:
/// its key in the model file ("law": "hoek-brown"), its own number fields (key, unit, range,
/// default, help: ModelFields.hpp's NumberField), the checks that involve more than one field,
/// how a strength reduction divides its strength, and how to build it. A law is one file that
/// defines its ConstitutiveLaw and its MaterialLaw, and one line in MaterialLaws.cpp
/// (docs/architecture.md, "How to add a material law").

#include "material/ConstitutiveLaw.hpp"
#include "model/ModelFields.hpp"
#include "model/Model.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mcdda {

/// A problem a law finds in a material's parameters: the field it is about ("" for the material
/// as a whole) and why.
struct LawProblem {
    std::string field;
    std::string message;
};

struct MaterialLaw {
    const char* key;    ///< the value of "law" in the model file, e.g. "mohr-coulomb"
    const char* label;  ///< in forms and messages, e.g. "Mohr–Coulomb" (translatable)
    const char* help;   ///< one sentence for the form's tooltip
    /// Its own number fields, beyond Young's modulus, Poisson's ratio and the unit weight that
    /// every material has (material_fields()); the values are kept in Material::parameters.
    std::vector<NumberField> fields;
    /// Problems that no single field's range can say (ψ ≤ φ), appended to `problems`; each
    /// field's own range and physical limit are checked by the caller. `plasticity`: whether
    /// the analysis lets materials yield at all.
    void (*check)(const Material& material, bool plasticity, std::vector<LawProblem>& problems) = nullptr;
    /// The material with its strength divided by `factor` (the strength reduction method); the
    /// caller leaves materials with `reduce` off alone. nullptr: nothing to reduce (elastic).
    Material (*reduced)(const Material& material, double factor, AnalysisSettings::NonAssociatedFlow flow) = nullptr;
    /// Whether its plastic flow is non-associated (the factor of safety then says how it was treated).
    bool (*non_associated)(const Material& material) = nullptr;
    /// The law of a material whose parameters passed the checks.
    std::unique_ptr<ConstitutiveLaw> (*create)(const Material& material) = nullptr;
};

/// The value of `field` in `material`: its parameter, else the field's default, else NaN (the
/// checker reports a required field that is missing before a law is built).
double law_value(const Material& material, const NumberField& field);

}  // namespace mcdda
