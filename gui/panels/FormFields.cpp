#include "panels/FormFields.hpp"

#include "model/Model.hpp"
#include "panels/DeclaredFields.hpp"
#include "session/DisplayUnits.hpp"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QVariant>

#include <algorithm>
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

namespace {

/// Sees Enter in a spin box (which has no returnPressed signal): the box handles the key first
/// (it interprets the text and fixes the value), then the form applies it.
class EnterFilter : public QObject {
public:
    EnterFilter(QWidget* field, std::function<void()> apply) : QObject(field), apply_(std::move(apply))
    {
        field->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::KeyPress || busy_) return false;
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key != Qt::Key_Return && key != Qt::Key_Enter) return false;
        busy_ = true;
        watched->event(event);
        busy_ = false;
        apply_();
        return true;
    }

private:
    std::function<void()> apply_;
    bool busy_ = false;
};

}  // namespace

void apply_on_enter(QWidget* field, std::function<void()> apply)
{
    if (auto* line = qobject_cast<QLineEdit*>(field)) {
        QObject::connect(line, &QLineEdit::returnPressed, line, std::move(apply));
        return;
    }
    new EnterFilter(field, std::move(apply));
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

/// How a form shows a quantity: model value = shown value × factor. Stresses and moduli follow
/// the units chosen (DisplayUnits); the rest is fixed.
struct FormUnit {
    QString unit;
    double factor;
    double range;  ///< the field accepts ±range; the validator says what is allowed within it
    int decimals;
};

FormUnit form_unit(Quantity quantity)
{
    // Units and factors are DisplayUnits' (the messages use the same); ranges and decimals are the form's.
    const DisplayUnits* units = DisplayUnits::instance();
    const QString unit = units->unitOf(quantity);
    const double factor = units->factorOf(quantity);
    switch (quantity) {
    case Quantity::Ratio: return {unit, factor, 10.0, 6};
    case Quantity::Modulus: return {unit, factor, 1e15 / factor, 3};
    case Quantity::Stress: return {unit, factor, 1e12 / factor, factor > 1e3 ? 6 : 3};  // 1 kPa steps in MPa too
    case Quantity::Density: return {unit, factor, 1e4, 3};
    case Quantity::Angle: return {unit, factor, 360.0, 3};
    case Quantity::Stiffness: return {unit, factor, 1e9, 3};
    case Quantity::Force: return {unit, factor, 1e9, 3};
    case Quantity::Time: return {unit, factor, 1e6, 6};
    case Quantity::Frequency: return {unit, factor, 1e6, 3};
    }
    return {QString(), 1.0, 1e9, 3};
}

/// Gives `box` the unit, decimals and range of `u` (the unit may have changed since).
void set_unit(QDoubleSpinBox* box, const FormUnit& u)
{
    box->setSuffix(u.unit.isEmpty() ? QString() : QLatin1Char(' ') + u.unit);
    box->setDecimals(u.decimals);
    box->setMaximum(u.range);
    if (box->minimum() != 0.0) box->setMinimum(-u.range);  // "0 = automatic" fields stay at 0
}

}  // namespace

/// The form unit of a field, its range wide enough for the field's own bounds (GSI up to 100).
FormUnit field_unit(const NumberField& field)
{
    FormUnit u = form_unit(field.quantity);
    if (field.upper) u.range = std::max(u.range, field.upper->value / u.factor);
    if (field.physical_limit > 0.0) u.range = std::max(u.range, field.physical_limit / u.factor);
    return u;
}

QDoubleSpinBox* declared_number(const NumberField& field, const QString& prefix, QFormLayout* form, QWidget* parent)
{
    const FormUnit u = field_unit(field);
    QDoubleSpinBox* box = number(prefix + QString::fromLatin1(field.key), u.unit, -u.range, u.range, u.decimals, parent);
    if (field.quantity == Quantity::Ratio) box->setSingleStep(0.001);
    QString label = QCoreApplication::translate("ModelFields", field.label);
    if (u.unit.isEmpty()) label += QStringLiteral(" [–]");
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
    const FormUnit u = field_unit(field);
    set_unit(box, u);
    display(box, model_value / u.factor);
}

double declared_value(const QDoubleSpinBox* box, const NumberField& field, double original)
{
    return si(box, original, form_unit(field.quantity).factor);
}

void display_stress(QDoubleSpinBox* box, double pascal)
{
    const FormUnit u = form_unit(Quantity::Stress);
    set_unit(box, u);
    display(box, pascal / u.factor);
}

double stress_value(const QDoubleSpinBox* box, double original, double sign)
{
    return si(box, original, sign * form_unit(Quantity::Stress).factor);
}

namespace {
/// The chooser's item of a strength reduction (the others carry AnalysisSettings::Kind).
constexpr int strength_reduction_item = 100;
}  // namespace

QComboBox* analysis_type_box(const QString& name, QWidget* parent)
{
    auto* box = new QComboBox(parent);
    box->setObjectName(name);
    box->addItem(QCoreApplication::translate("mcdda::gui::form", "Static"), static_cast<int>(AnalysisSettings::Kind::Static));
    box->addItem(QCoreApplication::translate("mcdda::gui::form", "Dynamic"), static_cast<int>(AnalysisSettings::Kind::Dynamic));
    box->addItem(QCoreApplication::translate("mcdda::gui::form", "Strength reduction"), strength_reduction_item);
    explain(box, QCoreApplication::translate(
                     "mcdda::gui::form",
                     "Static: each step ends at rest (velocities reset), for equilibrium and collapse loads. Dynamic: "
                     "velocities carry over, for falls and sliding. Strength reduction: the factor of safety, the "
                     "largest factor c and tan φ can be divided by while the model still stands (of the whole model, "
                     "or as the last stage: a safety stage starting from the stresses of the stages before)"));
    return box;
}

void show_analysis_type(QComboBox* box, const AnalysisSettings& a)
{
    box->setCurrentIndex(box->findData(a.strength_reduction ? strength_reduction_item : static_cast<int>(a.kind)));
}

void read_analysis_type(const QComboBox* box, AnalysisSettings& a)
{
    const int item = box->currentData().toInt();
    a.strength_reduction = item == strength_reduction_item;
    a.kind = a.strength_reduction ? AnalysisSettings::Kind::Static : static_cast<AnalysisSettings::Kind>(item);
}

}  // namespace mcdda::gui::form
