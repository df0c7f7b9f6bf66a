#include "panels/PropertyEditor.hpp"

#include "document/ModelDocument.hpp"
#include "check/ModelValidator.hpp"
#include "panels/AdvancedSettings.hpp"
#include "panels/BoltForm.hpp"
#include "panels/FormFields.hpp"
#include "panels/LawFields.hpp"
#include "panels/LoadForm.hpp"
#include "panels/MeshForm.hpp"
#include "session/DiagnosticText.hpp"
#include "session/DisplayUnits.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdda::gui {

namespace {

using form::deg;
using form::display;
using form::explain;
using form::zero_is_automatic;
using form::number;
using form::si;
using form::status_label;
using form::to_qt;


/// Two buttons side by side in a form row.
QWidget* buttons_row(QPushButton* a, QPushButton* b, QWidget* parent)
{
    auto* row = new QWidget(parent);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(a);
    layout->addWidget(b);
    layout->addStretch();
    return row;
}

bool same(const Material& a, const Material& b)
{
    return a.name == b.name && a.law == b.law && a.parameters == b.parameters && a.reduce == b.reduce &&
           same_fields(a, b, material_fields());
}

bool same(const JointMaterial& a, const JointMaterial& b)
{
    return a.name == b.name && a.reduce == b.reduce && same_fields(a, b, joint_material_fields());
}

bool same(const AnalysisSettings& a, const AnalysisSettings& b)
{
    // Every declared field (the equilibrium and search tolerances too), not a hand-kept list.
    return a.kind == b.kind && a.strength_reduction == b.strength_reduction && a.steps == b.steps &&
           a.output_every == b.output_every && a.plasticity == b.plasticity &&
           a.non_associated_flow == b.non_associated_flow && same_fields(a, b, analysis_fields());
}

bool same(const InitialStress& a, const InitialStress& b)
{
    return a.kind == b.kind && a.stress == b.stress && a.stress_zz == b.stress_zz && a.surface_y == b.surface_y &&
           a.k0 == b.k0;
}

}  // namespace

PropertyEditor::PropertyEditor(ModelDocument* document, QWidget* parent) : QWidget(parent), document_(document)
{
    setObjectName(QStringLiteral("propertyEditor"));
    tabs_ = new QTabWidget(this);
    tabs_->setObjectName(QStringLiteral("propertyTabs"));
    tabs_->addTab(createMaterialForm(), tr("Material"));
    tabs_->addTab(createJointMaterialForm(), tr("Joint material"));
    tabs_->addTab(createAnalysisForm(), tr("Analysis"));
    tabs_->addTab(createInitialStressForm(), tr("In-situ stress"));
    load_form_ = new LoadForm(document_, this);
    load_form_->setObjectName(QStringLiteral("loadForm"));
    tabs_->addTab(load_form_, tr("Loads"));
    bolt_form_ = new BoltForm(document_, this);
    tabs_->addTab(bolt_form_, tr("Bolts"));
    mesh_form_ = new MeshForm(document_, this);
    mesh_form_->setObjectName(QStringLiteral("meshForm"));
    tabs_->addTab(mesh_form_, tr("Mesh"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tabs_);
    connect(document_, &ModelDocument::changed, this, &PropertyEditor::refresh);
    connect(DisplayUnits::instance(), &DisplayUnits::changed, this, &PropertyEditor::refresh);
    refresh();
}

QString PropertyEditor::refusal(const Model& candidate, const std::string& prefix)
{
    std::vector<Diagnostic> diagnostics;
    validate_model(candidate, diagnostics);
    for (const Diagnostic& d : diagnostics) {
        if (d.severity != Diagnostic::Severity::Error) continue;
        const bool concerns = d.path.compare(0, prefix.size(), prefix) == 0 &&
                              (d.path.size() == prefix.size() || d.path[prefix.size()] == '/');
        if (concerns) return diagnostic_text(candidate, d);  // in words and the forms' units
    }
    return {};
}

// --- forms -------------------------------------------------------------------------------

QWidget* PropertyEditor::createMaterialForm()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    material_box_ = new QComboBox(page);
    material_box_->setObjectName(QStringLiteral("materialBox"));
    connect(material_box_, &QComboBox::currentIndexChanged, this, [this] {
        if (!loading_) loadMaterial();
    });
    form->addRow(tr("Material"), material_box_);
    explain(material_box_, tr("The material shown below; Assign to Selection gives it to the selected region"));
    mat_new_ = new QPushButton(tr("New"), page);
    mat_new_->setObjectName(QStringLiteral("materialNew"));
    explain(mat_new_, tr("Add a material (a copy of the one shown)"));
    connect(mat_new_, &QPushButton::clicked, this, &PropertyEditor::newMaterial);
    mat_assign_ = new QPushButton(tr("Assign to Selection"), page);
    mat_assign_->setObjectName(QStringLiteral("materialAssign"));
    explain(mat_assign_, tr("The region selected in the view or the Model tree is made of this material"));
    connect(mat_assign_, &QPushButton::clicked, this, &PropertyEditor::assignMaterial);
    form->addRow(QString(), buttons_row(mat_new_, mat_assign_, page));
    mat_name_ = new QLineEdit(page);
    mat_name_->setObjectName(QStringLiteral("materialName"));
    form->addRow(tr("Name"), mat_name_);
    explain(mat_name_, tr("Name of the material, as the tree and the legend show it"));
    mat_fields_ = std::make_unique<form::DeclaredFields<Material>>(material_fields(), QStringLiteral("material_"), form, page);
    mat_law_ = std::make_unique<form::LawFields>(QStringLiteral("material_"), form, page);
    // A new law shows its fields at once; it is applied with them (Apply, or a field's edit).
    connect(mat_law_->chooser(), &QComboBox::currentIndexChanged, this, [this] {
        if (!loading_) mat_law_->showChosenLaw();
    });
    mat_reduce_ = new QCheckBox(tr("Reduced in a strength reduction"), page);
    mat_reduce_->setObjectName(QStringLiteral("materialReduce"));
    form->addRow(QString(), mat_reduce_);
    explain(mat_reduce_, tr("Whether a strength reduction divides this material's strength; off for a footing or a lining that must not fail in the search"));
    auto* apply = new QPushButton(tr("Apply"), page);
    apply->setObjectName(QStringLiteral("materialApply"));
    connect(apply, &QPushButton::clicked, this, &PropertyEditor::applyMaterial);
    form->addRow(QString(), apply);
    mat_status_ = status_label(QStringLiteral("materialStatus"), page);
    form->addRow(mat_status_);
    std::vector<QDoubleSpinBox*> boxes = mat_fields_->boxes();
    for (QDoubleSpinBox* box : mat_law_->boxes()) boxes.push_back(box);
    // Typed values wait for Apply or Enter (form::apply_on_enter); a box ticked applies at once.
    for (QDoubleSpinBox* box : boxes) form::apply_on_enter(box, [this] { if (!loading_) applyMaterial(); });
    form::apply_on_enter(mat_name_, [this] { if (!loading_) applyMaterial(); });
    connect(mat_reduce_, &QCheckBox::toggled, this, [this] { if (!loading_) applyMaterial(); });
    return page;
}

QWidget* PropertyEditor::createJointMaterialForm()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    joint_box_ = new QComboBox(page);
    joint_box_->setObjectName(QStringLiteral("jointMaterialBox"));
    connect(joint_box_, &QComboBox::currentIndexChanged, this, [this] {
        if (!loading_) loadJointMaterial();
    });
    form->addRow(tr("Joint material"), joint_box_);
    explain(joint_box_, tr("The joint material shown below; Assign to Selection gives it to the selected joint"));
    jm_new_ = new QPushButton(tr("New"), page);
    jm_new_->setObjectName(QStringLiteral("jointMaterialNew"));
    explain(jm_new_, tr("Add a joint material (a copy of the one shown)"));
    connect(jm_new_, &QPushButton::clicked, this, &PropertyEditor::newJointMaterial);
    jm_assign_ = new QPushButton(tr("Assign to Selection"), page);
    jm_assign_->setObjectName(QStringLiteral("jointMaterialAssign"));
    explain(jm_assign_, tr("The joint selected in the view or the Model tree gets this joint material"));
    connect(jm_assign_, &QPushButton::clicked, this, &PropertyEditor::assignJointMaterial);
    form->addRow(QString(), buttons_row(jm_new_, jm_assign_, page));
    jm_name_ = new QLineEdit(page);
    jm_name_->setObjectName(QStringLiteral("jointMaterialName"));
    form->addRow(tr("Name"), jm_name_);
    explain(jm_name_, tr("Name of the joint material"));
    jm_fields_ = std::make_unique<form::DeclaredFields<JointMaterial>>(joint_material_fields(), QStringLiteral("joint_"),
                                                                       form, page);
    jm_reduce_ = new QCheckBox(tr("Reduced in a strength reduction"), page);
    jm_reduce_->setObjectName(QStringLiteral("jointMaterialReduce"));
    form->addRow(QString(), jm_reduce_);
    explain(jm_reduce_, tr("Whether a strength reduction divides this joint material's cohesion, tan φj and tensile strength"));
    auto* apply = new QPushButton(tr("Apply"), page);
    apply->setObjectName(QStringLiteral("jointMaterialApply"));
    connect(apply, &QPushButton::clicked, this, &PropertyEditor::applyJointMaterial);
    form->addRow(QString(), apply);
    jm_status_ = status_label(QStringLiteral("jointMaterialStatus"), page);
    form->addRow(jm_status_);
    for (QDoubleSpinBox* box : jm_fields_->boxes())
        form::apply_on_enter(box, [this] { if (!loading_) applyJointMaterial(); });
    form::apply_on_enter(jm_name_, [this] { if (!loading_) applyJointMaterial(); });
    connect(jm_reduce_, &QCheckBox::toggled, this, [this] { if (!loading_) applyJointMaterial(); });
    return page;
}

QWidget* PropertyEditor::createAnalysisForm()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    an_kind_ = form::analysis_type_box(QStringLiteral("analysisKind"), page);
    form->addRow(tr("Type"), an_kind_);
    connect(an_kind_, &QComboBox::currentIndexChanged, this, [this] { if (!loading_) applyAnalysis(); });
    an_steps_ = new QSpinBox(page);
    an_steps_->setObjectName(QStringLiteral("analysisSteps"));
    an_steps_->setRange(-1, 100000000);
    an_steps_->setKeyboardTracking(false);
    form->addRow(form::steps_label(false), an_steps_);
    explain(an_steps_, tr("Number of load steps (a static analysis) or time steps (a dynamic one); the loads follow "
                          "their tables over the steps"));
    an_fields_ = std::make_unique<form::DeclaredFields<AnalysisSettings>>(form::everyday_analysis_fields(),
                                                                          QStringLiteral("analysis_"), form, page);
    an_output_ = new QSpinBox(page);
    an_output_->setObjectName(QStringLiteral("analysisOutputEvery"));
    an_output_->setRange(-1, 100000000);
    an_output_->setKeyboardTracking(false);
    an_output_->setSuffix(tr(" steps"));
    form->addRow(tr("Save every"), an_output_);
    explain(an_output_, tr("Every how many steps the results are written (the last step always is)"));
    an_plasticity_ = new QCheckBox(tr("Plasticity"), page);
    an_plasticity_->setObjectName(QStringLiteral("analysisPlasticity"));
    form->addRow(QString(), an_plasticity_);
    explain(an_plasticity_, tr("Off: every material stays elastic (a quick elastic check of a plastic model)"));
    an_flow_ = new QComboBox(page);
    an_flow_->setObjectName(QStringLiteral("analysisNonAssociatedFlow"));
    an_flow_->addItem(tr("Davis (associated, strength lowered)"),
                      static_cast<int>(AnalysisSettings::NonAssociatedFlow::Davis));
    an_flow_->addItem(tr("Direct (ψ as given)"), static_cast<int>(AnalysisSettings::NonAssociatedFlow::Direct));
    form->addRow(tr("Non-associated flow"), an_flow_);
    explain(an_flow_, tr("Strength reduction of materials whose dilation angle is below their friction angle. "
                         "Davis: each trial's reduced c and tan φ are lowered by β = cos ψ cos φ / (1 − sin ψ sin φ) "
                         "and solved with associated flow: a factor that converges with the mesh. Direct: ψ as given; "
                         "the non-associated law has no unique limit load and its factor may depend on the mesh "
                         "and the iteration where much of the ground yields"));
    connect(an_flow_, &QComboBox::currentIndexChanged, this, [this] { if (!loading_) applyAnalysis(); });
    // DDA's numerical settings, collapsed: a geotechnical analysis rarely changes them.
    QFormLayout* advanced = form::advanced_section(QStringLiteral("analysisAdvanced"), form, page);
    an_advanced_ = std::make_unique<form::DeclaredFields<AnalysisSettings>>(form::numerical_analysis_fields(),
                                                                            QStringLiteral("analysis_"), advanced,
                                                                            advanced->parentWidget());
    form::add_default_notes(form::numerical_analysis_fields(), QStringLiteral("analysis_"), advanced);
    auto* apply = new QPushButton(tr("Apply"), page);
    apply->setObjectName(QStringLiteral("analysisApply"));
    connect(apply, &QPushButton::clicked, this, &PropertyEditor::applyAnalysis);
    form->addRow(QString(), apply);
    an_status_ = status_label(QStringLiteral("analysisStatus"), page);
    form->addRow(an_status_);
    for (const auto* fields : {an_fields_.get(), an_advanced_.get()})
        for (QDoubleSpinBox* box : fields->boxes()) form::apply_on_enter(box, [this] { if (!loading_) applyAnalysis(); });
    for (QSpinBox* box : {an_steps_, an_output_}) form::apply_on_enter(box, [this] { if (!loading_) applyAnalysis(); });
    return page;
}

QWidget* PropertyEditor::createInitialStressForm()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    is_kind_ = new QComboBox(page);
    is_kind_->setObjectName(QStringLiteral("stressKind"));
    is_kind_->addItem(tr("None"), static_cast<int>(InitialStress::Kind::None));
    is_kind_->addItem(tr("Uniform"), static_cast<int>(InitialStress::Kind::Uniform));
    is_kind_->addItem(tr("From gravity"), static_cast<int>(InitialStress::Kind::Gravity));
    connect(is_kind_, &QComboBox::currentIndexChanged, this, [this] { updateStressFields(); });
    form->addRow(tr("Type"), is_kind_);
    explain(is_kind_, tr("In-situ stress before the first step: none, uniform (the values below) or from gravity (overburden and K0)"));
    auto* note = new QLabel(tr("Stresses: compression positive."), page);
    note->setWordWrap(true);
    form->addRow(note);
    is_sxx_ = number(QStringLiteral("stressXX"), tr("kPa"), -1e9, 1e9, 3, page);
    form->addRow(tr("σxx"), is_sxx_);
    explain(is_sxx_, tr("Horizontal in-situ stress, compression positive"));
    is_syy_ = number(QStringLiteral("stressYY"), tr("kPa"), -1e9, 1e9, 3, page);
    form->addRow(tr("σyy"), is_syy_);
    explain(is_syy_, tr("Vertical in-situ stress, compression positive"));
    is_sxy_ = number(QStringLiteral("stressXY"), tr("kPa"), -1e9, 1e9, 3, page);
    form->addRow(tr("τxy"), is_sxy_);
    explain(is_sxy_, tr("In-situ shear stress"));
    is_szz_given_ = new QCheckBox(tr("σzz given (else ν(σxx + σyy))"), page);
    is_szz_given_->setObjectName(QStringLiteral("stressZZGiven"));
    connect(is_szz_given_, &QCheckBox::toggled, this, [this] { updateStressFields(); });
    form->addRow(QString(), is_szz_given_);
    explain(is_szz_given_, tr("Give the out-of-plane stress σzz yourself; else it follows from plane strain, ν(σxx + σyy)"));
    is_szz_ = number(QStringLiteral("stressZZ"), tr("kPa"), -1e9, 1e9, 3, page);
    form->addRow(tr("σzz"), is_szz_);
    explain(is_szz_, tr("Out-of-plane in-situ stress, compression positive"));
    is_surface_ = number(QStringLiteral("stressSurfaceY"), tr("m"), -1e7, 1e7, 3, page);
    form->addRow(tr("Ground surface y"), is_surface_);
    explain(is_surface_, tr("Height of the ground surface: the overburden of a point is the rock above it up to here"));
    is_k0_ = number(QStringLiteral("stressK0"), QString(), -100.0, 100.0, 4, page);
    is_k0_->setSingleStep(0.05);
    form->addRow(tr("K0 = σh/σv [–]"), is_k0_);
    explain(is_k0_, tr("Ratio of horizontal to vertical in-situ stress, ≥ 0"));
    auto* apply = new QPushButton(tr("Apply"), page);
    apply->setObjectName(QStringLiteral("stressApply"));
    connect(apply, &QPushButton::clicked, this, &PropertyEditor::applyInitialStress);
    form->addRow(QString(), apply);
    is_status_ = status_label(QStringLiteral("stressStatus"), page);
    form->addRow(is_status_);
    for (QDoubleSpinBox* box : {is_sxx_, is_syy_, is_sxy_, is_szz_, is_surface_, is_k0_})
        form::apply_on_enter(box, [this] { if (!loading_) applyInitialStress(); });
    return page;
}

void PropertyEditor::updateStressFields()
{
    const auto kind = static_cast<InitialStress::Kind>(is_kind_->currentData().toInt());
    const bool uniform = kind == InitialStress::Kind::Uniform;
    const bool gravity = kind == InitialStress::Kind::Gravity;
    for (QWidget* w : {static_cast<QWidget*>(is_sxx_), static_cast<QWidget*>(is_syy_),
                       static_cast<QWidget*>(is_sxy_), static_cast<QWidget*>(is_szz_given_)})
        w->setEnabled(uniform);
    is_szz_->setEnabled(uniform && is_szz_given_->isChecked());
    is_surface_->setEnabled(gravity);
    is_k0_->setEnabled(gravity);
}

// --- loading -----------------------------------------------------------------------------

void PropertyEditor::refresh()
{
    const Model& m = document_->model();
    loading_ = true;
    const int material = material_box_->currentIndex();
    material_box_->clear();
    for (std::size_t i = 0; i < m.materials.size(); ++i)
        material_box_->addItem(tr("%1: %2").arg(i).arg(to_qt(m.materials[i].name)));
    if (material_box_->count() > 0) material_box_->setCurrentIndex(std::clamp(material, 0, material_box_->count() - 1));
    const int joint = joint_box_->currentIndex();
    joint_box_->clear();
    for (std::size_t i = 0; i < m.joint_materials.size(); ++i)
        joint_box_->addItem(tr("%1: %2").arg(i).arg(to_qt(m.joint_materials[i].name)));
    if (joint_box_->count() > 0) joint_box_->setCurrentIndex(std::clamp(joint, 0, joint_box_->count() - 1));
    loading_ = false;
    loadMaterial();
    loadJointMaterial();
    loadAnalysis();
    loadInitialStress();
}

void PropertyEditor::loadMaterial()
{
    const Model& m = document_->model();
    const int i = material_box_->currentIndex();
    const bool valid = i >= 0 && static_cast<std::size_t>(i) < m.materials.size();
    for (QWidget* w : material_box_->parentWidget()->findChildren<QWidget*>())
        if (w != mat_status_) w->setEnabled(valid);
    mat_new_->setEnabled(true);
    mat_new_->parentWidget()->setEnabled(true);
    updateAssignButtons();
    if (!valid) return;
    loading_ = true;
    const Material& x = m.materials[static_cast<std::size_t>(i)];
    mat_name_->setText(to_qt(x.name));
    mat_fields_->show(x);
    mat_law_->show(x);
    mat_reduce_->setChecked(x.reduce);
    loading_ = false;
}

void PropertyEditor::loadJointMaterial()
{
    const Model& m = document_->model();
    const int i = joint_box_->currentIndex();
    const bool valid = i >= 0 && static_cast<std::size_t>(i) < m.joint_materials.size();
    for (QWidget* w : joint_box_->parentWidget()->findChildren<QWidget*>())
        if (w != jm_status_) w->setEnabled(valid);
    jm_new_->setEnabled(true);
    jm_new_->parentWidget()->setEnabled(true);
    updateAssignButtons();
    if (!valid) return;
    loading_ = true;
    const JointMaterial& x = m.joint_materials[static_cast<std::size_t>(i)];
    jm_name_->setText(to_qt(x.name));
    jm_fields_->show(x);
    jm_reduce_->setChecked(x.reduce);
    loading_ = false;
}

void PropertyEditor::loadAnalysis()
{
    const AnalysisSettings& a = document_->model().analysis;
    loading_ = true;
    form::show_analysis_type(an_kind_, a);
    an_steps_->setValue(a.steps);
    an_fields_->show(a);
    an_advanced_->show(a);
    an_output_->setValue(a.output_every);
    an_plasticity_->setChecked(a.plasticity);
    an_flow_->setCurrentIndex(an_flow_->findData(static_cast<int>(a.non_associated_flow)));
    // Only a strength reduction uses it; a hidden row also keeps the dock as short as before.
    auto* layout = static_cast<QFormLayout*>(an_flow_->parentWidget()->layout());
    layout->setRowVisible(an_flow_, a.strength_reduction);
    // Newmark's γ and the Rayleigh damping act in a dynamic analysis only (an earthquake's).
    const bool dynamic = a.kind == AnalysisSettings::Kind::Dynamic;
    // Static DDA speaks of load steps; time matters in a dynamic analysis only.
    if (auto* label = qobject_cast<QLabel*>(layout->labelForField(an_steps_))) label->setText(form::steps_label(dynamic));
    for (QDoubleSpinBox* box : an_fields_->boxes()) {
        const QString key = box->objectName().mid(QStringLiteral("analysis_").size());
        if (key == QLatin1String("newmark_gamma") || key.startsWith(QLatin1String("damping_"))) layout->setRowVisible(box, dynamic);
    }
    loading_ = false;
}

void PropertyEditor::loadInitialStress()
{
    const InitialStress& s = document_->model().initial_stress;
    loading_ = true;
    is_kind_->setCurrentIndex(is_kind_->findData(static_cast<int>(s.kind)));
    form::display_stress(is_sxx_, -s.stress[0]);  // shown compression positive
    form::display_stress(is_syy_, -s.stress[1]);
    form::display_stress(is_sxy_, -s.stress[2]);
    is_szz_given_->setChecked(s.stress_zz.has_value());
    form::display_stress(is_szz_, s.stress_zz ? -*s.stress_zz : 0.0);
    display(is_surface_, s.surface_y);
    display(is_k0_, s.k0);
    updateStressFields();
    loading_ = false;
}

// --- applying ----------------------------------------------------------------------------

int PropertyEditor::materialIndex() const { return material_box_->currentIndex(); }
void PropertyEditor::setMaterialIndex(int index) { material_box_->setCurrentIndex(index); }
int PropertyEditor::jointMaterialIndex() const { return joint_box_->currentIndex(); }
void PropertyEditor::setJointMaterialIndex(int index) { joint_box_->setCurrentIndex(index); }
QString PropertyEditor::materialStatus() const { return mat_status_->text(); }
QString PropertyEditor::jointMaterialStatus() const { return jm_status_->text(); }
QString PropertyEditor::analysisStatus() const { return an_status_->text(); }
QString PropertyEditor::initialStressStatus() const { return is_status_->text(); }

void PropertyEditor::setSelection(const ItemRef& ref)
{
    selection_ = ref.valid() ? ItemRef{ref.kind, ref.index} : ItemRef{};
    const Model& m = document_->model();
    if (item_exists(m, selection_)) {
        const auto i = static_cast<std::size_t>(selection_.index);
        switch (selection_.kind) {
        case ItemRef::Kind::Region:
            if (m.regions[i].material >= 0) setMaterialIndex(m.regions[i].material);
            tabs_->setCurrentIndex(0);
            break;
        case ItemRef::Kind::Joint: {
            const int jm = m.joints[i].joint_material >= 0 ? m.joints[i].joint_material : m.default_joint_material;
            if (jm >= 0) setJointMaterialIndex(jm);
            tabs_->setCurrentIndex(1);
            break;
        }
        case ItemRef::Kind::PointLoad:
            load_form_->setLoadIndex(selection_.index);
            tabs_->setCurrentWidget(load_form_);
            break;
        case ItemRef::Kind::EdgePressure:
            load_form_->setLoadIndex(static_cast<int>(m.point_loads.size()) + selection_.index);
            tabs_->setCurrentWidget(load_form_);
            break;
        default:
            break;
        }
    }
    updateAssignButtons();
}

void PropertyEditor::updateAssignButtons()
{
    if (!mat_assign_ || !jm_assign_) return;  // still being built
    const Model& m = document_->model();
    const bool exists = item_exists(m, selection_);
    const bool region = exists && selection_.kind == ItemRef::Kind::Region;
    const bool joint = exists && selection_.kind == ItemRef::Kind::Joint;
    const QString name = exists ? document_->itemName(selection_) : QString();
    mat_assign_->setEnabled(region && material_box_->currentIndex() >= 0);
    mat_assign_->setText(region ? tr("Assign to %1").arg(name) : tr("Assign to Selection"));
    jm_assign_->setEnabled(joint && joint_box_->currentIndex() >= 0);
    jm_assign_->setText(joint ? tr("Assign to %1").arg(name) : tr("Assign to Selection"));
}

bool PropertyEditor::newMaterial()
{
    const Model& m = document_->model();
    const int shown = material_box_->currentIndex();
    Material material;
    if (shown >= 0 && static_cast<std::size_t>(shown) < m.materials.size()) {
        material = m.materials[static_cast<std::size_t>(shown)];
    } else {  // sound rock as a start: every value valid
        material.young_modulus = 10e9;
        material.poisson_ratio = 0.25;
        material.density = 2600.0;
        material.parameters = {{"cohesion", 1e6}, {"friction_angle", 35.0 * deg}};
    }
    material.name.clear();  // the document names it
    const int index = document_->addMaterial(material);
    setMaterialIndex(index);
    form::set_status(mat_status_, tr("Added \"%1\".").arg(to_qt(document_->model().materials[static_cast<std::size_t>(index)].name)), false);
    return true;
}

bool PropertyEditor::newJointMaterial()
{
    const Model& m = document_->model();
    const int shown = joint_box_->currentIndex();
    JointMaterial material;
    if (shown >= 0 && static_cast<std::size_t>(shown) < m.joint_materials.size())
        material = m.joint_materials[static_cast<std::size_t>(shown)];
    else
        material.friction_angle = 30.0 * deg;
    material.name.clear();
    const int index = document_->addJointMaterial(material);
    setJointMaterialIndex(index);
    form::set_status(jm_status_,
              tr("Added \"%1\".").arg(to_qt(document_->model().joint_materials[static_cast<std::size_t>(index)].name)),
              false);
    return true;
}

bool PropertyEditor::assignMaterial()
{
    const int material = material_box_->currentIndex();
    if (!item_exists(document_->model(), selection_) || selection_.kind != ItemRef::Kind::Region || material < 0)
        return false;
    document_->setRegionMaterial(selection_.index, material);
    form::set_status(mat_status_, tr("Assigned to %1.").arg(document_->itemName(selection_)), false);
    return true;
}

bool PropertyEditor::assignJointMaterial()
{
    const int material = joint_box_->currentIndex();
    if (!item_exists(document_->model(), selection_) || selection_.kind != ItemRef::Kind::Joint || material < 0)
        return false;
    document_->setJointMaterialOfJoint(selection_.index, material);
    form::set_status(jm_status_, tr("Assigned to %1.").arg(document_->itemName(selection_)), false);
    return true;
}

bool PropertyEditor::applyMaterial()
{
    const Model& m = document_->model();
    const int i = material_box_->currentIndex();
    if (i < 0 || static_cast<std::size_t>(i) >= m.materials.size()) return false;
    const Material& old = m.materials[static_cast<std::size_t>(i)];
    Material x = old;
    x.name = mat_name_->text().toStdString();
    mat_fields_->read(old, x);
    mat_law_->read(old, x);
    x.reduce = mat_reduce_->isChecked();
    if (same(x, old)) return true;
    Model candidate = m;
    candidate.materials[static_cast<std::size_t>(i)] = x;
    const QString reason = refusal(candidate, "/materials/" + std::to_string(i));
    if (!reason.isEmpty()) {
        form::set_status(mat_status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    document_->setMaterial(i, x);  // → changed() → refresh()
    form::set_status(mat_status_, tr("Applied."), false);
    return true;
}

bool PropertyEditor::applyJointMaterial()
{
    const Model& m = document_->model();
    const int i = joint_box_->currentIndex();
    if (i < 0 || static_cast<std::size_t>(i) >= m.joint_materials.size()) return false;
    const JointMaterial& old = m.joint_materials[static_cast<std::size_t>(i)];
    JointMaterial x = old;
    x.name = jm_name_->text().toStdString();
    jm_fields_->read(old, x);
    x.reduce = jm_reduce_->isChecked();
    if (same(x, old)) return true;
    Model candidate = m;
    candidate.joint_materials[static_cast<std::size_t>(i)] = x;
    const QString reason = refusal(candidate, "/joint_materials/" + std::to_string(i));
    if (!reason.isEmpty()) {
        form::set_status(jm_status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    document_->setJointMaterial(i, x);
    form::set_status(jm_status_, tr("Applied."), false);
    return true;
}

bool PropertyEditor::applyAnalysis()
{
    const Model& m = document_->model();
    const AnalysisSettings& old = m.analysis;
    AnalysisSettings a = old;
    form::read_analysis_type(an_kind_, a);
    a.steps = an_steps_->value();
    an_fields_->read(old, a);
    an_advanced_->read(old, a);
    a.output_every = an_output_->value();
    a.plasticity = an_plasticity_->isChecked();
    a.non_associated_flow = static_cast<AnalysisSettings::NonAssociatedFlow>(an_flow_->currentData().toInt());
    if (same(a, old)) return true;
    Model candidate = m;
    candidate.analysis = a;
    const QString reason = refusal(candidate, "/analysis");
    if (!reason.isEmpty()) {
        form::set_status(an_status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    document_->setAnalysisSettings(a);
    form::set_status(an_status_, tr("Applied."), false);
    return true;
}

bool PropertyEditor::applyInitialStress()
{
    const Model& m = document_->model();
    const InitialStress& old = m.initial_stress;
    InitialStress s = old;
    s.kind = static_cast<InitialStress::Kind>(is_kind_->currentData().toInt());
    s.stress = {form::stress_value(is_sxx_, old.stress[0], -1.0), form::stress_value(is_syy_, old.stress[1], -1.0),
                form::stress_value(is_sxy_, old.stress[2], -1.0)};
    if (is_szz_given_->isChecked())
        s.stress_zz = form::stress_value(is_szz_, old.stress_zz.value_or(0.0), -1.0);
    else
        s.stress_zz.reset();
    s.surface_y = si(is_surface_, old.surface_y, 1.0);
    s.k0 = si(is_k0_, old.k0, 1.0);
    if (same(s, old)) return true;
    Model candidate = m;
    candidate.initial_stress = s;
    const QString reason = refusal(candidate, "/initial_stress");
    if (!reason.isEmpty()) {
        form::set_status(is_status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    document_->setInitialStress(s);
    form::set_status(is_status_, tr("Applied."), false);
    return true;
}

}  // namespace mcdda::gui
