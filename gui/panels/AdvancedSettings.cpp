#include "panels/AdvancedSettings.hpp"

#include "session/DiagnosticText.hpp"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QToolButton>

#include <cstring>

namespace mcdda::gui::form {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("mcdda::gui::form", text); }

/// DDA's numerical settings: what RS2 and PLAXIS keep out of a stage's everyday settings.
bool numerical(const char* key)
{
    for (const char* k : {"time_step", "max_displacement_ratio", "penalty", "dynamic_ratio", "plastic_tolerance",
                          "min_load_fraction", "equilibrium_ratio"})
        if (std::strcmp(k, key) == 0) return true;
    return false;
}

std::vector<RecordField<AnalysisSettings>> analysis_fields_where(bool advanced)
{
    std::vector<RecordField<AnalysisSettings>> fields;
    for (const RecordField<AnalysisSettings>& f : analysis_fields())
        if (numerical(f.field.key) == advanced) fields.push_back(f);
    return fields;
}

}  // namespace

const std::vector<RecordField<AnalysisSettings>>& everyday_analysis_fields()
{
    static const std::vector<RecordField<AnalysisSettings>> fields = analysis_fields_where(false);
    return fields;
}

const std::vector<RecordField<AnalysisSettings>>& numerical_analysis_fields()
{
    static const std::vector<RecordField<AnalysisSettings>> fields = analysis_fields_where(true);
    return fields;
}

QFormLayout* advanced_section(const QString& name, QFormLayout* form, QWidget* parent, QToolButton** toggle)
{
    auto* button = new QToolButton(parent);
    button->setObjectName(name);
    button->setText(tr("Advanced"));
    button->setCheckable(true);
    button->setChecked(false);
    button->setArrowType(Qt::RightArrow);
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    button->setAutoRaise(true);
    button->setToolTip(tr("The numerical settings of the DDA solver (time step, contact penalty, dynamic ratio, "
                          "largest displacement per step, tolerances); their defaults suit most models"));
    auto* body = new QWidget(parent);
    body->setObjectName(name + QStringLiteral("Body"));
    auto* inner = new QFormLayout(body);
    inner->setContentsMargins(12, 0, 0, 0);
    body->setVisible(false);
    QObject::connect(button, &QToolButton::toggled, body, [button, body](bool on) {
        body->setVisible(on);
        button->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
    });
    form->addRow(button);
    form->addRow(body);
    if (toggle) *toggle = button;
    return inner;
}

void add_default_notes(const std::vector<RecordField<AnalysisSettings>>& fields, const QString& prefix,
                       QFormLayout* form)
{
    QWidget* parent = form->parentWidget();
    for (const RecordField<AnalysisSettings>& f : fields) {
        auto* box = parent->findChild<QDoubleSpinBox*>(prefix + QString::fromLatin1(f.field.key));
        if (!box) continue;
        int row = -1;
        QFormLayout::ItemRole role;
        form->getWidgetPosition(box, &row, &role);
        if (row < 0) continue;
        const double v = f.field.default_value.value_or(0.0);
        const QString value = v == 0.0 && f.field.zero_means
                                  ? QCoreApplication::translate("ModelFields", f.field.zero_means)
                                  : quantity_text(f.field.quantity, v);
        auto* note = new QLabel(tr("Default %1. %2.").arg(value, QCoreApplication::translate("ModelFields", f.field.help)),
                                parent);
        note->setObjectName(prefix + QString::fromLatin1(f.field.key) + QStringLiteral("_note"));
        note->setWordWrap(true);
        QFont small = note->font();
        small.setPointSizeF(small.pointSizeF() * 0.9);
        note->setFont(small);
        note->setForegroundRole(QPalette::PlaceholderText);
        form->insertRow(row + 1, note);
    }
}

QString steps_label(bool dynamic) { return dynamic ? tr("Time steps") : tr("Load steps"); }

}  // namespace mcdda::gui::form
