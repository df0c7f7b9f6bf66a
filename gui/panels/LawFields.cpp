#include "panels/LawFields.hpp"

#include "material/MaterialLaws.hpp"
#include "panels/DeclaredFields.hpp"
#include "panels/FormFields.hpp"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>

#include <cmath>

namespace mcdda::gui::form {

LawFields::LawFields(const QString& prefix, QFormLayout* form, QWidget* parent) : form_(form)
{
    chooser_ = new QComboBox(parent);
    chooser_->setObjectName(QStringLiteral("materialLaw"));
    QString help;
    for (const MaterialLaw* law : material_laws()) {
        chooser_->addItem(QCoreApplication::translate("ModelFields", law->label), QString::fromLatin1(law->key));
        help += QStringLiteral("<p><b>%1</b>: %2</p>")
                    .arg(QCoreApplication::translate("ModelFields", law->label),
                         QCoreApplication::translate("ModelFields", law->help));
    }
    form->addRow(QCoreApplication::translate("ModelFields", "Law"), chooser_);
    explain(chooser_, help);
    for (const MaterialLaw* law : material_laws()) {
        const QString law_prefix = prefix + QString::fromLatin1(law->key).replace(QLatin1Char('-'), QLatin1Char('_')) + QLatin1Char('_');
        LawRows rows{law, {}};
        for (const NumberField& f : law->fields) rows.boxes.push_back(declared_number(f, law_prefix, form, parent));
        laws_.push_back(std::move(rows));
    }
}

const LawFields::LawRows* LawFields::chosen() const
{
    const QString key = chooser_->currentData().toString();
    for (const LawRows& rows : laws_)
        if (key == QLatin1String(rows.law->key)) return &rows;
    return nullptr;
}

void LawFields::showChosenLaw()
{
    const LawRows* shown = chosen();
    for (const LawRows& rows : laws_)
        for (QDoubleSpinBox* box : rows.boxes) form_->setRowVisible(box, &rows == shown);
}

void LawFields::show(const Material& material)
{
    chooser_->setCurrentIndex(std::max(0, chooser_->findData(QString::fromStdString(material.law))));
    for (const LawRows& rows : laws_)
        for (std::size_t k = 0; k < rows.boxes.size(); ++k) {
            // A field the material does not have (another law's) shows its default, or 0.
            const double value = law_value(material, rows.law->fields[k]);
            display_declared(rows.boxes[k], rows.law->fields[k], std::isnan(value) ? 0.0 : value);
        }
    showChosenLaw();
}

void LawFields::read(const Material& original, Material& material) const
{
    const LawRows* rows = chosen();
    if (!rows) return;
    material.law = rows->law->key;
    for (std::size_t k = 0; k < rows->boxes.size(); ++k) {
        const NumberField& f = rows->law->fields[k];
        const double kept = law_value(original, f);
        material.parameters[f.key] = declared_value(rows->boxes[k], f, std::isnan(kept) ? 0.0 : kept);
    }
}

std::vector<QDoubleSpinBox*> LawFields::boxes() const
{
    std::vector<QDoubleSpinBox*> all;
    for (const LawRows& rows : laws_) all.insert(all.end(), rows.boxes.begin(), rows.boxes.end());
    return all;
}

}  // namespace mcdda::gui::form
