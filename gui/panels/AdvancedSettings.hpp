#pragma once
/// \file AdvancedSettings.hpp
/// The analysis settings a geotechnical user meets first (steps, the factor of safety tolerance,
/// an earthquake's damping) apart from DDA's numerical ones (time step, penalty, dynamic ratio,
/// largest displacement per step, tolerances), which sit in a collapsed "Advanced" part of the
/// form, each with a sentence giving its default and what it does. Used by the Analysis tab and
/// the Stages dock alike.

#include "model/ModelFields.hpp"

#include <QString>

#include <vector>

class QFormLayout;
class QToolButton;
class QWidget;

namespace mcdda::gui::form {

/// The declared analysis fields shown in the form itself, and the numerical ones (Advanced).
const std::vector<RecordField<AnalysisSettings>>& everyday_analysis_fields();
const std::vector<RecordField<AnalysisSettings>>& numerical_analysis_fields();

/// Adds to `form` a toggle button "Advanced" (named `name`, unchecked: collapsed) and under it a
/// form of its own, hidden until the button is checked; returns that form.
QFormLayout* advanced_section(const QString& name, QFormLayout* form, QWidget* parent, QToolButton** toggle = nullptr);

/// Adds a small wrapped line under each field of `form` that has a declared field of `fields`
/// (named `prefix + key`): its default in the form's unit and its help sentence.
void add_default_notes(const std::vector<RecordField<AnalysisSettings>>& fields, const QString& prefix,
                       QFormLayout* form);

/// The label of the steps field: "Load steps" in a static analysis (a strength reduction too),
/// "Time steps" in a dynamic one.
QString steps_label(bool dynamic);

}  // namespace mcdda::gui::form
