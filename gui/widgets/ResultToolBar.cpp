#include "widgets/ResultToolBar.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QIcon>
#include <QLabel>

namespace mcdda::gui {

ResultToolBar::ResultToolBar(QWidget* parent) : QToolBar(tr("Results"), parent)
{
    setObjectName(QStringLiteral("results"));
    field_box_ = new QComboBox(this);
    field_box_->setToolTip(tr("Field shown for results"));
    field_box_->setObjectName(QStringLiteral("fieldBox"));
    field_box_->addItem(tr("Displacement |u|"), QStringLiteral("displacement"));
    field_box_->addItem(tr("Displacement ux"), QStringLiteral("ux"));
    field_box_->addItem(tr("Displacement uy"), QStringLiteral("uy"));
    field_box_->addItem(tr("Stress σxx"), QStringLiteral("stress_xx"));
    field_box_->addItem(tr("Stress σyy"), QStringLiteral("stress_yy"));
    field_box_->addItem(tr("Stress τxy"), QStringLiteral("stress_xy"));
    field_box_->addItem(tr("Principal stress σ1"), QStringLiteral("stress_1"));
    field_box_->addItem(tr("Principal stress σ3"), QStringLiteral("stress_3"));
    field_box_->addItem(tr("Plastic state"), QStringLiteral("plastic_state"));
    field_box_->addItem(tr("Plastic strain"), QStringLiteral("plastic_strain"));
    connect(field_box_, &QComboBox::currentIndexChanged, this, &ResultToolBar::optionsChanged);
    addWidget(field_box_);

    auto* deform_label = new QLabel(tr("Deformation ×"), this);
    deform_label->setContentsMargins(6, 0, 2, 0);
    addWidget(deform_label);
    deform_box_ = new QDoubleSpinBox(this);
    deform_box_->setObjectName(QStringLiteral("deformBox"));
    deform_box_->setToolTip(tr("Scale factor of the drawn displacements (0 = undeformed)"));
    deform_box_->setRange(0.0, 1e6);
    deform_box_->setDecimals(1);
    deform_box_->setSingleStep(10.0);
    deform_box_->setValue(0.0);
    connect(deform_box_, &QDoubleSpinBox::valueChanged, this, &ResultToolBar::optionsChanged);
    addWidget(deform_box_);

    contacts_ = addAction(QIcon(QStringLiteral(":/icons/contacts.svg")), tr("Contacts"));
    contacts_->setObjectName(QStringLiteral("contactsAction"));
    contacts_->setCheckable(true);
    contacts_->setChecked(true);
    contacts_->setToolTip(tr("Draw the contact forces (lines along the force, the largest 6 % of the model long), "
                             "joint slip and opening, and the bolts of the saved step shown"));
    connect(contacts_, &QAction::toggled, this, &ResultToolBar::optionsChanged);
}

bool ResultToolBar::showContacts() const { return contacts_->isChecked(); }

void ResultToolBar::setShowContacts(bool show) { contacts_->setChecked(show); }

QString ResultToolBar::field() const { return field_box_->currentData().toString(); }

void ResultToolBar::setField(const QString& field)
{
    const int index = field_box_->findData(field);
    if (index >= 0) field_box_->setCurrentIndex(index);
}

double ResultToolBar::deformFactor() const { return deform_box_->value(); }

void ResultToolBar::setDeformFactor(double factor) { deform_box_->setValue(factor); }

view::ResultOptions ResultToolBar::options() const
{
    view::ResultOptions options;
    options.field = field().toStdString();
    options.deform = deformFactor();
    return options;
}

}  // namespace mcdda::gui
