#include "panels/StagesPanel.hpp"

#include "document/ModelDocument.hpp"
#include "widgets/ModelView.hpp"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace mcdda::gui {

namespace {

QListWidget* region_checklist(const QString& name, QWidget* parent)
{
    auto* list = new QListWidget(parent);
    list->setObjectName(name);
    list->setMaximumHeight(110);
    return list;
}

/// The regions checked in `list`.
std::vector<int> checked(const QListWidget* list)
{
    std::vector<int> regions;
    for (int i = 0; i < list->count(); ++i)
        if (list->item(i)->checkState() == Qt::Checked) regions.push_back(i);
    return regions;
}

}  // namespace

StagesPanel::StagesPanel(ModelDocument* document, ModelView* view, QWidget* parent)
    : QWidget(parent), document_(document), view_(view)
{
    setObjectName(QStringLiteral("stagesPanel"));
    list_ = new QListWidget(this);
    list_->setObjectName(QStringLiteral("stageList"));
    list_->setToolTip(tr("Choose a stage to see the model as it stands in it; the first row shows every region"));
    auto* add = new QPushButton(tr("Add"), this);
    add->setObjectName(QStringLiteral("addStage"));
    add->setToolTip(tr("Add a stage at the end (10 steps, the model's analysis settings)"));
    remove_ = new QPushButton(tr("Remove"), this);
    remove_->setObjectName(QStringLiteral("removeStage"));
    up_ = new QPushButton(tr("Up"), this);
    up_->setObjectName(QStringLiteral("stageUp"));
    down_ = new QPushButton(tr("Down"), this);
    down_->setObjectName(QStringLiteral("stageDown"));
    name_ = new QLineEdit(this);
    name_->setObjectName(QStringLiteral("stageName"));
    name_->setToolTip(tr("Name of the stage (results, tree, messages)"));
    excavate_ = region_checklist(QStringLiteral("stageExcavate"), this);
    excavate_->setToolTip(tr("Regions removed at the start of the stage (an excavation)"));
    activate_ = region_checklist(QStringLiteral("stageActivate"), this);
    activate_->setToolTip(tr("Regions added at the start of the stage (backfill, a liner); absent before"));
    apply_ = new QPushButton(tr("Apply"), this);
    apply_->setObjectName(QStringLiteral("applyStage"));
    note_ = new QLabel(this);
    note_->setWordWrap(true);

    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {add, remove_, up_, down_}) buttons->addWidget(b);
    auto* form = new QFormLayout;
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Excavates"), excavate_);
    form->addRow(tr("Builds"), activate_);
    form->addRow(QString(), apply_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(list_, 1);
    layout->addLayout(buttons);
    layout->addLayout(form);
    layout->addWidget(note_);

    connect(list_, &QListWidget::currentRowChanged, this, &StagesPanel::showStage);
    connect(add, &QPushButton::clicked, this, &StagesPanel::addStage);
    connect(remove_, &QPushButton::clicked, this, &StagesPanel::removeStage);
    connect(up_, &QPushButton::clicked, this, [this] { moveStage(-1); });
    connect(down_, &QPushButton::clicked, this, [this] { moveStage(+1); });
    connect(apply_, &QPushButton::clicked, this, &StagesPanel::applyStage);
    connect(document_, &ModelDocument::changed, this, &StagesPanel::refresh);
    refresh();
}

int StagesPanel::currentStage() const { return list_->currentRow() - 1; }

void StagesPanel::setCurrentStage(int stage) { list_->setCurrentRow(stage + 1); }

void StagesPanel::refresh()
{
    const Model& m = document_->model();
    const int kept = std::min(list_->currentRow(), static_cast<int>(m.stages.size()));
    {
        const QSignalBlocker block(list_);
        list_->clear();
        list_->addItem(tr("Model as drawn (every region)"));
        for (std::size_t k = 0; k < m.stages.size(); ++k)
            list_->addItem(tr("%1. %2").arg(k + 1).arg(QString::fromStdString(m.stages[k].name)));
        list_->setCurrentRow(std::max(kept, 0));
    }
    note_->setText(m.stages.empty() ? tr("No stages: the model is analysed in one go. Add one to excavate or build "
                                         "regions step by step.")
                                    : QString());
    showStage();
}

void StagesPanel::showStage()
{
    const Model& m = document_->model();
    const int stage = currentStage();
    const bool editing = stage >= 0 && stage < static_cast<int>(m.stages.size());
    for (QWidget* w : {static_cast<QWidget*>(name_), static_cast<QWidget*>(excavate_), static_cast<QWidget*>(activate_),
                       static_cast<QWidget*>(apply_), static_cast<QWidget*>(remove_)})
        w->setEnabled(editing);
    up_->setEnabled(editing && stage > 0);
    down_->setEnabled(editing && stage + 1 < static_cast<int>(m.stages.size()));
    name_->setText(editing ? QString::fromStdString(m.stages[static_cast<std::size_t>(stage)].name) : QString());
    for (auto [list, which] : {std::pair{excavate_, 0}, std::pair{activate_, 1}}) {
        list->clear();
        for (std::size_t r = 0; r < m.regions.size(); ++r) {
            const QString region = QString::fromStdString(m.regions[r].name);
            auto* item = new QListWidgetItem(region.isEmpty() ? tr("region %1").arg(r + 1) : region, list);
            bool on = false;
            if (editing) {
                const Stage& st = m.stages[static_cast<std::size_t>(stage)];
                const std::vector<int>& regions = which == 0 ? st.excavate : st.activate;
                on = std::count(regions.begin(), regions.end(), static_cast<int>(r)) > 0;
            }
            item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
        }
    }
    // The picture: the model as it stands in the stage.
    view::SceneOptions options = view_->sceneOptions();
    options.hidden_regions = stage >= 0 ? regions_absent(m, stage) : std::vector<int>{};
    view_->setSceneOptions(options);
}

void StagesPanel::applyStage()
{
    const int stage = currentStage();
    Model m = document_->model();
    if (stage < 0 || stage >= static_cast<int>(m.stages.size())) return;
    Stage& st = m.stages[static_cast<std::size_t>(stage)];
    st.name = name_->text().trimmed().toStdString();
    st.excavate = checked(excavate_);
    st.activate = checked(activate_);
    document_->replaceModel(m, tr("Edit stage \"%1\"").arg(QString::fromStdString(st.name)));
}

void StagesPanel::addStage()
{
    Model m = document_->model();
    Stage st;
    st.name = tr("stage %1").arg(m.stages.size() + 1).toStdString();
    st.analysis = m.analysis;
    st.analysis.steps = 10;
    m.stages.push_back(st);
    document_->replaceModel(m, tr("Add stage \"%1\"").arg(QString::fromStdString(st.name)));
    setCurrentStage(static_cast<int>(m.stages.size()) - 1);
}

void StagesPanel::removeStage()
{
    const int stage = currentStage();
    Model m = document_->model();
    if (stage < 0 || stage >= static_cast<int>(m.stages.size())) return;
    const QString name = QString::fromStdString(m.stages[static_cast<std::size_t>(stage)].name);
    m.stages.erase(m.stages.begin() + stage);
    document_->replaceModel(m, tr("Remove stage \"%1\"").arg(name));
}

void StagesPanel::moveStage(int by)
{
    const int stage = currentStage(), to = stage + by;
    Model m = document_->model();
    if (stage < 0 || to < 0 || stage >= static_cast<int>(m.stages.size()) || to >= static_cast<int>(m.stages.size())) return;
    std::swap(m.stages[static_cast<std::size_t>(stage)], m.stages[static_cast<std::size_t>(to)]);
    document_->replaceModel(m, tr("Move stage \"%1\"").arg(QString::fromStdString(m.stages[static_cast<std::size_t>(to)].name)));
    setCurrentStage(to);
}

}  // namespace mcdda::gui
