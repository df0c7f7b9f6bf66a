#pragma once
/// \file DiagnosticText.hpp
/// The model checker's messages as the window words them (Qt Core only): the item named in words
/// (`material "rock"`) instead of its JSON pointer (`/materials/0/young_modulus`), and a declared
/// field's range or limit restated with its label and in the units the forms show (DisplayUnits:
/// "Young's modulus must be positive (got −100 MPa)" rather than "(got -1e+08 Pa)"). The command
/// line keeps the solver's own format_diagnostic().

#include "model/Diagnostic.hpp"
#include "model/Model.hpp"
#include "model/ModelFields.hpp"

#include <QString>

#include <string>

namespace mcdda::gui {

/// The message of `d` about `model` in words and display units, without "error:".
QString diagnostic_text(const Model& model, const Diagnostic& d);

/// The same with "error: " or "warning: " before it, for the Messages dock.
QString diagnostic_line(const Model& model, const Diagnostic& d);

/// The item a JSON pointer names, in words: `material "rock"`, `stage "Excavate", analysis
/// settings`, `load table "ramp", point 2`; empty for the model as a whole or an unknown pointer.
QString item_words(const Model& model, const std::string& path);

/// A value of `quantity` (model units) in the unit the forms show, in the user's locale and
/// with a true minus sign: "−100 MPa", "35°", "0.6".
QString quantity_text(Quantity quantity, double model_value);

/// Whether `d` is the checker's "at least one region is required" of a model still empty: the
/// window then asks the user to draw one instead of reporting an error.
bool is_empty_model_notice(const Model& model, const Diagnostic& d);

/// The hint shown for an empty model.
QString empty_model_hint();

}  // namespace mcdda::gui
