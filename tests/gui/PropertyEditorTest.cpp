// The Properties dock and the support/load/measurement tools on a (virtual) X server: refused
// and applied edits with undo, tools placing items with simulated clicks, and the picture
// following edits that are pre-processed off the GUI thread.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "document/ModelDocument.hpp"
#include "material/MaterialLaws.hpp"
#include "model/ModelFields.hpp"
#include "panels/BoltForm.hpp"
#include "panels/PropertyEditor.hpp"
#include "session/DisplayUnits.hpp"
#include "widgets/ModelTree.hpp"
#include "view/Palette.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTimer>
#include <QTreeWidgetItemIterator>
#include <QUndoStack>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace mcdda;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;
using mcdda::gui::PropertyEditor;
using namespace mcdda::guitest;


class PropertyEditorTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void refusesImpossibleValues();
    void appliesCohesionWithUndo();
    void appliesJointMaterialAndInSituStress();
    void strengthReductionSettings();
    void toolsPlaceRollerAndMeasurementPoint();
    void otherToolsPlaceItems();
    void viewFollowsEditsOffTheGuiThread();
    void everyFieldExplainsItself();
    void formsFollowTheFieldDeclarations();
    void theMaterialFormShowsTheFieldsOfTheChosenLaw();
    void boltFormEditsBolts();
    void unitsChosenReachFormsAndTree();
};

void PropertyEditorTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    gui::DisplayUnits::instance()->set(view::StressUnit::Automatic, view::LengthUnit::Metre);  // whatever a run left
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

void PropertyEditorTest::refusesImpossibleValues()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    gui::ModelDocument* doc = window->document();
    const Material before = doc->model().materials[0];
    const int commands = doc->undoStack()->count();
    PropertyEditor* editor = window->propertyEditor();
    QVERIFY(editor);
    auto* nu = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_poisson_ratio"));
    auto* apply = editor->findChild<QPushButton*>(QStringLiteral("materialApply"));
    QVERIFY(nu && apply);

    nu->setValue(0.5);
    apply->click();
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("Poisson")), qPrintable(editor->materialStatus()));
    QCOMPARE(doc->model().materials[0].poisson_ratio, before.poisson_ratio);
    QCOMPARE(doc->undoStack()->count(), commands);

    nu->setValue(before.poisson_ratio);
    auto* phi = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_mohr_coulomb_friction_angle"));
    QVERIFY(phi->suffix().contains(QStringLiteral("°")));
    phi->setValue(90.0);
    QVERIFY(!editor->applyMaterial());
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("friction")), qPrintable(editor->materialStatus()));
    QCOMPARE(doc->model().materials[0].parameter("friction_angle"), before.parameter("friction_angle"));

    phi->setValue(35.0);
    auto* e = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_young_modulus"));
    QVERIFY(e->suffix().contains(QStringLiteral("MPa")));
    e->setValue(0.0);
    QVERIFY(!editor->applyMaterial());
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("Young")), qPrintable(editor->materialStatus()));
    QCOMPARE(doc->model().materials[0].young_modulus, before.young_modulus);
    QCOMPARE(doc->undoStack()->count(), commands);
}

void PropertyEditorTest::appliesCohesionWithUndo()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    PropertyEditor* editor = window->propertyEditor();
    const double old_cohesion = doc->model().materials[0].parameter("cohesion");
    const double old_e = doc->model().materials[0].young_modulus;
    const double old_density = doc->model().materials[0].density;
    auto* c = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_mohr_coulomb_cohesion"));
    QVERIFY(c);
    QVERIFY(c->suffix().contains(QStringLiteral("kPa")));
    QCOMPARE(c->value(), old_cohesion / 1e3);
    c->setValue(200.0);
    editor->findChild<QPushButton*>(QStringLiteral("materialApply"))->click();
    QCOMPARE(doc->model().materials[0].parameter("cohesion"), 2e5);
    QCOMPARE(doc->model().materials[0].young_modulus, old_e);   // untouched fields stay exact
    QCOMPARE(doc->model().materials[0].density, old_density);
    QVERIFY(editor->materialStatus().contains(QStringLiteral("Applied")));
    QAction* undo = window->findChild<QAction*>(QStringLiteral("undoAction"));
    QVERIFY(undo->text().contains(QStringLiteral("material")));
    undo->trigger();
    QCOMPARE(doc->model().materials[0].parameter("cohesion"), old_cohesion);
    QCOMPARE(c->value(), old_cohesion / 1e3);  // the form follows the undo
    window->findChild<QAction*>(QStringLiteral("redoAction"))->trigger();
    QCOMPARE(doc->model().materials[0].parameter("cohesion"), 2e5);
    QTRY_VERIFY(settled(*window));
}

void PropertyEditorTest::strengthReductionSettings()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    PropertyEditor* editor = window->propertyEditor();
    // The analysis type applies when chosen; strength reduction is static with the flag set.
    auto* type = editor->findChild<QComboBox*>(QStringLiteral("analysisKind"));
    QVERIFY(type);
    QCOMPARE(type->count(), 3);
    type->setCurrentIndex(type->findText(QStringLiteral("Strength reduction")));
    QVERIFY(doc->model().analysis.strength_reduction);
    QCOMPARE(doc->model().analysis.kind, AnalysisSettings::Kind::Static);
    type->setCurrentIndex(type->findText(QStringLiteral("Dynamic")));
    QVERIFY(!doc->model().analysis.strength_reduction);
    QCOMPARE(doc->model().analysis.kind, AnalysisSettings::Kind::Dynamic);
    QTRY_VERIFY(editor->findChild<QComboBox*>(QStringLiteral("analysisNonAssociatedFlow"))->isHidden());
    doc->undoStack()->undo();
    QVERIFY(doc->model().analysis.strength_reduction);
    QCOMPARE(type->currentText(), QStringLiteral("Strength reduction"));  // the form follows the undo
    // The search's tolerance is a declared field of the analysis form.
    auto* tolerance = editor->findChild<QDoubleSpinBox*>(QStringLiteral("analysis_factor_tolerance"));
    QVERIFY(tolerance);
    tolerance->setValue(0.01);
    QVERIFY(editor->applyAnalysis());
    QCOMPARE(doc->model().analysis.factor_tolerance, 0.01);
    // Non-associated materials: Davis's reduction by default, the law itself when asked.
    auto* flow = editor->findChild<QComboBox*>(QStringLiteral("analysisNonAssociatedFlow"));
    QVERIFY(flow && !flow->isHidden());  // shown for a strength reduction only
    QCOMPARE(doc->model().analysis.non_associated_flow, AnalysisSettings::NonAssociatedFlow::Davis);
    flow->setCurrentIndex(flow->findData(static_cast<int>(AnalysisSettings::NonAssociatedFlow::Direct)));
    QCOMPARE(doc->model().analysis.non_associated_flow, AnalysisSettings::NonAssociatedFlow::Direct);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().analysis.non_associated_flow, AnalysisSettings::NonAssociatedFlow::Davis);
    QCOMPARE(flow->currentData().toInt(), static_cast<int>(AnalysisSettings::NonAssociatedFlow::Davis));
    // A material or joint material kept out of the reduction (a footing, a lining).
    auto* reduce = editor->findChild<QCheckBox*>(QStringLiteral("materialReduce"));
    QVERIFY(reduce && reduce->isChecked());
    reduce->setChecked(false);
    QVERIFY(!doc->model().materials[0].reduce);
    auto* joint_reduce = editor->findChild<QCheckBox*>(QStringLiteral("jointMaterialReduce"));
    QVERIFY(joint_reduce && joint_reduce->isChecked());
    joint_reduce->setChecked(false);
    QVERIFY(!doc->model().joint_materials[0].reduce);
    doc->undoStack()->undo();
    QVERIFY(doc->model().joint_materials[0].reduce);
    QVERIFY(joint_reduce->isChecked());
    QTRY_VERIFY(settled(*window));
}

void PropertyEditorTest::appliesJointMaterialAndInSituStress()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    PropertyEditor* editor = window->propertyEditor();
    auto* cj = editor->findChild<QDoubleSpinBox*>(QStringLiteral("joint_cohesion"));
    QVERIFY(cj);
    cj->setValue(50.0);
    QVERIFY(editor->applyJointMaterial());
    QCOMPARE(doc->model().joint_materials[0].cohesion, 5e4);
    auto* phij = editor->findChild<QDoubleSpinBox*>(QStringLiteral("joint_friction_angle"));
    phij->setValue(95.0);
    QVERIFY(!editor->applyJointMaterial());
    QVERIFY(!editor->jointMaterialStatus().isEmpty());

    auto* kind = editor->findChild<QComboBox*>(QStringLiteral("stressKind"));
    kind->setCurrentIndex(kind->findData(static_cast<int>(InitialStress::Kind::Uniform)));
    editor->findChild<QDoubleSpinBox*>(QStringLiteral("stressXX"))->setValue(1000.0);  // kPa, compression
    editor->findChild<QDoubleSpinBox*>(QStringLiteral("stressYY"))->setValue(2000.0);
    QVERIFY(editor->applyInitialStress());
    const InitialStress& s = doc->model().initial_stress;
    QCOMPARE(s.kind, InitialStress::Kind::Uniform);
    QCOMPARE(s.stress[0], -1e6);  // stored tension positive
    QCOMPARE(s.stress[1], -2e6);
    QVERIFY(!s.stress_zz.has_value());
    doc->undoStack()->undo();
    QCOMPARE(doc->model().initial_stress.kind, InitialStress::Kind::None);

    auto* steps = editor->findChild<QSpinBox*>(QStringLiteral("analysisSteps"));
    steps->setValue(0);
    QVERIFY(!editor->applyAnalysis());
    QVERIFY(editor->analysisStatus().contains(QStringLiteral("step")));
    steps->setValue(42);
    QVERIFY(editor->applyAnalysis());
    QCOMPARE(doc->model().analysis.steps, 42);
    QTRY_VERIFY(settled(*window));
}

void PropertyEditorTest::toolsPlaceRollerAndMeasurementPoint()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    gui::ModelDocument* doc = window->document();
    ModelView* view = window->modelView();
    view->showBox(-2, -2, 12, 12);

    auto* fix = window->findChild<QComboBox*>(QStringLiteral("rollerFixBox"));
    QVERIFY(fix);
    fix->setCurrentIndex(fix->findData(QStringLiteral("x")));
    window->findChild<QAction*>(QStringLiteral("rollerAction"))->trigger();
    QVERIFY(window->activeTool());
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 10.1, 0.1));
    QCOMPARE(doc->model().rollers.size(), std::size_t(1));  // one click is not a roller yet
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 9.9, 9.95));
    QCOMPARE(doc->model().rollers.size(), std::size_t(2));
    const Roller& r = doc->model().rollers[1];
    QCOMPARE(r.from.x, 10.0);
    QCOMPARE(r.from.y, 0.0);
    QCOMPARE(r.to.x, 10.0);
    QCOMPARE(r.to.y, 10.0);
    QVERIFY(r.fix_x);
    QVERIFY(!r.fix_y);
    QCOMPARE(r.name, std::string("roller 2"));

    QTRY_VERIFY(settled(*window));
    QCOMPARE(count_around(*view, 5, 5, view::palette::measurement, 7), 0);
    window->findChild<QAction*>(QStringLiteral("measurementPointAction"))->trigger();
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 5.05, 4.95));
    QCOMPARE(doc->model().measurement_points.size(), std::size_t(1));
    QCOMPARE(doc->model().measurement_points[0].name, std::string("point 1"));
    QCOMPARE(doc->model().measurement_points[0].point.x, 5.0);
    QCOMPARE(doc->model().measurement_points[0].point.y, 5.0);
    QTRY_VERIFY2(count_around(*view, 5, 5, view::palette::measurement, 7) > 0, "the measurement point is drawn");

    QAction* undo = window->findChild<QAction*>(QStringLiteral("undoAction"));
    QVERIFY(undo->text().contains(QStringLiteral("measurement")));
    undo->trigger();
    QVERIFY(doc->model().measurement_points.empty());
    undo->trigger();
    QCOMPARE(doc->model().rollers.size(), std::size_t(1));
    QTRY_VERIFY(settled(*window) && count_around(*view, 5, 5, view::palette::measurement, 7) == 0);
}

void PropertyEditorTest::otherToolsPlaceItems()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    ModelView* view = window->modelView();
    view->showBox(-2, -2, 12, 12);

    window->findChild<QAction*>(QStringLiteral("fixedPointAction"))->trigger();
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 0.05, 0.05));
    QCOMPARE(doc->model().fixed_points.size(), std::size_t(1));
    QCOMPARE(doc->model().fixed_points[0].point.x, 0.0);

    window->findChild<QAction*>(QStringLiteral("pointLoadAction"))->trigger();
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 5, 10));
    QCOMPARE(doc->model().point_loads.size(), std::size_t(1));
    QCOMPARE(doc->model().point_loads[0].force.x, 0.0);
    QCOMPARE(doc->model().point_loads[0].force.y, -1e3);  // default −1 kN/m

    window->findChild<QAction*>(QStringLiteral("edgePressureAction"))->trigger();
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 0, 10));
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 10, 10));
    QCOMPARE(doc->model().edge_pressures.size(), std::size_t(1));
    QCOMPARE(doc->model().edge_pressures[0].pressure, 1e5);  // default 100 kPa
    QCOMPARE(doc->model().edge_pressures[0].to.x, 10.0);

    for (int i = 0; i < 3; ++i) doc->undoStack()->undo();
    QVERIFY(doc->model().fixed_points.empty());
    QVERIFY(doc->model().point_loads.empty());
    QVERIFY(doc->model().edge_pressures.empty());
    QTRY_VERIFY(settled(*window));
}

void PropertyEditorTest::viewFollowsEditsOffTheGuiThread()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    QVERIFY(window->statisticsText().contains(QStringLiteral("elements")));
    gui::ModelDocument* doc = window->document();
    const auto before = window->modelView()->scene();

    // An edit returns at once; the previous picture stays until the new one is ready.
    auto* c = window->propertyEditor()->findChild<QDoubleSpinBox*>(QStringLiteral("material_mohr_coulomb_cohesion"));
    c->setValue(200.0);
    QVERIFY(window->propertyEditor()->applyMaterial());
    QVERIFY(window->isPreprocessing());
    QCOMPARE(window->modelView()->scene(), before);
    QAction* run = window->findChild<QAction*>(QStringLiteral("runAction"));
    QVERIFY2(!run->isEnabled(), "no run of the stale picture");

    // A newer edit supersedes the one being computed; only its result is shown.
    c->setValue(300.0);
    QVERIFY(window->propertyEditor()->applyMaterial());

    // The event loop keeps running meanwhile.
    int ticks = 0;
    QTimer timer;
    connect(&timer, &QTimer::timeout, [&] { ++ticks; });
    timer.start(1);
    QTRY_VERIFY(!window->isPreprocessing());
    QVERIFY(ticks > 0);
    const auto after = window->modelView()->scene();
    QVERIFY(after != before);
    QCOMPARE(after->model.materials[0].parameter("cohesion"), 3e5);
    QVERIFY(window->statisticsText().contains(QStringLiteral("elements")));
    QCOMPARE(doc->model().materials[0].parameter("cohesion"), 3e5);
    QVERIFY(run->isEnabled());

    // Removing the region empties the picture (pixel check) after the background work.
    const view::Rgb rock = view::material_color(0);
    window->modelView()->showBox(-2, -2, 12, 12);
    QTRY_VERIFY(count_around(*window->modelView(), 5, 7, rock, 7) > 100);
    while (!doc->model().regions.empty()) doc->undoStack()->undo();
    QTRY_VERIFY(count_around(*window->modelView(), 5, 7, view::palette::background, 7) > 100);
    QTRY_VERIFY(!window->isPreprocessing());
}

// Every field of the Properties dock says what it means, in its tooltip and in
// What's This, and the fields where 0 means "automatic" read so.
void PropertyEditorTest::everyFieldExplainsItself()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    PropertyEditor* editor = window->propertyEditor();
    int fields = 0;
    for (QWidget* w : editor->findChildren<QWidget*>()) {
        const bool input = qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w) ||
                           qobject_cast<QCheckBox*>(w) || qobject_cast<QLineEdit*>(w);
        // (A spin box's or combo box's own line edit is part of it.)
        if (!input || qobject_cast<QAbstractSpinBox*>(w->parentWidget()) || qobject_cast<QComboBox*>(w->parentWidget()))
            continue;
        if (qobject_cast<QLineEdit*>(w) && w->parentWidget() && w->parentWidget()->inherits("QTableView")) continue;
        ++fields;
        const QString name = w->objectName().isEmpty() ? QString::fromLatin1(w->metaObject()->className()) : w->objectName();
        QVERIFY2(!w->toolTip().isEmpty(), qPrintable(name + QStringLiteral(" has no tooltip")));
        QVERIFY2(!w->whatsThis().isEmpty(), qPrintable(name + QStringLiteral(" has no What's This")));
    }
    QVERIFY2(fields >= 40, qPrintable(QString::number(fields)));
    auto* penalty = editor->findChild<QDoubleSpinBox*>(QStringLiteral("analysis_penalty"));
    QVERIFY(penalty);
    penalty->setValue(0.0);
    QCOMPARE(penalty->text(), QStringLiteral("automatic"));
    QVERIFY(penalty->toolTip().contains(QStringLiteral("automatic")));
}

namespace {

/// Each declared field has its form field, named after its key, labelled and explained by its
/// declaration, showing the model's value in the form's unit.
template <class Record>
void check_declared(PropertyEditor* editor, const std::vector<RecordField<Record>>& fields, const QString& prefix,
                    const Record& shown)
{
    for (const RecordField<Record>& f : fields) {
        const QString name = prefix + QString::fromLatin1(f.field.key);
        auto* box = editor->findChild<QDoubleSpinBox*>(name);
        QVERIFY2(box, qPrintable(name + QStringLiteral(" missing")));
        auto* form = qobject_cast<QFormLayout*>(box->parentWidget()->layout());
        QVERIFY(form);
        auto* label = qobject_cast<QLabel*>(form->labelForField(box));
        QVERIFY2(label && label->text().startsWith(QString::fromUtf8(f.field.label)), qPrintable(name));
        QCOMPARE(box->toolTip(), QString::fromUtf8(f.field.help));
        const double shown_value = shown.*f.member / gui::form::form_unit_factor(f.field.quantity);
        QVERIFY2(std::abs(box->value() - shown_value) <= 0.5 * std::pow(10.0, -box->decimals()), qPrintable(name));
    }
}

}  // namespace

// The law chooser offers every law the solver declares; the form shows exactly the chosen law's
// fields (label, help) and Apply stores the law with them.
void PropertyEditorTest::theMaterialFormShowsTheFieldsOfTheChosenLaw()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    PropertyEditor* editor = window->propertyEditor();
    window->show();
    auto* chooser = editor->findChild<QComboBox*>(QStringLiteral("materialLaw"));
    QVERIFY(chooser);
    QCOMPARE(chooser->count(), static_cast<int>(material_laws().size()));
    auto visible_fields = [&](const MaterialLaw& law) {
        const QString prefix = QStringLiteral("material_") + QString::fromLatin1(law.key).replace(QLatin1Char('-'), QLatin1Char('_')) + QLatin1Char('_');
        int visible = 0;
        for (const NumberField& f : law.fields) {
            auto* box = editor->findChild<QDoubleSpinBox*>(prefix + QString::fromLatin1(f.key));
            if (!box) return -1;
            auto* label = qobject_cast<QLabel*>(qobject_cast<QFormLayout*>(box->parentWidget()->layout())->labelForField(box));
            if (!label || !label->text().startsWith(QString::fromUtf8(f.label)) || box->toolTip() != QString::fromUtf8(f.help))
                return -1;
            if (!box->isHidden() && !label->isHidden()) ++visible;
        }
        return visible;
    };
    const MaterialLaw& mc = *find_material_law("mohr-coulomb");
    const MaterialLaw& hb = *find_material_law("hoek-brown");
    QCOMPARE(chooser->currentData().toString(), QStringLiteral("mohr-coulomb"));
    QCOMPARE(visible_fields(mc), static_cast<int>(mc.fields.size()));
    QCOMPARE(visible_fields(hb), 0);

    chooser->setCurrentIndex(chooser->findData(QStringLiteral("hoek-brown")));
    QCOMPARE(visible_fields(mc), 0);
    QCOMPARE(visible_fields(hb), static_cast<int>(hb.fields.size()));
    QCOMPARE(window->document()->model().materials[0].law, std::string("mohr-coulomb"));  // not applied yet
    QVERIFY(!editor->applyMaterial());  // σci and mi are still 0
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("uniaxial compressive strength")), qPrintable(editor->materialStatus()));
    editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_hoek_brown_uniaxial_strength"))
        ->setValue(50e6 / gui::form::form_unit_factor(Quantity::Stress));
    editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_hoek_brown_gsi"))->setValue(60.0);
    editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_hoek_brown_mi"))->setValue(10.0);
    QVERIFY2(editor->applyMaterial(), qPrintable(editor->materialStatus()));
    const Material& applied = window->document()->model().materials[0];
    QCOMPARE(applied.law, std::string("hoek-brown"));
    QCOMPARE(applied.parameter("uniaxial_strength"), 50e6);
    QCOMPARE(applied.parameter("gsi"), 60.0);
    QCOMPARE(applied.parameter("disturbance"), 0.0);

    chooser->setCurrentIndex(chooser->findData(QStringLiteral("elastic")));
    QVERIFY(editor->applyMaterial());
    QCOMPARE(window->document()->model().materials[0].law, std::string("elastic"));
    QCOMPARE(visible_fields(mc) + visible_fields(hb), 0);
}

// The Material, Joint material and Bolts forms are built from the field declarations
// the reader, writer and validator use (model/ModelFields.hpp).
void PropertyEditorTest::formsFollowTheFieldDeclarations()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    PropertyEditor* editor = window->propertyEditor();
    const Model& m = window->document()->model();
    check_declared(editor, material_fields(), QStringLiteral("material_"), m.materials[0]);
    check_declared(editor, joint_material_fields(), QStringLiteral("joint_"), m.joint_materials[0]);
    check_declared(editor, bolt_fields(), QStringLiteral("bolt_"), Bolt{});
    check_declared(editor, analysis_fields(), QStringLiteral("analysis_"), m.analysis);
    // The unit weight is typed in kN/m³ and stored as a density.
    auto* gamma = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_density"));
    QVERIFY(gamma->suffix().contains(QStringLiteral("kN/m³")));
    QCOMPARE(gamma->value(), std::round(m.materials[0].density * 9.81 / 1e3 * 1e3) / 1e3);
    gamma->setValue(20.0);
    QVERIFY(editor->applyMaterial());
    QCOMPARE(window->document()->model().materials[0].density, 20.0e3 / 9.81);
}

// The Bolts tab edits the staged tunnel's roof bolts: strength in kN/m, refusals with
// the validator's reason, a rename that the stages follow, each change one undoable edit.
void PropertyEditorTest::boltFormEditsBolts()
{
    MainWindow window;
    QVERIFY(show_model(window, QStringLiteral(MCDDA_EXAMPLES_DIR "/jointed-tunnel-staged.json")));
    QTRY_VERIFY(settled(window));
    gui::BoltForm* form = window.propertyEditor()->boltForm();
    QVERIFY(form);
    auto* box = form->findChild<QComboBox*>(QStringLiteral("boltBox"));
    QCOMPARE(box->count(), 5);
    form->setBoltIndex(2);
    auto* strength = form->findChild<QDoubleSpinBox*>(QStringLiteral("bolt_strength"));
    auto* stiffness = form->findChild<QDoubleSpinBox*>(QStringLiteral("bolt_stiffness"));
    QVERIFY(strength && stiffness);
    QVERIFY(strength->suffix().contains(QStringLiteral("kN/m")));
    QCOMPARE(strength->value(), 160.0);
    QCOMPARE(stiffness->value(), 65.0);  // MN/m
    QUndoStack* undo = window.document()->undoStack();
    const int edits = undo->count();
    strength->setValue(200.0);
    QVERIFY(form->apply());
    QCOMPARE(window.document()->model().bolts[2].strength, 200e3);
    QCOMPARE(undo->count(), edits + 1);
    stiffness->setValue(0.0);
    QVERIFY(!form->apply());
    QVERIFY2(form->status().contains(QStringLiteral("bolt stiffness EA must be positive")), qPrintable(form->status()));
    QCOMPARE(window.document()->model().bolts[2].stiffness, 65e6);
    stiffness->setValue(65.0);
    auto* name = form->findChild<QLineEdit*>(QStringLiteral("boltName"));
    name->setText(QStringLiteral("roof bolt 1"));  // taken
    QVERIFY(!form->apply());
    QVERIFY2(form->status().contains(QStringLiteral("duplicate bolt name")), qPrintable(form->status()));
    name->setText(QStringLiteral("crown bolt"));
    QVERIFY(form->apply());
    const Model& m = window.document()->model();
    QCOMPARE(m.bolts[2].name, std::string("crown bolt"));
    QVERIFY(std::count(m.stages[2].install.begin(), m.stages[2].install.end(), std::string("crown bolt")) == 1);
    undo->undo();
    undo->undo();
    QCOMPARE(window.document()->model().bolts[2].strength, 160e3);
    QCOMPARE(window.document()->model().bolts[2].name, std::string("roof bolt 3"));
}

// The units chosen in the Results toolbar (Units ▸ MPa / kPa) reach the forms
// (moduli, strengths, in-situ stresses, pressures) and the Model tree; values typed in them mean
// the unit shown.
void PropertyEditorTest::unitsChosenReachFormsAndTree()
{
    MainWindow window;
    QVERIFY(show_model(window, QStringLiteral(MCDDA_EXAMPLES_DIR "/jointed-tunnel-staged.json")));
    QTRY_VERIFY(settled(window));
    PropertyEditor* editor = window.propertyEditor();
    const Material rock = window.document()->model().materials[0];
    auto* cohesion = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_mohr_coulomb_cohesion"));
    auto* modulus = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_young_modulus"));
    auto* pressure = editor->findChild<QDoubleSpinBox*>(QStringLiteral("loadPressure"));
    QVERIFY(cohesion && modulus && pressure);
    auto pressure_row = [&](const QString& unit) {
        for (QTreeWidgetItemIterator it(window.modelTree()); *it; ++it)
            if ((*it)->text(1).startsWith(QStringLiteral("pressure ")) && (*it)->text(1).endsWith(unit)) return (*it)->text(1);
        return QString();
    };
    auto* mpa = window.findChild<QAction*>(QStringLiteral("stressUnitMPa"));
    auto* kpa = window.findChild<QAction*>(QStringLiteral("stressUnitKPa"));
    QVERIFY(mpa && kpa);

    mpa->trigger();
    QVERIFY2(cohesion->suffix().contains(QStringLiteral("MPa")), qPrintable(cohesion->suffix()));
    QCOMPARE(cohesion->value(), rock.parameter("cohesion") / 1e6);
    QVERIFY(modulus->suffix().contains(QStringLiteral("MPa")));
    QVERIFY(editor->findChild<QDoubleSpinBox*>(QStringLiteral("stressXX"))->suffix().contains(QStringLiteral("MPa")));
    QVERIFY(pressure->suffix().contains(QStringLiteral("MPa")));
    QCOMPARE(pressure_row(QStringLiteral("MPa")), QStringLiteral("pressure 2 MPa"));
    cohesion->setValue(0.25);  // MPa
    QVERIFY(editor->applyMaterial());
    QCOMPARE(window.document()->model().materials[0].parameter("cohesion"), 0.25e6);

    kpa->trigger();
    QVERIFY(cohesion->suffix().contains(QStringLiteral("kPa")));
    QCOMPARE(cohesion->value(), 250.0);
    QVERIFY(modulus->suffix().contains(QStringLiteral("kPa")));
    QCOMPARE(modulus->value(), rock.young_modulus / 1e3);
    QCOMPARE(pressure_row(QStringLiteral("kPa")), QStringLiteral("pressure 2000 kPa"));
    QCOMPARE(gui::DisplayUnits::instance()->stress(), view::StressUnit::KPa);

    window.findChild<QAction*>(QStringLiteral("stressUnitAuto"))->trigger();  // as it was
    QVERIFY(modulus->suffix().contains(QStringLiteral("MPa")));
    QVERIFY(cohesion->suffix().contains(QStringLiteral("kPa")));
}

QTEST_MAIN(PropertyEditorTest)
#include "PropertyEditorTest.moc"
