// What an engineer who knows RS2, PLAXIS and UDEC met in the desktop window, each checked on a
// virtual X server: refusals in the units and words of the forms (no JSON pointers, no values
// in Pa), a new model that asks for a region instead of reporting an error, typed values applied
// on Apply or Enter only; a static analysis in load steps with DDA's numerical settings under
// Advanced, a history plotted against load steps, and the stage after the gravity stage
// resetting displacements by default.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "document/ModelDocument.hpp"
#include "panels/PropertyEditor.hpp"
#include "panels/StagesPanel.hpp"
#include "results/HistoryPlot.hpp"
#include "results/StepSlider.hpp"
#include "session/DisplayUnits.hpp"
#include "session/RunMessages.hpp"
#include "widgets/ModelTree.hpp"

#include "Language.hpp"

#include <QAction>
#include <QAbstractAxis>
#include <QChart>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGuiApplication>
#include <QDockWidget>
#include <QLabel>
#include <QListWidget>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <memory>

using namespace mcdda;
using mcdda::gui::MainWindow;
using mcdda::gui::PropertyEditor;

namespace {

/// Types `text` into a spin box as a user does: everything selected, then the keys.
void type_into(QAbstractSpinBox* box, const QString& text)
{
    box->selectAll();
    QTest::keyClicks(box, text);
}

}  // namespace

class EngineerTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void refusalSpeaksTheFormsUnitsAndWords();
    void typedValueWaitsForApplyOrEnter();
    void newModelAsksForARegion();
    void staticAnalysisSpeaksLoadSteps();
    void staticHistoryIsAgainstLoadSteps();
    void stageAfterGravityResetsDisplacements();
    void stagesDockNeverScrollsSideways();
    void germanNumbersTakeTheDecimalComma();  // last: it installs the German texts

private:
    std::unique_ptr<MainWindow> window_;
};

void EngineerTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    gui::DisplayUnits::instance()->set(view::StressUnit::Automatic, view::LengthUnit::Metre);  // E in MPa
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
    window_ = guitest::square_window();
    QVERIFY(window_);
    QTRY_VERIFY_WITH_TIMEOUT(guitest::settled(*window_), 60000);
}

// E typed as −100 MPa: refused as 'material "rock": Young's modulus must be positive (got
// −100 MPa)', not "(got -1e+08 Pa) (/materials/0/young_modulus)".
void EngineerTest::refusalSpeaksTheFormsUnitsAndWords()
{
    PropertyEditor* editor = window_->propertyEditor();
    gui::ModelDocument* doc = window_->document();
    const std::string name = doc->model().materials[0].name;
    const double before = doc->model().materials[0].young_modulus;
    auto* e = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_young_modulus"));
    QVERIFY(e && e->suffix().contains(QStringLiteral("MPa")));
    e->setValue(-100.0);
    editor->findChild<QPushButton*>(QStringLiteral("materialApply"))->click();
    const QString status = editor->materialStatus();
    QVERIFY2(status.contains(QStringLiteral("material \"%1\": ").arg(QString::fromStdString(name))), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("Young's modulus must be positive")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("(got \u2212100 MPa)")), qPrintable(status));
    QVERIFY2(!status.contains(QStringLiteral("/materials")) && !status.contains(QStringLiteral("e+")), qPrintable(status));
    QCOMPARE(doc->model().materials[0].young_modulus, before);

    // A ratio's interval, and a strength in the form's kPa.
    e->setValue(before / 1e6);
    auto* nu = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_poisson_ratio"));
    const double nu_before = nu->value();
    nu->setValue(0.5);
    QVERIFY(!editor->applyMaterial());
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("Poisson's ratio must lie in (\u22121, 0.5) (got 0.5)")),
             qPrintable(editor->materialStatus()));
    nu->setValue(nu_before);
    gui::DisplayUnits::instance()->set(view::StressUnit::KPa, view::LengthUnit::Metre);
    e->setValue(-5.0);
    QVERIFY(!editor->applyMaterial());
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("(got \u22125 kPa)")), qPrintable(editor->materialStatus()));
    gui::DisplayUnits::instance()->set(view::StressUnit::Automatic, view::LengthUnit::Metre);
    editor->refresh();
}

// A value typed and left (another field clicked: the spin box says editingFinished) is not
// applied and no "Applied." appears; Enter applies it, as Apply does.
void EngineerTest::typedValueWaitsForApplyOrEnter()
{
    PropertyEditor* editor = window_->propertyEditor();
    gui::ModelDocument* doc = window_->document();
    editor->refresh();
    auto* c = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_mohr_coulomb_cohesion"));
    QVERIFY(c && c->suffix().contains(QStringLiteral("kPa")));
    const double before = doc->model().materials[0].parameter("cohesion");
    const int commands = doc->undoStack()->count();
    type_into(c, QStringLiteral("250"));
    emit c->editingFinished();  // what leaving the field emits
    QCOMPARE(doc->model().materials[0].parameter("cohesion"), before);
    QCOMPARE(doc->undoStack()->count(), commands);
    QVERIFY2(!editor->materialStatus().contains(QStringLiteral("Applied")), qPrintable(editor->materialStatus()));
    QTest::keyClick(c, Qt::Key_Return);
    QCOMPARE(doc->model().materials[0].parameter("cohesion"), 250e3);
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("Applied")), qPrintable(editor->materialStatus()));
    QCOMPARE(doc->undoStack()->count(), commands + 1);

    // The same rule in the other forms: the mesh size and a name.
    auto* size = window_->findChild<QDoubleSpinBox*>(QStringLiteral("meshSize"));
    QVERIFY(size);
    const double mesh_before = doc->model().mesh.size;
    type_into(size, QStringLiteral("0.7"));
    emit size->editingFinished();
    QCOMPARE(doc->model().mesh.size, mesh_before);
    auto* name = editor->findChild<QLineEdit*>(QStringLiteral("materialName"));
    name->setText(QStringLiteral("granite"));
    emit name->editingFinished();
    QVERIFY(doc->model().materials[0].name != "granite");
    QTest::keyClick(name, Qt::Key_Return);
    QCOMPARE(doc->model().materials[0].name, std::string("granite"));
    doc->undoStack()->undo();
    doc->undoStack()->undo();
}

// File ▸ New: the Messages dock and the status bar ask for a region; no "error: /regions".
void EngineerTest::newModelAsksForARegion()
{
    MainWindow window;
    window.setAskToSave(false);
    QVERIFY(guitest::show_new_model(window, 1100, 750));
    QTRY_VERIFY_WITH_TIMEOUT(!window.isPreprocessing() && window.modelView()->scene(), 30000);
    const QString messages = window.messages();
    QVERIFY2(messages.contains(QStringLiteral("Draw a region to start")), qPrintable(messages));
    QVERIFY2(!messages.contains(QStringLiteral("error")) && !messages.contains(QStringLiteral("/regions")), qPrintable(messages));
    QVERIFY2(window.statisticsText().contains(QStringLiteral("Draw a region")), qPrintable(window.statisticsText()));
    QVERIFY2(!window.statisticsText().contains(QStringLiteral("error")), qPrintable(window.statisticsText()));
}

// The Analysis tab of a static analysis: "Load steps", no time step in sight (it is under a
// collapsed Advanced, with its default explained), and the log counts load steps without t.
void EngineerTest::staticAnalysisSpeaksLoadSteps()
{
    PropertyEditor* editor = window_->propertyEditor();
    auto* tabs = editor->findChild<QTabWidget*>(QStringLiteral("propertyTabs"));
    tabs->setCurrentIndex(2);  // Analysis
    auto* steps = editor->findChild<QSpinBox*>(QStringLiteral("analysisSteps"));
    auto* form = qobject_cast<QFormLayout*>(steps->parentWidget()->layout());
    QVERIFY(form);
    auto* label = qobject_cast<QLabel*>(form->labelForField(steps));
    QVERIFY(label);
    QCOMPARE(label->text(), QStringLiteral("Load steps"));
    for (const char* key : {"analysis_time_step", "analysis_penalty", "analysis_dynamic_ratio", "analysis_max_displacement_ratio"}) {
        auto* box = editor->findChild<QDoubleSpinBox*>(QString::fromLatin1(key));
        QVERIFY2(box && !box->isVisibleTo(editor), key);
    }
    auto* advanced = editor->findChild<QToolButton*>(QStringLiteral("analysisAdvanced"));
    QVERIFY(advanced && advanced->isVisibleTo(editor) && !advanced->isChecked());
    advanced->click();
    auto* dt = editor->findChild<QDoubleSpinBox*>(QStringLiteral("analysis_time_step"));
    QVERIFY(dt->isVisibleTo(editor));
    auto* note = editor->findChild<QLabel*>(QStringLiteral("analysis_time_step_note"));
    QVERIFY(note && note->isVisibleTo(editor));
    QVERIFY2(note->text().startsWith(QStringLiteral("Default 0.01 s.")) && note->text().contains(QStringLiteral("load steps")),
             qPrintable(note->text()));
    auto* penalty = editor->findChild<QLabel*>(QStringLiteral("analysis_penalty_note"));
    QVERIFY2(penalty && penalty->text().startsWith(QStringLiteral("Default automatic.")), qPrintable(penalty->text()));
    advanced->click();
    QVERIFY(!dt->isVisibleTo(editor));

    gui::RunProgress p;
    p.step = 3;
    p.total_steps = 20;
    p.time = 3.0;
    p.time_step = 1.0;
    p.load_steps = true;
    QVERIFY2(gui::progress_line(p).startsWith(QStringLiteral("load step 3/20")), qPrintable(gui::progress_line(p)));
    QVERIFY2(!gui::progress_line(p).contains(QStringLiteral("t = ")), qPrintable(gui::progress_line(p)));
}

// The history of a static model is plotted against the load step, and the Steps dock names
// load steps without a time.
void EngineerTest::staticHistoryIsAgainstLoadSteps()
{
    QTemporaryDir dir;
    QFile csv(dir.filePath(QStringLiteral("history.csv")));
    QVERIFY(csv.open(QIODevice::WriteOnly));
    csv.write("step,time,stage,unbalanced_ratio,P:ux,P:uy\n0,0,1,0,0,0\n1,1,1,0.1,0,-0.001\n2,2,1,0.01,0,-0.002\n");
    csv.close();
    gui::HistoryPlot* plot = window_->historyPlot();
    QCOMPARE(plot->load(csv.fileName()), 3);
    QCOMPARE(plot->xColumn(), QStringLiteral("step"));
    QCOMPARE(plot->chart()->axes(Qt::Horizontal).first()->titleText(), QStringLiteral("load step"));
    plot->clear();

    QFile pvd(dir.filePath(QStringLiteral("m.pvd")));
    QVERIFY(pvd.open(QIODevice::WriteOnly));
    pvd.write("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n"
              "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"m_000000.vtu\"/>\n"
              "    <DataSet timestep=\"10\" group=\"\" part=\"0\" file=\"m_000010.vtu\"/>\n  </Collection>\n</VTKFile>\n");
    pvd.close();
    auto* steps = window_->findChild<gui::StepSlider*>();
    QVERIFY(steps);
    QCOMPARE(steps->load(pvd.fileName()), 2);
    auto* label = steps->findChild<QLabel*>(QStringLiteral("stepLabel"));
    QVERIFY2(label->text() == QStringLiteral("load step 10 (2 of 2)"), qPrintable(label->text()));
    steps->clear();
}

// Stages of a model with gravity: the first is the gravity stage, the one after it resets the
// displacements (RS2's and PLAXIS's reset) unless the user clears the box.
void EngineerTest::stageAfterGravityResetsDisplacements()
{
    gui::ModelDocument* doc = window_->document();
    QVERIFY(doc->model().gravity.y < 0.0);
    auto* panel = window_->findChild<gui::StagesPanel*>();
    QVERIFY(panel);
    auto* add = panel->findChild<QPushButton*>(QStringLiteral("addStage"));
    add->click();
    add->click();
    QCOMPARE(doc->model().stages.size(), std::size_t(2));
    QVERIFY(!doc->model().stages[0].reset_displacements);
    QVERIFY(doc->model().stages[1].reset_displacements);
    auto* reset = panel->findChild<QCheckBox*>(QStringLiteral("stageResetDisplacements"));
    QVERIFY(reset);
    panel->setCurrentStage(1);
    QVERIFY(reset->isChecked() && reset->isEnabled());
    panel->setCurrentStage(0);
    QVERIFY(!reset->isChecked());
    auto* steps = panel->findChild<QSpinBox*>(QStringLiteral("stageSteps"));
    auto* label = qobject_cast<QLabel*>(qobject_cast<QFormLayout*>(steps->parentWidget()->layout())->labelForField(steps));
    QCOMPARE(label->text(), QStringLiteral("Load steps"));
    QVERIFY(!panel->findChild<QDoubleSpinBox*>(QStringLiteral("stage_time_step"))->isVisibleTo(panel));
    // Cleared and applied: the stage keeps it cleared.
    panel->setCurrentStage(1);
    reset->setChecked(false);
    panel->findChild<QPushButton*>(QStringLiteral("applyStage"))->click();
    QVERIFY(!doc->model().stages[1].reset_displacements);
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    QVERIFY(doc->model().stages.empty());
}

// The Stages dock at its default width: long names are elided (whole in the tooltip), no list
// and not the settings scroll sideways, and a splitter shares the height between list and settings.
void EngineerTest::stagesDockNeverScrollsSideways()
{
    gui::ModelDocument* doc = window_->document();
    Roller roller;
    roller.name = "temporary support of the top heading, left side, installed after the second round";
    roller.from = {10, 0};
    roller.to = {10, 10};
    roller.fix_x = true;
    doc->addRoller(roller);
    auto* panel = window_->findChild<gui::StagesPanel*>();
    panel->findChild<QPushButton*>(QStringLiteral("addStage"))->click();
    panel->setCurrentStage(0);
    auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("stages"));
    dock->raise();
    QTRY_VERIFY(panel->isVisible());
    QTest::qWait(100);
    QVERIFY2(dock->width() < 450, qPrintable(QString::number(dock->width())));
    QVERIFY(panel->findChild<QSplitter*>(QStringLiteral("stageSplitter")));
    for (const char* name : {"stageList", "stageExcavate", "stageActivate", "stageInstall", "stageRemove"}) {
        auto* list = panel->findChild<QListWidget*>(QString::fromLatin1(name));
        QVERIFY2(list && !list->horizontalScrollBar()->isVisible(), name);
        QVERIFY2(list->width() <= dock->width(), name);
    }
    auto* install = panel->findChild<QListWidget*>(QStringLiteral("stageInstall"));
    const QListWidgetItem* last = install->item(install->count() - 1);
    QVERIFY(last->toolTip().contains(QString::fromStdString(roller.name)));
    auto* scroll = panel->findChild<QScrollArea*>(QStringLiteral("stageSettingsScroll"));
    QVERIFY(scroll && !scroll->horizontalScrollBar()->isVisible());
    QVERIFY2(scroll->widget()->width() <= scroll->viewport()->width(),
             qPrintable(QStringLiteral("%1 > %2").arg(scroll->widget()->width()).arg(scroll->viewport()->width())));
    window_->grab().save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/engineer_stages_dock.png"));
    doc->undoStack()->undo();
    doc->undoStack()->undo();
}

// In German every number of the window takes the decimal comma: the joint set's spacing in
// the Model tree ("Abstand 6,5 m", not "6.5" beside "0,6044") and a refusal's value.
void EngineerTest::germanNumbersTakeTheDecimalComma()
{
    QObject owner;
    QVERIFY(i18n::install_translations(i18n::choose_locale(QStringLiteral("de")), &owner).mcdda);
    QCOMPARE(QLocale().decimalPoint(), QStringLiteral(","));
    gui::ModelDocument* doc = window_->document();
    JointSet set;
    set.name = "J1";
    set.angle = 0.5;
    set.spacing = 6.5;
    set.origin = {5, 5};
    doc->addJointSet(set);
    auto* tree = window_->findChild<gui::ModelTree*>();
    QVERIFY(tree);
    const auto found = tree->findItems(QStringLiteral("Abstand 6,5 m"), Qt::MatchContains | Qt::MatchRecursive, 1);
    QVERIFY2(!found.isEmpty(), "no \"Abstand 6,5 m\" in the Model tree");
    QVERIFY(tree->findItems(QStringLiteral("6.5"), Qt::MatchContains | Qt::MatchRecursive, 1).isEmpty());
    PropertyEditor* editor = window_->propertyEditor();
    editor->refresh();
    auto* nu = editor->findChild<QDoubleSpinBox*>(QStringLiteral("material_poisson_ratio"));
    nu->setValue(0.55);
    QVERIFY(!editor->applyMaterial());
    QVERIFY2(editor->materialStatus().contains(QStringLiteral("0,55")) && !editor->materialStatus().contains(QStringLiteral("0.55")),
             qPrintable(editor->materialStatus()));
    editor->refresh();
    doc->undoStack()->undo();
    QLocale::setDefault(QLocale::c());
}

QTEST_MAIN(EngineerTest)
#include "EngineerTest.moc"
