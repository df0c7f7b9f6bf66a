#include "panels/BoltForm.hpp"

#include "document/ModelDocument.hpp"
#include "panels/FormFields.hpp"
#include "panels/PropertyEditor.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <algorithm>

namespace mcdda::gui {

BoltForm::BoltForm(ModelDocument* document, QWidget* parent) : QWidget(parent), document_(document)
{
    setObjectName(QStringLiteral("boltForm"));
    auto* form = new QFormLayout(this);
    bolt_box_ = new QComboBox(this);
    bolt_box_->setObjectName(QStringLiteral("boltBox"));
    connect(bolt_box_, &QComboBox::currentIndexChanged, this, [this] {
        if (!loading_) loadBolt();
    });
    form->addRow(tr("Bolt"), bolt_box_);
    form::explain(bolt_box_, tr("The rock bolt shown below; Edit ▸ Bolt draws new ones"));
    name_ = new QLineEdit(this);
    name_->setObjectName(QStringLiteral("boltName"));
    form->addRow(tr("Name"), name_);
    form::explain(name_, tr("Name of the bolt, as stages install or remove it"));
    fields_ = std::make_unique<form::DeclaredFields<Bolt>>(bolt_fields(), QStringLiteral("bolt_"), form, this);
    apply_ = new QPushButton(tr("Apply"), this);
    apply_->setObjectName(QStringLiteral("boltApply"));
    connect(apply_, &QPushButton::clicked, this, &BoltForm::apply);
    form->addRow(QString(), apply_);
    status_ = form::status_label(QStringLiteral("boltStatus"), this);
    form->addRow(status_);
    for (QDoubleSpinBox* box : fields_->boxes()) form::apply_on_enter(box, [this] { if (!loading_) apply(); });
    form::apply_on_enter(name_, [this] { if (!loading_) apply(); });
    connect(document_, &ModelDocument::changed, this, &BoltForm::refresh);
    refresh();
}

BoltForm::~BoltForm() = default;

int BoltForm::boltIndex() const { return bolt_box_->currentIndex(); }

void BoltForm::setBoltIndex(int index) { bolt_box_->setCurrentIndex(index); }

QString BoltForm::status() const { return status_->text(); }

void BoltForm::refresh()
{
    const Model& m = document_->model();
    loading_ = true;
    const int kept = bolt_box_->currentIndex();
    bolt_box_->clear();
    for (std::size_t i = 0; i < m.bolts.size(); ++i)
        bolt_box_->addItem(tr("%1: %2").arg(i + 1).arg(form::to_qt(m.bolts[i].name)));
    if (bolt_box_->count() > 0) bolt_box_->setCurrentIndex(std::clamp(kept, 0, bolt_box_->count() - 1));
    loading_ = false;
    loadBolt();
}

void BoltForm::loadBolt()
{
    const Model& m = document_->model();
    const int i = bolt_box_->currentIndex();
    const bool valid = i >= 0 && static_cast<std::size_t>(i) < m.bolts.size();
    for (QWidget* w : findChildren<QWidget*>())
        if (w != status_) w->setEnabled(valid);
    if (!valid) {
        form::set_status(status_, tr("No bolts: Edit ▸ Bolt draws one between two anchors."), false);
        return;
    }
    loading_ = true;
    const Bolt& b = m.bolts[static_cast<std::size_t>(i)];
    name_->setText(form::to_qt(b.name));
    fields_->show(b);
    loading_ = false;
}

bool BoltForm::apply()
{
    const Model& m = document_->model();
    const int i = bolt_box_->currentIndex();
    if (i < 0 || static_cast<std::size_t>(i) >= m.bolts.size()) return false;
    const Bolt& old = m.bolts[static_cast<std::size_t>(i)];
    Bolt x = old;
    x.name = name_->text().trimmed().toStdString();
    fields_->read(old, x);
    if (x.name == old.name && same_fields(x, old, bolt_fields())) return true;
    Model candidate = m;
    candidate.bolts[static_cast<std::size_t>(i)] = x;
    // Stages name the bolts they install or remove: a renamed bolt keeps its stages.
    for (Stage& st : candidate.stages)
        for (std::vector<std::string>* names : {&st.install, &st.remove})
            std::replace(names->begin(), names->end(), old.name, x.name);
    const QString reason = PropertyEditor::refusal(candidate, "/bolts/" + std::to_string(i));
    if (!reason.isEmpty()) {
        form::set_status(status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    document_->replaceModel(candidate, tr("Edit bolt \"%1\"").arg(form::to_qt(x.name)));
    form::set_status(status_, tr("Applied."), false);
    return true;
}

}  // namespace mcdda::gui
