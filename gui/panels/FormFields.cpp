#include "panels/FormFields.hpp"

#include "panels/DeclaredFields.hpp"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QVariant>

#include <cmath>

namespace mcdda::gui::form {

QDoubleSpinBox* number(const QString& name, const QString& unit, double min, double max, int decimals,
                       QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(min, max);
    box->setDecimals(decimals);
    box->setKeyboardTracking(false);
    box->setAccelerated(true);
    if (!unit.isEmpty()) box->setSuffix(QLatin1Char(' ') + unit);
    return box;
}

void display(QDoubleSpinBox* box, double value)
{
    box->setValue(value);
    box->setProperty("shown", box->value());
}

double si(const QDoubleSpinBox* box, double original, double factor)
{
    const QVariant shown = box->property("shown");
    if (shown.isValid() && shown.toDouble() == box->value()) return original;
    return box->value() * factor;
}

void explain(QWidget* field, const QString& text)
{
    field->setToolTip(text);
    field->setWhatsThis(text);
}

void zero_is_automatic(QDoubleSpinBox* box)
{
    box->setMinimum(0.0);  // below 0 means nothing: the validator refuses it anyway
    box->setSpecialValueText(QCoreApplication::translate("mcdda::gui::form", "automatic"));
}

QLabel* status_label(const QString& name, QWidget* parent)
{
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

void set_status(QLabel* label, const QString& text, bool error)
{
    label->setStyleSheet(error ? QStringLiteral("color: #b00020;") : QString());
    label->setText(text);
}

QString cell_text(double value)
{
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);  // cell_value rejects them
    return locale.toString(value, 'g', QLocale::FloatingPointShortest);
}

bool cell_value(const QString& text, double* value)
{
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::RejectGroupSeparator);
    const QString trimmed = text.trimmed();
    bool ok = false;
    double v = locale.toDouble(trimmed, &ok);
    if (!ok) {
        QLocale c = QLocale::c();
        c.setNumberOptions(c.numberOptions() | QLocale::RejectGroupSeparator);
        v = c.toDouble(trimmed, &ok);
    }
    if (!ok || !std::isfinite(v)) return false;
    *value = v;
    return true;
}

// --- declared fields (DeclaredFields.hpp) -----------------------------------------------------

namespace {

/// How a form shows a quantity: model value = shown value × factor.
struct FormUnit {
    const char* unit;  ///< translated in the context "mcdda::gui::form"
    double factor;
    double range;  ///< the field accepts ±range; the validator says what is allowed within it
    int decimals;
};

FormUnit form_unit(Quantity quantity)
{
    switch (quantity) {
    case Quantity::Ratio: return {"", 1.0, 10.0, 4};
    case Quantity::Modulus: return {QT_TRANSLATE_NOOP("mcdda::gui::form", "MPa"), 1e6, 1e9, 3};
    case Quantity::Stress: return {QT_TRANSLATE_NOOP("mcdda::gui::form", "kPa"), 1e3, 1e9, 3};
    case Quantity::Density: return {QT_TRANSLATE_NOOP("mcdda::gui::form", "kN/m³"), 1e3 / standard_gravity, 1e4, 3};
    case Quantity::Angle: return {QT_TRANSLATE_NOOP("mcdda::gui::form", "°"), degree, 360.0, 3};
    case Quantity::Stiffness: return {QT_TRANSLATE_NOOP("mcdda::gui::form", "MN/m"), 1e6, 1e9, 3};
    case Quantity::Force: return {QT_TRANSLATE_NOOP("mcdda::gui::form", "kN/m"), 1e3, 1e9, 3};
    }
    return {"", 1.0, 1e9, 3};
}

}  // namespace

QDoubleSpinBox* declared_number(const NumberField& field, const QString& prefix, QFormLayout* form, QWidget* parent)
{
    const FormUnit u = form_unit(field.quantity);
    const QString unit = *u.unit ? QCoreApplication::translate("mcdda::gui::form", u.unit) : QString();
    QDoubleSpinBox* box = number(prefix + QString::fromLatin1(field.key), unit, -u.range, u.range, u.decimals, parent);
    if (field.quantity == Quantity::Ratio) box->setSingleStep(0.01);
    QString label = QCoreApplication::translate("ModelFields", field.label);
    if (unit.isEmpty()) label += QStringLiteral(" [–]");
    form->addRow(label, box);
    explain(box, QCoreApplication::translate("ModelFields", field.help));
    if (field.zero_means && field.lower && field.lower->value == 0.0 && field.lower->inclusive) {
        box->setMinimum(0.0);  // below 0 means nothing: the validator would refuse it anyway
        box->setSpecialValueText(QCoreApplication::translate("ModelFields", field.zero_means));
    }
    return box;
}

double form_unit_factor(Quantity quantity) { return form_unit(quantity).factor; }

void display_declared(QDoubleSpinBox* box, const NumberField& field, double model_value)
{
    display(box, model_value / form_unit(field.quantity).factor);
}

double declared_value(const QDoubleSpinBox* box, const NumberField& field, double original)
{
    return si(box, original, form_unit(field.quantity).factor);
}

}  // namespace mcdda::gui::form
