#include "panels/FormFields.hpp"

#include <QCoreApplication>
#include <QDoubleSpinBox>
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

}  // namespace mcdda::gui::form
