#pragma once
/// \file LawFields.hpp
/// A material's constitutive law in a form: a chooser of the laws the solver declares
/// (material/MaterialLaws.hpp) and, below it, exactly the number fields of the chosen law, each
/// with its declared label, unit, help text and meaning of 0. A law added to the solver appears
/// here without code in the desktop program.

#include "model/Model.hpp"

#include <QString>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QWidget;

namespace mcdda {
struct MaterialLaw;
}

namespace mcdda::gui::form {

class LawFields {
public:
    /// The chooser ("materialLaw") and one field per law and parameter, named
    /// `prefix + law + "_" + key` with the law's dashes as underscores ("material_hoek_brown_gsi").
    LawFields(const QString& prefix, QFormLayout* form, QWidget* parent);

    /// Shows the material's law and its parameters; the other laws' fields are hidden.
    void show(const Material& material);

    /// `material` with the chosen law and its fields' values; fields left untouched keep
    /// `original`'s values, those the original law did not have take the field's default.
    void read(const Material& original, Material& material) const;

    /// Shows the fields of the law chosen now (a new choice, before it is applied).
    void showChosenLaw();

    QComboBox* chooser() const { return chooser_; }
    /// Every law's fields, for connecting their signals.
    std::vector<QDoubleSpinBox*> boxes() const;

private:
    struct LawRows {
        const MaterialLaw* law;
        std::vector<QDoubleSpinBox*> boxes;  ///< by the law's fields
    };
    const LawRows* chosen() const;

    QFormLayout* form_;
    QComboBox* chooser_;
    std::vector<LawRows> laws_;
};

}  // namespace mcdda::gui::form
