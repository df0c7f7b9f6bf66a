#pragma once
/// \file DeclaredFields.hpp
/// A record's declared number fields (model/ModelFields.hpp) in a form: one field each, with the
/// declaration's label, unit, help text and meaning of 0, filled from the record and read back
/// into it. The Material, Joint material and Bolts forms are built this way, so a field declared
/// in the solver appears in its form without code here.

#include "model/ModelFields.hpp"

#include <QString>

#include <vector>

class QDoubleSpinBox;
class QFormLayout;
class QWidget;

namespace mcdda::gui::form {

/// A form field for `field`, named `prefix + key` (e.g. "material_cohesion"), added to `form`.
QDoubleSpinBox* declared_number(const NumberField& field, const QString& prefix, QFormLayout* form, QWidget* parent);

/// The factor from a quantity's form unit to the model's: model value = form value × factor.
double form_unit_factor(Quantity quantity);

/// Shows a model value (SI, radians) in the field in its form unit (MPa, kPa, °, kN/m³ …).
void display_declared(QDoubleSpinBox* box, const NumberField& field, double model_value);

/// The field's value as a model value; `original` when the field was not touched, so that an
/// untouched field never rounds the model's value.
double declared_value(const QDoubleSpinBox* box, const NumberField& field, double original);

/// The fields of one record type in a form.
template <class Record>
class DeclaredFields {
public:
    DeclaredFields(const std::vector<RecordField<Record>>& fields, const QString& prefix, QFormLayout* form,
                   QWidget* parent)
        : fields_(fields)
    {
        for (const RecordField<Record>& f : fields_) boxes_.push_back(declared_number(f.field, prefix, form, parent));
    }

    void show(const Record& record) const
    {
        for (std::size_t k = 0; k < fields_.size(); ++k)
            display_declared(boxes_[k], fields_[k].field, record.*fields_[k].member);
    }

    /// `record` with the fields' values (untouched ones keep `original`'s).
    void read(const Record& original, Record& record) const
    {
        for (std::size_t k = 0; k < fields_.size(); ++k)
            record.*fields_[k].member = declared_value(boxes_[k], fields_[k].field, original.*fields_[k].member);
    }

    const std::vector<QDoubleSpinBox*>& boxes() const { return boxes_; }

private:
    const std::vector<RecordField<Record>>& fields_;
    std::vector<QDoubleSpinBox*> boxes_;
};

}  // namespace mcdda::gui::form
