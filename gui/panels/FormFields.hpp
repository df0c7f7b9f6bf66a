#pragma once
/// \file FormFields.hpp
/// Small helpers shared by the Properties dock's forms (PropertyEditor, LoadForm, MeshForm):
/// number fields with their unit, exact round trips of untouched values, status lines.

#include "model/Defaults.hpp"

#include <QString>

#include <functional>
#include <string>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QWidget;

namespace mcdda {
struct AnalysisSettings;
}

namespace mcdda::gui::form {

using mcdda::pi;
constexpr double deg = mcdda::degree;

inline QString to_qt(const std::string& s) { return QString::fromStdString(s); }

/// A number field with its unit shown after the value.
QDoubleSpinBox* number(const QString& name, const QString& unit, double min, double max, int decimals,
                       QWidget* parent);

/// Shows `value` (already in the field's unit) and remembers what was shown, so an untouched
/// field gives back the exact SI value instead of a rounded one.
void display(QDoubleSpinBox* box, double value);

/// The field's value converted to SI by `factor`, or `original` when the field is untouched.
double si(const QDoubleSpinBox* box, double original, double factor);

/// A stress field in the stress unit chosen (Results ▸ Units: kPa, or MPa): shows `pascal`
/// (already signed as the form shows it) and sets the field's unit.
void display_stress(QDoubleSpinBox* box, double pascal);
/// The stress field's value in Pa times `sign` (−1: the form shows compression positive), or
/// `original` when untouched.
double stress_value(const QDoubleSpinBox* box, double original, double sign = 1.0);

/// Says what a field means, in its tooltip and in Help ▸ What's This (Shift+F1).
void explain(QWidget* field, const QString& text);

/// A number field whose value 0 means "automatic" and reads so (e.g. the contact penalty).
void zero_is_automatic(QDoubleSpinBox* box);

/// Calls `apply` when Enter (Return) is pressed in `field`, a spin box or a line edit, after the
/// field has taken the text typed. Typed values are applied on Enter or the form's Apply button
/// only: leaving a field (clicking elsewhere, Tab) does not apply it behind the user's back.
void apply_on_enter(QWidget* field, std::function<void()> apply);

/// A word-wrapped, selectable status line under a form.
QLabel* status_label(const QString& name, QWidget* parent);

/// Shows `text` in `label`, red when it is a refusal.
void set_status(QLabel* label, const QString& text, bool error);

/// A number as text for a table cell: the shortest form that reads back to the same double.
QString cell_text(double value);

/// Reads a table cell: the user's locale first (without group separators, so "1.500" is never
/// 1500 in a German locale), then the C locale. False when the text is not a finite number.
bool cell_value(const QString& text, double* value);

/// The analysis type chooser of the model's and a stage's settings: static, dynamic, strength
/// reduction (static with `strength_reduction` set).
QComboBox* analysis_type_box(const QString& name, QWidget* parent);
void show_analysis_type(QComboBox* box, const AnalysisSettings& a);
void read_analysis_type(const QComboBox* box, AnalysisSettings& a);

}  // namespace mcdda::gui::form
