#pragma once
/// \file ModelFields.hpp
/// The number fields of materials, joint materials, bolts and analysis settings, each declared once: its key in the
/// model file, its name in messages, its label and help text in the desktop program's forms, its
/// quantity (which fixes its units in the file, the model and the forms), its default and the
/// values it may take. The reader, the writer, the validator and the forms all go through these
/// lists, so a new field is one more line here (and a member of the record).

#include "model/Model.hpp"

#include <optional>
#include <string>
#include <vector>

/// Marks a text of this file for translation: Qt's lupdate collects it (translations/ passes
/// `-tr-function-alias QT_TRANSLATE_NOOP+=MCDDA_TRANSLATABLE`), the solver keeps it as it is and
/// the desktop program translates it in the context "ModelFields".
#define MCDDA_TRANSLATABLE(context, text) text

namespace mcdda {

/// What a number measures. The file and the model hold SI units except angles (degrees in the
/// file, radians in the model); the forms show the unit field_form_unit() of the desktop program.
enum class Quantity {
    Ratio,      ///< dimensionless
    Modulus,    ///< Pa
    Stress,     ///< Pa
    Density,    ///< kg/m³ (the forms show the unit weight γ = ρ g)
    Angle,      ///< degrees in the file, radians in the model
    Stiffness,  ///< N/m per metre of model thickness
    Force,      ///< N/m per metre of model thickness
    Time,       ///< s
    Frequency,  ///< Hz
};

/// One end of the values a field may take.
struct Bound {
    double value = 0.0;  ///< in the model's unit (radians for angles)
    bool inclusive = true;
};

/// The declaration of one number field.
struct NumberField {
    const char* key;    ///< in the model file, e.g. "young_modulus"
    const char* name;   ///< in messages, e.g. "Young's modulus"
    const char* label;  ///< in forms, e.g. "Young's modulus E"
    Quantity quantity;
    std::optional<double> default_value;  ///< in the model's unit; none: the file must give it
    std::optional<Bound> lower, upper;    ///< the values allowed
    double physical_limit = 0.0;          ///< |value| beyond this is a unit error (0: no limit)
    const char* zero_means = nullptr;     ///< what 0 stands for, e.g. "automatic"; nullptr: just 0
    const char* help = "";                ///< one sentence for tooltips and What's This
};

/// A field of the record `Record` and the member holding it.
template <class Record>
struct RecordField {
    NumberField field;
    double Record::*member;
};

/// The fields every material has (elasticity and weight); a law's own fields are declared by the
/// law (material/MaterialLaw.hpp).
const std::vector<RecordField<Material>>& material_fields();
const std::vector<RecordField<JointMaterial>>& joint_material_fields();
const std::vector<RecordField<Bolt>>& bolt_fields();
/// The number settings of an analysis (the whole-number and choice settings — steps, type,
/// geometry, iterations — are read and written by hand). A stage's analysis starts from the
/// model's, so the reader takes an absent setting from the record, not from default_value.
const std::vector<RecordField<AnalysisSettings>>& analysis_fields();

/// Whether `a` and `b` agree in every declared field.
template <class Record>
bool same_fields(const Record& a, const Record& b, const std::vector<RecordField<Record>>& fields)
{
    for (const RecordField<Record>& f : fields)
        if (!(a.*f.member == b.*f.member)) return false;
    return true;
}

/// A value of the model in the file's unit, and back. Angles go to the shortest decimal number
/// of degrees that reads back to exactly the same radians (30°, not 29.999999999999996°).
double to_file_unit(Quantity quantity, double model_value);
double from_file_unit(Quantity quantity, double file_value);

/// A value for messages with its unit: "95°", "-5e+09 Pa", "0.6".
std::string value_text(Quantity quantity, double model_value);

/// Empty when `value` is allowed; else why not, e.g. "friction angle must lie in [0°, 90°) (got
/// 95°)" or "normal stiffness must not be negative (got -1 N/m; 0 = automatic)".
std::string range_error(const NumberField& field, double value);

/// Empty when |value| is within the field's physical limit; else a message that suspects units.
std::string limit_error(const NumberField& field, double value);

}  // namespace mcdda
