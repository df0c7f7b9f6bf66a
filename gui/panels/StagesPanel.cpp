#include "panels/StagesPanel.hpp"

#include "document/ModelDocument.hpp"
#include "panels/AdvancedSettings.hpp"
#include "panels/DeclaredFields.hpp"
#include "panels/FormFields.hpp"
#include "widgets/ModelView.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace mcdda::gui {

namespace {

/// A list that never scrolls sideways in the narrow dock: long names are elided in the middle
/// (the whole name in the row's tooltip) and the list asks for no width of its own.
void fit_width(QListWidget* list)
{
    list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    list->setTextElideMode(Qt::ElideMiddle);
    list->setSizePolicy(QSizePolicy::Ignored, list->sizePolicy().verticalPolicy());
    list->setMinimumWidth(60);
}

/// A row of a list, its whole text also in its tooltip (the row may be elided).
QListWidgetItem* row(const QString& text, QListWidget* list)
{
    auto* item = new QListWidgetItem(text, list);
    item->setToolTip(text);
    return item;
}

QListWidget* checklist(const QString& name, QWidget* parent)
{
    auto* list = new QListWidget(parent);
    list->setObjectName(name);
    list->setMaximumHeight(90);
    fit_width(list);
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

/// The names of the items checked in `list` (each item keeps its model name as user data).
std::vector<std::string> checked_names(const QListWidget* list)
{
    std::vector<std::string> names;
    for (int i = 0; i < list->count(); ++i)
        if (list->item(i)->checkState() == Qt::Checked)
            names.push_back(list->item(i)->data(Qt::UserRole).toString().toStdString());
    return names;
}

/// The supports, loads and bolts a stage can install or remove, by name, with their kind.
std::vector<std::pair<std::string, QString>> stage_items(const Model& m)
{
    std::vector<std::pair<std::string, QString>> items;
    for (const FixedPoint& f : m.fixed_points) items.emplace_back(f.name, StagesPanel::tr("fixed point"));
    for (const Roller& r : m.rollers) items.emplace_back(r.name, StagesPanel::tr("roller"));
    for (const PointLoad& l : m.point_loads) items.emplace_back(l.name, StagesPanel::tr("point load"));
    for (const EdgePressure& l : m.edge_pressures) items.emplace_back(l.name, StagesPanel::tr("edge pressure"));
    for (const Bolt& b : m.bolts) items.emplace_back(b.name, StagesPanel::tr("bolt"));
    return items;
}

/// A water in words: its line's points, or dry.
QString water_words(const Water& water)
{
    return water.present()
               ? StagesPanel::tr("line with %1 points").arg(water.piezometric_line.size())  // present: ≥ 2
               : StagesPanel::tr("dry");
}

QSpinBox* count_box(const QString& name, int min, const QString& special, QWidget* parent)
{
    auto* box = new QSpinBox(parent);
    box->setObjectName(name);
    box->setRange(min, 100000000);
    box->setKeyboardTracking(false);
    if (!special.isEmpty()) box->setSpecialValueText(special);
    return box;
}

}  // namespace

StagesPanel::~StagesPanel() = default;

StagesPanel::StagesPanel(ModelDocument* document, ModelView* view, QWidget* parent)
    : QWidget(parent), document_(document), view_(view)
{
    setObjectName(QStringLiteral("stagesPanel"));
    list_ = new QListWidget(this);
    list_->setObjectName(QStringLiteral("stageList"));
    list_->setToolTip(tr("Choose a stage to see the model as it stands in it; the first row shows every region"));
    fit_width(list_);
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
    excavate_ = checklist(QStringLiteral("stageExcavate"), this);
    excavate_->setToolTip(tr("Regions removed at the start of the stage (an excavation)"));
    activate_ = checklist(QStringLiteral("stageActivate"), this);
    activate_->setToolTip(tr("Regions added at the start of the stage (backfill, a liner); absent before"));
    install_ = checklist(QStringLiteral("stageInstall"), this);
    install_->setToolTip(tr("Supports, loads and bolts added at the start of the stage; absent before"));
    remove_items_ = checklist(QStringLiteral("stageRemove"), this);
    remove_items_->setToolTip(tr("Supports, loads and bolts taken away at the start of the stage"));
    steps_ = count_box(QStringLiteral("stageSteps"), 1, QString(), this);
    steps_->setToolTip(tr("Number of load steps of the stage (time steps in a dynamic stage)"));
    release_ = count_box(QStringLiteral("stageRelease"), 0, tr("over all steps"), this);
    release_->setSuffix(tr(" steps"));
    release_->setToolTip(tr("Over how many steps the forces the stage leaves out of balance (an excavation's) are "
                            "released, linearly; fewer steps release them faster"));
    water_ = new QLabel(this);
    water_->setObjectName(QStringLiteral("stageWater"));
    water_->setWordWrap(true);
    water_->setToolTip(tr("The ground water in the stage: the piezometric line drawn blue in the picture"));
    water_draw_ = new QPushButton(tr("Draw..."), this);
    water_draw_->setObjectName(QStringLiteral("stageWaterDraw"));
    water_draw_->setToolTip(tr("Draw the water table of this stage with the Water Table tool: click its points from "
                               "left to right, double-click or Enter finishes"));
    water_dry_ = new QPushButton(tr("Dry"), this);
    water_dry_->setObjectName(QStringLiteral("stageWaterDry"));
    water_dry_->setToolTip(tr("No ground water from this stage on (dewatered)"));
    water_inherit_ = new QPushButton(tr("As Before"), this);
    water_inherit_->setObjectName(QStringLiteral("stageWaterInherit"));
    water_inherit_->setToolTip(tr("The stage keeps the water of the stage before (the model's for the first stage)"));
    reset_ = new QCheckBox(tr("Reset displacements at its start"), this);
    reset_->setObjectName(QStringLiteral("stageResetDisplacements"));
    form::explain(reset_, tr("Displacements are reported from the start of this stage, as RS2 and PLAXIS reset them: the "
                             "settlement under gravity in the stage before no longer shows. Stresses and the shape "
                             "stay. Ticked by itself for the stage after the first when the model has gravity"));
    apply_ = new QPushButton(tr("Apply"), this);
    apply_->setObjectName(QStringLiteral("applyStage"));
    note_ = new QLabel(this);
    note_->setWordWrap(true);

    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {add, remove_, up_, down_}) buttons->addWidget(b);
    // The stage's settings scroll up and down, never sideways: long rows put the label above the
    // field, so that the form fits the dock's default width.
    auto* settings = new QWidget;
    settings->setObjectName(QStringLiteral("stageSettings"));
    auto* form = new QFormLayout(settings);
    form->setContentsMargins(0, 0, 0, 0);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Excavate regions"), excavate_);
    form->addRow(tr("Build regions (fill, liner)"), activate_);
    form->addRow(tr("Install supports, loads, bolts"), install_);
    form->addRow(tr("Remove supports, loads, bolts"), remove_items_);
    form->addRow(form::steps_label(false), steps_);
    form->addRow(tr("Release"), release_);
    form->addRow(QString(), reset_);
    // The water acts at once (one undoable edit per button), not through Apply; its buttons span
    // both columns so that they do not widen the form.
    form->addRow(tr("Ground water"), water_);
    auto* water_buttons = new QHBoxLayout;
    for (QPushButton* b : {water_draw_, water_dry_, water_inherit_}) water_buttons->addWidget(b);
    water_buttons->addStretch(1);
    form->addRow(water_buttons);
    // The pseudo-static earthquake load, like the water at once and from this stage on.
    seismic_own_ = new QCheckBox(tr("Own (else as the stage before)"), settings);
    seismic_own_->setObjectName(QStringLiteral("stageSeismicOwn"));
    form::explain(seismic_own_, tr("The stage sets its own seismic coefficient (e.g. a pseudo-static earthquake stage); "
                                   "cleared, it keeps the stage before's (the model's for the first stage)"));
    seismic_kh_ = form::number(QStringLiteral("stageSeismicKh"), QString(), -2.0, 2.0, 3, settings);
    seismic_kh_->setSingleStep(0.05);
    form::explain(seismic_kh_, tr("Horizontal seismic coefficient: every block carries kh·g per unit mass, towards +x for kh > 0"));
    seismic_kv_ = form::number(QStringLiteral("stageSeismicKv"), QString(), -2.0, 2.0, 3, settings);
    seismic_kv_->setSingleStep(0.05);
    form::explain(seismic_kv_, tr("Vertical seismic coefficient: kv·g per unit mass, upwards for kv > 0"));
    form->addRow(tr("Seismic coefficient"), seismic_own_);
    auto* seismic_row = new QHBoxLayout;
    seismic_row->addWidget(new QLabel(tr("kh"), settings));
    seismic_row->addWidget(seismic_kh_, 1);
    seismic_row->addWidget(new QLabel(tr("kv"), settings));
    seismic_row->addWidget(seismic_kv_, 1);
    form->addRow(seismic_row);
    type_ = form::analysis_type_box(QStringLiteral("stageAnalysisType"), settings);
    form->addRow(tr("Analysis"), type_);
    type_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    type_->setMinimumContentsLength(8);
    // The stage's own analysis settings, declared once with the model's (model/ModelFields.hpp);
    // DDA's numerical ones collapsed under Advanced, each with its default in a sentence.
    analysis_ = std::make_unique<form::DeclaredFields<AnalysisSettings>>(form::everyday_analysis_fields(),
                                                                         QStringLiteral("stage_"), form, settings);
    QFormLayout* advanced = form::advanced_section(QStringLiteral("stageAdvanced"), form, settings);
    advanced->setRowWrapPolicy(QFormLayout::WrapLongRows);
    advanced_ = std::make_unique<form::DeclaredFields<AnalysisSettings>>(form::numerical_analysis_fields(),
                                                                         QStringLiteral("stage_"), advanced,
                                                                         advanced->parentWidget());
    form::add_default_notes(form::numerical_analysis_fields(), QStringLiteral("stage_"), advanced);
    form->addRow(QString(), apply_);
    // The stage list above, the chosen stage's settings below, the border between them movable.
    auto* top = new QWidget;
    auto* top_layout = new QVBoxLayout(top);
    top_layout->setContentsMargins(0, 0, 0, 0);
    top_layout->addWidget(list_, 1);
    top_layout->addLayout(buttons);
    top_layout->addWidget(note_);
    auto* scroll = new QScrollArea;
    scroll->setObjectName(QStringLiteral("stageSettingsScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(settings);
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->setObjectName(QStringLiteral("stageSplitter"));
    splitter->setChildrenCollapsible(false);
    splitter->addWidget(top);
    splitter->addWidget(scroll);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(splitter);

    connect(list_, &QListWidget::currentRowChanged, this, &StagesPanel::showStage);
    connect(add, &QPushButton::clicked, this, &StagesPanel::addStage);
    connect(remove_, &QPushButton::clicked, this, &StagesPanel::removeStage);
    connect(up_, &QPushButton::clicked, this, [this] { moveStage(-1); });
    connect(down_, &QPushButton::clicked, this, [this] { moveStage(+1); });
    connect(apply_, &QPushButton::clicked, this, &StagesPanel::applyStage);
    connect(water_draw_, &QPushButton::clicked, this, &StagesPanel::drawWaterRequested);
    connect(water_dry_, &QPushButton::clicked, this, [this] { setStageWater(Water{}); });
    connect(water_inherit_, &QPushButton::clicked, this, [this] { setStageWater(std::nullopt); });
    connect(seismic_own_, &QCheckBox::toggled, this, &StagesPanel::applySeismicCoefficient);
    // Typed values wait for Enter or Apply, as in the Properties dock.
    for (QDoubleSpinBox* box : {seismic_kh_, seismic_kv_}) form::apply_on_enter(box, [this] { applySeismicCoefficient(); });
    form::apply_on_enter(name_, [this] { applyStage(); });
    for (QSpinBox* box : {steps_, release_}) form::apply_on_enter(box, [this] { applyStage(); });
    for (const auto* fields : {analysis_.get(), advanced_.get()})
        for (QDoubleSpinBox* box : fields->boxes()) form::apply_on_enter(box, [this] { applyStage(); });
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
        row(tr("Model as drawn (every region)"), list_);
        for (std::size_t k = 0; k < m.stages.size(); ++k)
            row(tr("%1. %2").arg(k + 1).arg(QString::fromStdString(m.stages[k].name)), list_);
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
    for (QWidget* w : std::initializer_list<QWidget*>{name_, excavate_, activate_, install_, remove_items_, steps_,
                                                       release_, type_, apply_, remove_, reset_})
        w->setEnabled(editing);
    for (const auto* fields : {analysis_.get(), advanced_.get()})
        for (QDoubleSpinBox* box : fields->boxes()) box->setEnabled(editing);
    up_->setEnabled(editing && stage > 0);
    down_->setEnabled(editing && stage + 1 < static_cast<int>(m.stages.size()));
    name_->setText(editing ? QString::fromStdString(m.stages[static_cast<std::size_t>(stage)].name) : QString());
    for (auto [list, which] : {std::pair{excavate_, 0}, std::pair{activate_, 1}}) {
        list->clear();
        for (std::size_t r = 0; r < m.regions.size(); ++r) {
            const QString region = QString::fromStdString(m.regions[r].name);
            auto* item = row(region.isEmpty() ? tr("region %1").arg(r + 1) : region, list);
            bool on = false;
            if (editing) {
                const Stage& st = m.stages[static_cast<std::size_t>(stage)];
                const std::vector<int>& regions = which == 0 ? st.excavate : st.activate;
                on = std::count(regions.begin(), regions.end(), static_cast<int>(r)) > 0;
            }
            item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
        }
    }
    const Stage* st = editing ? &m.stages[static_cast<std::size_t>(stage)] : nullptr;
    for (auto [list, which] : {std::pair{install_, 0}, std::pair{remove_items_, 1}}) {
        list->clear();
        for (const auto& [name, kind] : stage_items(m)) {
            auto* item = row(tr("%1 (%2)").arg(QString::fromStdString(name), kind), list);
            item->setData(Qt::UserRole, QString::fromStdString(name));
            const std::vector<std::string>* names = st ? (which == 0 ? &st->install : &st->remove) : nullptr;
            const bool on = names && std::count(names->begin(), names->end(), name) > 0;
            item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
        }
    }
    steps_->setValue(st ? st->analysis.steps : 1);
    release_->setValue(st ? st->release_steps : 0);
    analysis_->show(st ? st->analysis : m.analysis);
    advanced_->show(st ? st->analysis : m.analysis);
    reset_->setChecked(st && st->reset_displacements);
    form::show_analysis_type(type_, st ? st->analysis : m.analysis);
    // Newmark's γ and the Rayleigh damping: rows of a dynamic stage only (as in the Analysis tab).
    const bool dynamic = (st ? st->analysis : m.analysis).kind == AnalysisSettings::Kind::Dynamic;
    if (auto* label = qobject_cast<QLabel*>(static_cast<QFormLayout*>(steps_->parentWidget()->layout())->labelForField(steps_)))
        label->setText(form::steps_label(dynamic));
    for (QDoubleSpinBox* box : analysis_->boxes()) {
        const QString key = box->objectName().mid(QStringLiteral("stage_").size());
        if (key == QLatin1String("newmark_gamma") || key.startsWith(QLatin1String("damping_")))
            static_cast<QFormLayout*>(box->parentWidget()->layout())->setRowVisible(box, dynamic);
    }
    // The water: the model as drawn has its own; a stage sets one or keeps the stage before's.
    water_->setText(waterText());
    water_dry_->setEnabled(stage < 0 ? m.water.present() : !(st && st->water && !st->water->present()));
    water_inherit_->setEnabled(st && st->water.has_value());
    // The seismic coefficient in force: the model's, or the stage's own, or the stage before's.
    {
        const SeismicCoefficient& k = seismic_of_stage(m, editing ? stage : -1);
        const QSignalBlocker block(seismic_own_);
        seismic_own_->setChecked(!editing || st->seismic_coefficient.has_value());
        seismic_own_->setEnabled(editing);
        form::display(seismic_kh_, k.kh);
        form::display(seismic_kv_, k.kv);
        seismic_kh_->setEnabled(seismic_own_->isChecked());
        seismic_kv_->setEnabled(seismic_own_->isChecked());
    }
    // The picture: the model as it stands in the stage, with the water in force in it.
    view::SceneOptions options = view_->sceneOptions();
    options.hidden_regions = stage >= 0 ? regions_absent(m, stage) : std::vector<int>{};
    options.hidden_items = stage >= 0 ? items_absent(m, stage) : std::vector<std::string>{};
    options.stage = editing ? stage : -1;
    view_->setSceneOptions(options);
}

QString StagesPanel::waterText() const
{
    const Model& m = document_->model();
    const int stage = currentStage();
    if (stage < 0 || stage >= static_cast<int>(m.stages.size())) return water_words(m.water);
    const Stage& st = m.stages[static_cast<std::size_t>(stage)];
    if (st.water) return water_words(*st.water);
    return tr("as the stage before (%1)").arg(water_words(water_of_stage(m, stage)));
}

void StagesPanel::setStageWater(const std::optional<Water>& water)
{
    const int stage = currentStage();
    if (stage >= static_cast<int>(document_->model().stages.size())) return;
    // Dry keeps γw; the model as drawn has no "stage before" (the buttons say so).
    std::optional<Water> w = water;
    if (w) w->unit_weight = water_of_stage(document_->model(), stage).unit_weight;
    if (stage < 0 && !w) return;
    document_->setWater(stage, w);
}

void StagesPanel::applySeismicCoefficient()
{
    const Model& m = document_->model();
    const int stage = currentStage();
    if (stage >= static_cast<int>(m.stages.size())) return;
    const SeismicCoefficient& shown = seismic_of_stage(m, stage);
    SeismicCoefficient k;
    k.kh = form::si(seismic_kh_, shown.kh, 1.0);
    k.kv = form::si(seismic_kv_, shown.kv, 1.0);
    if (stage < 0) {
        if (k.kh != m.seismic_coefficient.kh || k.kv != m.seismic_coefficient.kv) document_->setSeismicCoefficient(-1, k);
        return;
    }
    const std::optional<SeismicCoefficient>& own = m.stages[static_cast<std::size_t>(stage)].seismic_coefficient;
    if (!seismic_own_->isChecked()) {
        if (own) document_->setSeismicCoefficient(stage, std::nullopt);
        return;
    }
    if (!own || own->kh != k.kh || own->kv != k.kv) document_->setSeismicCoefficient(stage, k);
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
    st.install = checked_names(install_);
    st.remove = checked_names(remove_items_);
    st.analysis.steps = steps_->value();
    st.release_steps = release_->value();
    const AnalysisSettings before = st.analysis;
    analysis_->read(before, st.analysis);
    advanced_->read(before, st.analysis);
    st.reset_displacements = reset_->isChecked();
    if (seismic_own_->isChecked()) {  // kh, kv typed and not yet entered go with Apply too, in the same edit
        const SeismicCoefficient shown = seismic_of_stage(m, stage);
        SeismicCoefficient k;
        k.kh = form::si(seismic_kh_, shown.kh, 1.0);
        k.kv = form::si(seismic_kv_, shown.kv, 1.0);
        st.seismic_coefficient = k;
    }
    form::read_analysis_type(type_, st.analysis);
    document_->replaceModel(m, tr("Edit stage \"%1\"").arg(QString::fromStdString(st.name)));
}

void StagesPanel::addStage()
{
    Model m = document_->model();
    Stage st;
    st.name = tr("stage %1").arg(m.stages.size() + 1).toStdString();
    st.analysis = m.analysis;
    st.analysis.steps = 10;
    // The first stage of a model with gravity is its gravity stage (RS2's, PLAXIS's initial
    // phase); the one after it reports displacements from its own start, so that the settlement
    // under gravity does not cover the excavation's. Stages read from a file keep their flag.
    st.reset_displacements = m.stages.size() == 1 && (m.gravity.x != 0.0 || m.gravity.y != 0.0);
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
