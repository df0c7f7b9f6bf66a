// Model editing in the desktop program on a (virtual) X server: File ▸ New, drawing a region
// and a joint with simulated clicks (grid snapping), the picture, undo/redo, saving and opening
// the file again in another window.

#include "MainWindow.hpp"
#include "ModelCompare.hpp"
#include "WindowProbe.hpp"
#include "dialogs/JointSetDialog.hpp"
#include "document/ModelDocument.hpp"
#include "panels/LoadForm.hpp"
#include "panels/PropertyEditor.hpp"
#include "session/RunController.hpp"
#include "tools/DrawTool.hpp"
#include "tools/EditingTools.hpp"
#include "view/Palette.hpp"
#include "widgets/ModelTree.hpp"
#include "results/StepSlider.hpp"
#include <QFile>
#include <QLabel>
#include <QScrollBar>
#include <QPlainTextEdit>
#include <QMenuBar>
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QUndoStack>
#include <QApplication>
#include <QTextBrowser>
#include <QDialog>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

#include <cmath>

using namespace mcdda;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;
using namespace mcdda::guitest;


class EditingTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void drawUndoRedoSaveOpen();
    void typedPointsHolesAndJointSets();
    void everyShortcutIsUnique();
    void stagesAndBoltsShownInTheTree();
    void undoFromTheCoordinateField();
    void viewMenuMessagesAndStepLabel();
    void helpShowsTheUserGuide();
    void newModelTalksOfRegionsAndFitsTheFirst();
    void typedPointsStayInSightWithRulers();
    void stageListShowsAndEditsStages();
    void boltToolDrawsABolt();
    void tinyBlocksAreReported();
    void importDxfMakesAModel();
};

void EditingTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);  // Recent Files go to a test settings file
    gui::register_run_types();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

void EditingTest::drawUndoRedoSaveOpen()
{
    MainWindow window;
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QAction* new_action = window.findChild<QAction*>(QStringLiteral("newAction"));
    QVERIFY(new_action);
    new_action->trigger();
    gui::ModelDocument* doc = window.document();
    QCOMPARE(doc->model().materials.size(), std::size_t(1));
    QCOMPARE(doc->model().joint_materials.size(), std::size_t(1));
    // A round unit weight (25.5 kN/m³, it read 25.506).
    QVERIFY(std::fabs(doc->model().materials[0].density * 9.81 - 25.5e3) < 1e-9);
    QVERIFY(doc->model().regions.empty());
    QVERIFY(!doc->isModified());
    QVERIFY(window.windowTitle().contains(QStringLiteral("Untitled")));

    ModelView* view = window.modelView();
    QVERIFY(count_around(*view, 5, 5, view::palette::background) >= 70);

    // A 10 m square, clicked a little off the grid nodes: the grid (0.5 m) puts it right.
    window.findChild<QAction*>(QStringLiteral("drawRegionAction"))->trigger();
    QVERIFY(window.activeTool() != nullptr);
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 0.1, -0.12));
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 10.15, 0.08));
    QTest::mouseMove(view, pixel_of(*view, 9.9, 9.9));
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 9.9, 9.9));
    QCOMPARE(view->preview().size(), std::size_t(3));  // the rubber band: 3 vertices
    QTest::mouseDClick(view, Qt::LeftButton, {}, pixel_of(*view, -0.1, 10.1));
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    QVERIFY(view->preview().empty());
    const Ring& ring = doc->model().regions[0].boundary;
    QCOMPARE(ring.size(), std::size_t(4));
    const double expected[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    for (int i = 0; i < 4; ++i) {
        QCOMPARE(ring[static_cast<std::size_t>(i)].x, expected[i][0]);
        QCOMPARE(ring[static_cast<std::size_t>(i)].y, expected[i][1]);
    }
    QCOMPARE(doc->model().regions[0].material, 0);
    QVERIFY(doc->isModified());
    QVERIFY(window.isWindowModified());

    // A joint across it; its first point snaps to nothing but the grid.
    window.findChild<QAction*>(QStringLiteral("drawJointAction"))->trigger();
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, -2.05, 3.1));
    QTest::mouseDClick(view, Qt::LeftButton, {}, pixel_of(*view, 12.1, 2.9));
    QCOMPARE(doc->model().joints.size(), std::size_t(1));
    QCOMPARE(doc->model().joints[0].points.size(), std::size_t(2));
    QCOMPARE(doc->model().joints[0].points[0].y, 3.0);
    QCOMPARE(doc->model().joints[0].points[1].x, 12.0);

    // The snap marker sits where a click would land; the grid is drawn while a drawing tool
    // is active (compare a spot outside the model with and without it).
    QTest::mouseMove(view, pixel_of(*view, 11.1, 5.9));
    Point2 marker;
    QVERIFY(view->snapMarker(&marker));
    QCOMPARE(marker.x, 11.0);
    QCOMPARE(marker.y, 6.0);
    QVERIFY(count_around(*view, 11.0, 6.0, view::palette::snap_marker, 3) >= 20);
    QCOMPARE(view->gridSpacing(), 0.5);
    const QImage with_grid = view->grabFrame();
    window.findChild<QAction*>(QStringLiteral("selectToolAction"))->trigger();
    QCOMPARE(view->gridSpacing(), 0.0);
    QVERIFY(!view->snapMarker());
    const QImage without_grid = view->grabFrame();
    int changed = 0;
    const QPointF outside = view->toWidget(QPointF(-1.3, 5.0)) * view->devicePixelRatioF();
    for (int y = qRound(outside.y()) - 40; y < qRound(outside.y()) + 40; ++y)
        changed += with_grid.pixelColor(qRound(outside.x()), y) != without_grid.pixelColor(qRound(outside.x()), y);
    QVERIFY2(changed >= 2, qPrintable(QString::number(changed)));
    window.findChild<QAction*>(QStringLiteral("drawJointAction"))->trigger();

    // Escape drops a half-drawn joint.
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 1, 1));
    QCOMPARE(view->preview().size(), std::size_t(1));
    QTest::keyClick(view, Qt::Key_Escape);
    QVERIFY(view->preview().empty());
    QCOMPARE(doc->model().joints.size(), std::size_t(1));
    window.findChild<QAction*>(QStringLiteral("selectToolAction"))->trigger();  // no grid over the checks below

    const view::Rgb rock = view::material_color(0);
    // The picture follows once the edit has been pre-processed on the thread pool.
    QTRY_VERIFY2(count_around(*view, 5, 7, rock) >= 40, "the square is filled with the material colour");
    QVERIFY(window.modelTree()->topLevelItem(0)->childCount() == 1);  // Regions

    QAction* undo = window.findChild<QAction*>(QStringLiteral("undoAction"));
    QAction* redo = window.findChild<QAction*>(QStringLiteral("redoAction"));
    QVERIFY(undo && redo);
    QVERIFY(undo->text().contains(QStringLiteral("joint")));
    undo->trigger();
    undo->trigger();
    QVERIFY(doc->model().regions.empty());
    QVERIFY(doc->model().joints.empty());
    QVERIFY(!doc->isModified());
    QTRY_VERIFY(count_around(*view, 5, 7, view::palette::background) >= 70);
    redo->trigger();
    redo->trigger();
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    QCOMPARE(doc->model().joints.size(), std::size_t(1));
    QTRY_VERIFY(count_around(*view, 5, 7, rock) >= 40);

    // A roller along the base (no support tool yet) makes the model usable.
    Roller base;
    base.name = "base";
    base.from = {0, 0};
    base.to = {10, 0};
    base.fix_x = true;
    base.fix_y = true;
    doc->addRoller(base);
    QTRY_VERIFY2(!window.isPreprocessing() && view->scene() && view->scene()->ok, qPrintable(window.messages()));
    QVERIFY(window.modelTree()->topLevelItem(4)->childCount() == 1);  // Supports

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("drawn.json"));
    QVERIFY(window.saveModelAs(path));
    QVERIFY(!doc->isModified());
    QVERIFY(!window.isWindowModified());
    QVERIFY(window.windowTitle().contains(QStringLiteral("drawn.json")));
    QVERIFY(window.recentFiles().contains(QFileInfo(path).absoluteFilePath()));

    MainWindow other;
    other.resize(800, 600);
    other.show();
    QVERIFY(QTest::qWaitForWindowExposed(&other));
    QVERIFY2(other.openModel(path), qPrintable(other.messages()));
    const std::string diff = test::ModelComparer(1e-12).compare(doc->model(), other.document()->model());
    QVERIFY2(diff.empty(), diff.c_str());
    QCOMPARE(other.document()->path(), path);
    QVERIFY(!other.document()->isModified());

    // The drawn model runs: gravity from the Loads tab, three steps, coloured by displacement.
    other.setRunOutputFolder(dir.filePath(QStringLiteral("results")));
    QVERIFY(other.propertyEditor()->loadForm()->setStandardGravity());
    AnalysisSettings analysis = other.document()->model().analysis;
    analysis.steps = 3;
    analysis.output_every = 1;
    other.document()->setAnalysisSettings(analysis);
    QTRY_VERIFY2(settled(other), qPrintable(other.messages()));
    QSignalSpy finished(&other, &MainWindow::runFinished);
    QVERIFY(other.startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Completed);
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("results/drawn.pvd"))));
    const QImage result = other.modelView()->grabFrame();
    const QPointF top = other.modelView()->toWidget(QPointF(5.0, 9.0)) * other.modelView()->devicePixelRatioF();
    const QColor c = result.pixelColor(top.toPoint());
    QVERIFY2(c.hsvSaturation() > 120, qPrintable(c.name()));  // a contour colour, not the rock's pale fill
}

namespace {

/// Types "x, y" (or nothing: finish) into the Tool Options' coordinate field and presses Enter.
void type_point(QLineEdit* edit, const QString& text)
{
    edit->setText(text);
    QTest::keyClick(edit, Qt::Key_Return);
}

}  // namespace

void EditingTest::typedPointsHolesAndJointSets()
{
    MainWindow window;
    window.setAskToSave(false);
    QVERIFY(guitest::show_new_model(window));
    gui::ModelDocument* doc = window.document();
    auto* edit = window.findChild<QLineEdit*>(QStringLiteral("coordinateEdit"));
    QVERIFY(edit);
    QVERIFY(!edit->isEnabled());  // Select is active

    // A triangle typed off the grid: the typed points are taken as they are.
    window.findChild<QAction*>(QStringLiteral("drawRegionAction"))->trigger();
    QVERIFY(edit->isEnabled());
    type_point(edit, QStringLiteral("0.1, 0.2"));
    type_point(edit, QStringLiteral("4.3,0.2"));
    QVERIFY(edit->text().isEmpty());  // cleared after each accepted point
    type_point(edit, QStringLiteral("not a point"));
    QCOMPARE(edit->text(), QStringLiteral("not a point"));  // kept to be corrected
    QCOMPARE(window.activeTool()->points().size(), std::size_t(2));
    type_point(edit, QStringLiteral("0.1 3.7"));
    QCOMPARE(window.modelView()->preview().size(), std::size_t(3));
    type_point(edit, QString());  // Enter on the empty field closes the polygon
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    const double triangle[3][2] = {{0.1, 0.2}, {4.3, 0.2}, {0.1, 3.7}};
    const Ring& t = doc->model().regions[0].boundary;
    QCOMPARE(t.size(), std::size_t(3));
    for (std::size_t i = 0; i < 3; ++i) {
        QCOMPARE(t[i].x, triangle[i][0]);
        QCOMPARE(t[i].y, triangle[i][1]);
    }
    doc->undoStack()->undo();
    QVERIFY(doc->model().regions.empty());

    // A 10 m square with a square hole drawn inside it (Tool Options ▸ Hole).
    for (const char* p : {"0, 0", "10, 0", "10, 10", "0, 10", ""}) type_point(edit, QString::fromLatin1(p));
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    auto* hole = window.findChild<QCheckBox*>(QStringLiteral("holeBox"));
    QVERIFY(hole);
    hole->setChecked(true);
    for (const char* p : {"4, 4", "6, 4", "6, 6", "4, 6", ""}) type_point(edit, QString::fromLatin1(p));
    hole->setChecked(false);
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    QCOMPARE(doc->model().regions[0].holes.size(), std::size_t(1));
    QCOMPARE(doc->model().regions[0].holes[0].size(), std::size_t(4));
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("hole")));
    doc->undoStack()->undo();
    QVERIFY(doc->model().regions[0].holes.empty());
    doc->undoStack()->redo();
    QCOMPARE(doc->model().regions[0].holes.size(), std::size_t(1));

    // A hole outside every region is refused.
    hole->setChecked(true);
    for (const char* p : {"20, 20", "22, 20", "22, 22", ""}) type_point(edit, QString::fromLatin1(p));
    hole->setChecked(false);
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    QCOMPARE(doc->model().regions[0].holes.size(), std::size_t(1));

    Roller base;
    base.from = {0, 0};
    base.to = {10, 0};
    base.fix_x = true;
    base.fix_y = true;
    doc->addRoller(base);
    QTRY_VERIFY2(!window.isPreprocessing() && window.modelView()->scene() && window.modelView()->scene()->ok,
                 qPrintable(window.messages()));
    const auto blocks_before = window.modelView()->scene()->statistics.blocks;

    // Edit ▸ Add Joint Set: the dialog with preset values, accepted.
    gui::JointSetDialog dialog(doc->model(), &window);
    JointSet preset;
    preset.angle = 0.0;
    preset.spacing = 3.0;
    preset.origin = {0.0, 1.5};
    preset.joint_material = 0;
    dialog.setJointSet(preset);
    dialog.accept();
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
    const JointSet entered = dialog.jointSet();
    QCOMPARE(entered.spacing, 3.0);
    QCOMPARE(entered.origin.y, 1.5);
    QVERIFY(!entered.extent);
    doc->addJointSet(entered);
    QCOMPARE(doc->model().joint_sets.size(), std::size_t(1));
    QCOMPARE(doc->model().joint_sets[0].name, std::string("joint set 1"));
    QTRY_VERIFY2(!window.isPreprocessing() && window.modelView()->scene() && window.modelView()->scene()->ok,
                 qPrintable(window.messages()));
    QVERIFY2(window.modelView()->scene()->statistics.blocks > blocks_before, qPrintable(window.statisticsText()));
    QTreeWidgetItem* joints = window.modelTree()->topLevelItem(2);  // Joints ▸ the set
    bool listed = false;
    for (int i = 0; i < joints->childCount(); ++i)
        listed = listed || joints->child(i)->text(0).contains(QStringLiteral("joint set 1"));
    QVERIFY(listed);

    // A zero spacing is refused by the dialog.
    gui::JointSetDialog bad(doc->model(), &window);
    preset.spacing = 0.0;
    bad.setJointSet(preset);
    bad.accept();
    QVERIFY(bad.result() != int(QDialog::Accepted));
    QVERIFY(!bad.validationError().isEmpty());
}

// Two actions with one shortcut make Qt ignore the key ("Ambiguous shortcut overload"): F5 once
// belonged to File ▸ Reload (QKeySequence::Refresh) and Run ▸ Run, and did nothing.
void EditingTest::everyShortcutIsUnique()
{
    gui::MainWindow window;
    window.show();
    QMap<QString, QString> owner;  // shortcut → action text
    bool f5_runs = false;  // (the Run menu's own action is called Run too, without a shortcut)
    for (QAction* action : window.findChildren<QAction*>()) {
        if (action->text().remove(QLatin1Char('&')) == QLatin1String("Run") &&
            action->shortcuts().contains(QKeySequence(Qt::Key_F5)))
            f5_runs = true;
        for (const QKeySequence& key : action->shortcuts()) {
            const QString name = key.toString(QKeySequence::PortableText);
            if (name.isEmpty()) continue;
            QVERIFY2(!owner.contains(name) || owner.value(name) == action->text(),
                     qPrintable(name + " is the shortcut of both " + owner.value(name) + " and " + action->text()));
            owner.insert(name, action->text());
        }
    }
    QVERIFY(f5_runs);
    QVERIFY(owner.size() > 10);  // the actions were found
}

// A staged model opens, and its stages and bolts are listed (read-only) with what they do.
void EditingTest::stagesAndBoltsShownInTheTree()
{
    gui::MainWindow window;
    window.show();
    QVERIFY2(window.openModel(QStringLiteral(MCDDA_EXAMPLES_DIR "/jointed-tunnel-staged.json")), qPrintable(window.messages()));
    QTreeWidgetItem* stages = nullptr;
    QTreeWidgetItem* bolts = nullptr;
    for (int i = 0; i < window.modelTree()->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = window.modelTree()->topLevelItem(i);
        if (item->text(0) == QLatin1String("Stages")) stages = item;
        if (item->text(0) == QLatin1String("Bolts")) bolts = item;
    }
    QVERIFY(stages != nullptr && bolts != nullptr);
    QCOMPARE(stages->childCount(), 4);
    QCOMPARE(bolts->childCount(), 5);
    QCOMPARE(stages->child(1)->text(0), QStringLiteral("2. top heading"));
    QVERIFY2(stages->child(1)->text(1).contains(QStringLiteral("excavates top heading")), qPrintable(stages->child(1)->text(1)));
    QVERIFY2(stages->child(2)->text(1).contains(QStringLiteral("installs roof bolt 1")), qPrintable(stages->child(2)->text(1)));
    QVERIFY2(stages->child(3)->text(1).startsWith(QStringLiteral("10 step")), qPrintable(stages->child(3)->text(1)));
    QCOMPARE(bolts->child(0)->text(0), QStringLiteral("roof bolt 1"));
}

// Ctrl+Z with the focus in the coordinate field undoes the last model edit
// (the field had nothing of its own to undo and swallowed the key).
void EditingTest::undoFromTheCoordinateField()
{
    MainWindow window;
    QVERIFY(guitest::show_new_model(window));
    gui::ModelDocument* doc = window.document();
    window.findChild<QAction*>(QStringLiteral("drawRegionAction"))->trigger();
    auto* field = window.findChild<QLineEdit*>(QStringLiteral("coordinateEdit"));
    QVERIFY(field && field->isEnabled());
    for (const char* point : {"0, 0", "10, 0", "10, 10", "0, 10"}) {
        field->setText(QString::fromLatin1(point));
        QTest::keyClick(field, Qt::Key_Return);
    }
    QTest::keyClick(field, Qt::Key_Return);  // Enter on the empty field finishes the region
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    // (No window manager under Xvfb: the window is made the active one by hand, as shortcuts
    // of the window's actions need.)
    QApplication::setActiveWindow(&window);
    field->setFocus();
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(doc->model().regions.size(), std::size_t(0));
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    // Text typed into the field is still undone there first.
    field->clear();
    QTest::keyClicks(field, QStringLiteral("3, 4"));
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
}

// The Properties dock is in the View menu; the Messages dock shows ten
// lines and keeps its newest line in sight; the step label names the step.
void EditingTest::viewMenuMessagesAndStepLabel()
{
    MainWindow window;
    window.resize(1200, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QMenu* view_menu = nullptr;
    for (QAction* a : window.menuBar()->actions())
        if (a->text().remove(QLatin1Char('&')) == QLatin1String("View")) view_menu = a->menu();
    QVERIFY(view_menu);
    bool properties = false;
    for (QAction* a : view_menu->actions()) properties = properties || a->text() == QLatin1String("Properties");
    QVERIFY(properties);

    auto* messages = window.findChild<QPlainTextEdit*>();
    QVERIFY(messages);
    QVERIFY2(messages->height() >= 8 * messages->fontMetrics().lineSpacing(), qPrintable(QString::number(messages->height())));
    QVERIFY2(window.openModel(QStringLiteral(MCDDA_EXAMPLES_DIR "/kirsch.json")), qPrintable(window.messages()));
    for (int k = 0; k < 40; ++k) messages->appendPlainText(QStringLiteral("earlier line %1").arg(k));
    messages->verticalScrollBar()->setValue(0);  // the user scrolled up to read
    QTemporaryDir out;
    window.setRunOutputFolder(out.path());
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY(messages->verticalScrollBar()->maximum() > 0);
    QCOMPARE(messages->verticalScrollBar()->value(), messages->verticalScrollBar()->maximum());
    QVERIFY(messages->toPlainText().endsWith(QStringLiteral("Results in ") + out.path()));

    // A results collection with steps 0 and 10: the label says "step 10".
    QTemporaryDir dir;
    QFile pvd(dir.filePath(QStringLiteral("m.pvd")));
    QVERIFY(pvd.open(QIODevice::WriteOnly));
    pvd.write("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n"
              "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"m_000000.vtu\"/>\n"
              "    <DataSet timestep=\"2.5\" group=\"\" part=\"0\" file=\"m_000010.vtu\"/>\n  </Collection>\n</VTKFile>\n");
    pvd.close();
    gui::StepSlider slider;
    QCOMPARE(slider.load(pvd.fileName()), 2);
    auto* label = slider.findChild<QLabel*>(QStringLiteral("stepLabel"));
    QVERIFY(label);
    QVERIFY2(label->text().startsWith(QStringLiteral("step 10 (2 of 2, t = 2.5 s)")), qPrintable(label->text()));
}

// F1 opens the user guide (compiled into the program), What's This is in
// the Help menu.
void EditingTest::helpShowsTheUserGuide()
{
    MainWindow window;
    window.show();
    QAction* guide = window.findChild<QAction*>(QStringLiteral("userGuideAction"));
    QVERIFY(guide);
    QVERIFY(guide->shortcuts().contains(QKeySequence(Qt::Key_F1)));
    QVERIFY(window.findChild<QAction*>(QStringLiteral("whatsThisAction")));
    guide->trigger();
    auto* dialog = window.findChild<QDialog*>(QStringLiteral("helpDialog"));
    QVERIFY(dialog && dialog->isVisible());
    auto* browser = dialog->findChild<QTextBrowser*>(QStringLiteral("helpBrowser"));
    QVERIFY(browser);
    const QString text = browser->toPlainText();
    QVERIFY2(text.contains(QStringLiteral("Run ▸ Run")) && text.contains(QStringLiteral("F5")), qPrintable(text.left(400)));
    window.findChild<QAction*>(QStringLiteral("modelFormatHelpAction"))->trigger();
    bool format_shown = false;
    for (auto* d : window.findChildren<QDialog*>(QStringLiteral("helpDialog")))
        if (auto* b = d->findChild<QTextBrowser*>(QStringLiteral("helpBrowser")))
            format_shown = format_shown || b->toPlainText().contains(QStringLiteral("Construction stages"));
    QVERIFY(format_shown);
}

// An empty new model asks for a region (not "nothing is fixed"), and the
// first region, typed far outside the default view, is brought into view.
void EditingTest::newModelTalksOfRegionsAndFitsTheFirst()
{
    MainWindow window;
    QVERIFY(guitest::show_new_model(window));
    QTRY_VERIFY(!window.isPreprocessing());
    // A hint, not an error (was "error: /regions: at least one region is required").
    QVERIFY2(window.messages().contains(QStringLiteral("Draw a region to start")), qPrintable(window.messages()));
    QVERIFY2(!window.messages().contains(QStringLiteral("error")), qPrintable(window.messages()));
    QVERIFY2(!window.messages().contains(QStringLiteral("nothing is fixed")), qPrintable(window.messages()));

    window.drawRegionTool();
    auto* field = window.findChild<QLineEdit*>(QStringLiteral("coordinateEdit"));
    for (const char* point : {"200, 100", "260, 100", "260, 140", "200, 140"}) {
        field->setText(QString::fromLatin1(point));
        QTest::keyClick(field, Qt::Key_Return);
    }
    QTest::keyClick(field, Qt::Key_Return);
    QTRY_VERIFY_WITH_TIMEOUT(!window.isPreprocessing() && window.modelView()->scene() &&
                                 !window.modelView()->scene()->model.regions.empty(), 30000);
    gui::ModelView* view = window.modelView();
    const QRect shown = view->rect();
    for (auto [x, y] : {std::pair{200.0, 100.0}, {260.0, 100.0}, {260.0, 140.0}, {200.0, 140.0}})
        QVERIFY2(shown.contains(guitest::pixel_of(*view, x, y)), qPrintable(QStringLiteral("(%1, %2) not in view").arg(x).arg(y)));
    // And it is drawn: the rock's colour fills the middle of the picture.
    const view::Rgb rock = view::material_color(0);
    QVERIFY(guitest::count_around(*view, 230.0, 120.0, rock) > 40);
    // Now "nothing is fixed" is worth saying.
    QVERIFY2(window.messages().contains(QStringLiteral("nothing is fixed")), qPrintable(window.messages()));
}

namespace {

/// Near-black pixels (ruler lines, ticks and numbers) in the strips the rulers take along the
/// left and bottom edges of the picture.
int ruler_ink(const QImage& picture)
{
    int ink = 0;
    for (int y = 0; y < picture.height(); ++y)
        for (int x = 0; x < picture.width(); ++x) {
            if (x >= 50 && y < picture.height() - 38) continue;
            const QColor c = picture.pixelColor(x, y);
            ink += c.red() < 90 && c.green() < 90 && c.blue() < 90;
        }
    return ink;
}

}  // namespace

// Typing the first region of a new model: rulers from the first point on (the model has no
// extent yet), and the view widens to a point typed beyond it instead of letting the shape run
// off the picture.
void EditingTest::typedPointsStayInSightWithRulers()
{
    MainWindow window;
    window.setAskToSave(false);
    QVERIFY(guitest::show_new_model(window));
    QTRY_VERIFY(!window.isPreprocessing());
    gui::ModelView* view = window.modelView();
    window.drawRegionTool();
    auto* field = window.findChild<QLineEdit*>(QStringLiteral("coordinateEdit"));
    const int empty_ink = ruler_ink(view->grabFrame());
    type_point(field, QStringLiteral("0, 0"));
    const int drawing_ink = ruler_ink(view->grabFrame());
    QVERIFY2(drawing_ink > empty_ink + 100, qPrintable(QStringLiteral("ruler ink %1 before the first point, %2 after")
                                                           .arg(empty_ink).arg(drawing_ink)));
    // Far beyond the picture (it shows a few tens of metres): the view follows, and both points
    // and the edge between them are drawn.
    const QRect shown = view->rect();
    QVERIFY(!shown.contains(guitest::pixel_of(*view, 400.0, 300.0)));
    type_point(field, QStringLiteral("400, 300"));
    for (auto [x, y] : {std::pair{0.0, 0.0}, {400.0, 300.0}})
        QVERIFY2(shown.contains(guitest::pixel_of(*view, x, y)), qPrintable(QStringLiteral("(%1, %2) not in view").arg(x).arg(y)));
    const QImage wide = view->grabFrame();
    const QPoint middle = guitest::pixel_of(*view, 200.0, 150.0);
    int blue = 0;
    for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx) {
            const QColor c = wide.pixelColor(middle.x() + dx, middle.y() + dy);
            blue += c.blue() > 150 && c.red() < 80;
        }
    QVERIFY2(blue > 0, "the edge being drawn is not in the picture");
    // The rulers now span hundreds of metres: still drawn.
    QVERIFY(ruler_ink(wide) > empty_ink + 100);
    // Once the region is closed the model's own rulers take over.
    type_point(field, QStringLiteral("0, 300"));
    type_point(field, QString());
    QTRY_VERIFY_WITH_TIMEOUT(!window.isPreprocessing() && view->scene() && !view->scene()->model.regions.empty(), 30000);
    QVERIFY(ruler_ink(view->grabFrame()) > empty_ink + 100);
}

// Stages in the window: the Stages dock lists the staged jointed tunnel's stages; the
// picture shows the model as it stands in the stage chosen (the top heading gone from the stage
// that excavates it on); stages are added, renamed, edited and removed as undoable edits.
void EditingTest::stageListShowsAndEditsStages()
{
    MainWindow window;
    QVERIFY(guitest::show_model(window, QStringLiteral(MCDDA_EXAMPLES_DIR "/jointed-tunnel-staged.json")));
    QTRY_VERIFY(guitest::settled(window));
    auto* list = window.findChild<QListWidget*>(QStringLiteral("stageList"));
    QVERIFY(list);
    const Model& model = window.document()->model();
    QCOMPARE(list->count(), static_cast<int>(model.stages.size()) + 1);  // and "as drawn"
    QVERIFY(list->item(2)->text().contains(QStringLiteral("top heading")));
    // The tree gives the overburden as the forms do, 2 MPa (not "2e+06 Pa").
    QVERIFY(!window.modelTree()->findItems(QStringLiteral("pressure 2 MPa"), Qt::MatchRecursive, 1).isEmpty());
    gui::ModelView* view = window.modelView();
    view::SceneOptions plain = view->sceneOptions();
    plain.show_mesh = false;  // the fine mesh around the tunnel would hide the fill
    plain.show_joints = false;
    view->setSceneOptions(plain);
    const view::Rgb rock = view::material_color(model.regions[1].material);
    const Point2 heading{0.0, 1.6};  // inside the top heading (radius 3, above the springline)
    list->setCurrentRow(1);  // in situ: everything stands
    QVERIFY2(guitest::count_around(*view, heading.x, heading.y, rock) > 40, "rock in the heading before it is dug");
    list->setCurrentRow(2);  // top heading excavated
    QCOMPARE(guitest::count_around(*view, heading.x, heading.y, rock), 0);
    QVERIFY(guitest::count_around(*view, heading.x, heading.y, view::palette::background) > 40);
    // The rock mass stays: the middle of its largest block (convex: cut by straight joints).
    const Block* largest = nullptr;
    for (const Block& b : view->scene()->blocks)
        if (b.region == 0 && b.outer.front().y < -5.0 && (!largest || b.area > largest->area)) largest = &b;
    QVERIFY(largest);
    Point2 middle{0.0, 0.0};
    for (const Point2& q : largest->outer) middle.x += q.x / largest->outer.size(), middle.y += q.y / largest->outer.size();
    QVERIFY(guitest::count_around(*view, middle.x, middle.y, rock) > 40);
    // The roof bolts are drawn from the stage that installs them on, and the stage's lists say so.
    const Point2 bolt{0.0, 6.0};  // on roof bolt 3
    QCOMPARE(guitest::count_around(*view, bolt.x, bolt.y, view::palette::bolt, 3), 0);
    QCOMPARE(window.findChild<QSpinBox*>(QStringLiteral("stageSteps"))->value(), 5);
    QCOMPARE(window.findChild<QSpinBox*>(QStringLiteral("stageRelease"))->value(), 10);
    list->setCurrentRow(3);  // roof bolts
    QVERIFY(guitest::count_around(*view, bolt.x, bolt.y, view::palette::bolt, 3) > 5);
    auto* installs = window.findChild<QListWidget*>(QStringLiteral("stageInstall"));
    QVERIFY(installs);
    int installed = 0;
    for (int i = 0; i < installs->count(); ++i)
        if (installs->item(i)->checkState() == Qt::Checked) {
            ++installed;
            QVERIFY2(installs->item(i)->text().contains(QStringLiteral("roof bolt")), qPrintable(installs->item(i)->text()));
        }
    QCOMPARE(installed, 5);
    list->setCurrentRow(0);  // the model as drawn
    QVERIFY(guitest::count_around(*view, heading.x, heading.y, rock) > 40);
    // At the default window size the legend leaves the model's top-right corner in sight.
    const Block* corner = nullptr;
    for (const Block& b : view->scene()->blocks)
        if (b.region == 0 && std::all_of(b.outer.begin(), b.outer.end(), [](const Point2& q) { return q.x > 8.0 && q.y > 8.0; }) &&
            (!corner || b.area > corner->area))
            corner = &b;
    QVERIFY(corner);
    Point2 corner_middle{0.0, 0.0};
    for (const Point2& q : corner->outer)
        corner_middle.x += q.x / corner->outer.size(), corner_middle.y += q.y / corner->outer.size();
    QVERIFY2(guitest::count_around(*view, corner_middle.x, corner_middle.y, rock) > 40, "the legend covers the model");

    // Add a stage, name it, let it build the top heading again (a backfill), undo all of it.
    QUndoStack* undo = window.document()->undoStack();
    const int edits = undo->count();
    window.findChild<QPushButton*>(QStringLiteral("addStage"))->click();
    QCOMPARE(window.document()->model().stages.size(), model.stages.size());  // `model` follows the document
    QCOMPARE(list->count(), static_cast<int>(window.document()->model().stages.size()) + 1);
    const int added = list->currentRow() - 1;
    QCOMPARE(added, static_cast<int>(window.document()->model().stages.size()) - 1);
    window.findChild<QLineEdit*>(QStringLiteral("stageName"))->setText(QStringLiteral("backfill"));
    auto* builds = window.findChild<QListWidget*>(QStringLiteral("stageActivate"));
    builds->item(1)->setCheckState(Qt::Checked);
    auto* removes = window.findChild<QListWidget*>(QStringLiteral("stageRemove"));
    const QList<QListWidgetItem*> first_bolt = removes->findItems(QStringLiteral("roof bolt 1"), Qt::MatchStartsWith);
    QCOMPARE(first_bolt.size(), 1);
    first_bolt.front()->setCheckState(Qt::Checked);
    window.findChild<QSpinBox*>(QStringLiteral("stageSteps"))->setValue(4);
    window.findChild<QSpinBox*>(QStringLiteral("stageRelease"))->setValue(2);
    auto* time_step = window.findChild<QDoubleSpinBox*>(QStringLiteral("stage_time_step"));
    QVERIFY(time_step && time_step->isEnabled());
    QCOMPARE(time_step->value(), window.document()->model().analysis.time_step);  // a new stage starts from the model's
    time_step->setValue(2.5);
    window.findChild<QPushButton*>(QStringLiteral("applyStage"))->click();
    const Stage& edited = window.document()->model().stages.back();
    QCOMPARE(edited.name, std::string("backfill"));
    QCOMPARE(edited.activate, std::vector<int>{1});
    QCOMPARE(edited.remove, std::vector<std::string>{"roof bolt 1"});
    QCOMPARE(edited.analysis.steps, 4);
    QCOMPARE(edited.release_steps, 2);
    QCOMPARE(edited.analysis.time_step, 2.5);
    QCOMPARE(edited.analysis.plastic_tolerance, window.document()->model().analysis.plastic_tolerance);  // untouched
    QCOMPARE(guitest::count_around(*view, 4.26, 4.26, view::palette::bolt, 3), 0);  // roof bolt 1 taken out
    QCOMPARE(undo->count(), edits + 2);
    QVERIFY(guitest::count_around(*view, heading.x, heading.y, rock) > 40);  // built again in it
    undo->undo();
    undo->undo();
    QCOMPARE(window.document()->model().stages.size(), std::size_t(4));
}

// Bolts: Edit ▸ Bolt adds a rock bolt between two clicked anchors (undoable); the
// picture draws it and the legend names it.
void EditingTest::boltToolDrawsABolt()
{
    MainWindow window;
    QVERIFY(guitest::show_square(window));
    QTRY_VERIFY(guitest::settled(window));
    gui::ModelDocument* doc = window.document();
    window.editingTools()->useBolt();
    QVERIFY(window.activeTool());
    QVERIFY(window.enterCoordinates(QStringLiteral("2, 5")));
    QVERIFY(window.enterCoordinates(QStringLiteral("8, 5")));
    QCOMPARE(doc->model().bolts.size(), std::size_t(1));
    const Bolt& bolt = doc->model().bolts.front();
    QCOMPARE(bolt.name, std::string("bolt 1"));
    QCOMPARE(bolt.from.x, 2.0);
    QCOMPARE(bolt.to.x, 8.0);
    QVERIFY(bolt.stiffness > 0.0 && bolt.strength > 0.0);
    QTRY_VERIFY2(guitest::settled(window), qPrintable(window.messages()));
    window.editingTools()->useSelect();
    QVERIFY(guitest::count_around(*window.modelView(), 5.0, 5.0, view::palette::bolt, 3) > 5);
    QVERIFY(!window.modelTree()->findItems(QStringLiteral("bolt 1"), Qt::MatchRecursive, 0).isEmpty());
    doc->undoStack()->undo();
    QVERIFY(doc->model().bolts.empty());
    QTRY_VERIFY(guitest::settled(window));
    QCOMPARE(guitest::count_around(*window.modelView(), 5.0, 5.0, view::palette::bolt, 3), 0);
}

// A joint set whose trace passes a hair's breadth from a corner (as with the old
// default origin on the model corner) cuts no sliver block: the cutter snaps it onto the corner.
// Where a sliver cannot be avoided — a region drawn with a vertex 1e-8 m from an edge — the
// Messages dock says so, naming the block, its region and the place.
void EditingTest::tinyBlocksAreReported()
{
    MainWindow window;
    QVERIFY(guitest::show_square(window));
    QTRY_VERIFY(guitest::settled(window));
    gui::ModelDocument* doc = window.document();
    JointSet set;
    set.name = "diagonal";
    set.angle = std::atan(1.0);  // 45°
    set.spacing = 2.0;
    set.origin = {1e-9, 0.0};  // a trace 0.7 nm from the corner (0, 0)
    doc->addJointSet(set);
    QTRY_VERIFY2(guitest::settled(window), qPrintable(window.messages()));
    const auto& blocks = window.modelView()->scene()->blocks;
    QVERIFY(blocks.size() >= 8);
    for (const Block& b : blocks) QVERIFY2(b.area > 1e-3, qPrintable(QString::number(b.area)));
    QVERIFY2(!window.messages().contains(QStringLiteral("cannot be meshed")), qPrintable(window.messages()));

    doc->addRegion({{20, 0}, {30, 0}, {30, 10}, {25, 1e-8}, {20, 10}}, 0);  // a spike down to 1e-8 m above the base
    QTRY_VERIFY(!window.isPreprocessing() && window.messages().contains(QStringLiteral("cannot be meshed")));
    const QString text = window.messages();
    QVERIFY2(text.contains(QStringLiteral("block")) && text.contains(QStringLiteral("near (25")), qPrintable(text));
}

// File ▸ Import DXF makes a new, untitled model of a drawing (a 10 m square in
// millimetres on layer "granite" and a joint across it), says what it did, and draws it.
void EditingTest::importDxfMakesAModel()
{
    MainWindow window;
    QVERIFY(guitest::show_square(window));
    QTRY_VERIFY(guitest::settled(window));
    QVERIFY(window.findChild<QAction*>(QStringLiteral("importDxfAction")));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("square.dxf"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QStringList groups{QStringLiteral("0"), QStringLiteral("SECTION"), QStringLiteral("2"), QStringLiteral("HEADER"),
                       QStringLiteral("9"), QStringLiteral("$INSUNITS"), QStringLiteral("70"), QStringLiteral("4"),
                       QStringLiteral("0"), QStringLiteral("ENDSEC"), QStringLiteral("0"), QStringLiteral("SECTION"),
                       QStringLiteral("2"), QStringLiteral("ENTITIES"), QStringLiteral("0"), QStringLiteral("LWPOLYLINE"),
                       QStringLiteral("8"), QStringLiteral("granite"), QStringLiteral("90"), QStringLiteral("4"),
                       QStringLiteral("70"), QStringLiteral("1")};
    for (const char* xy : {"0 0", "10000 0", "10000 10000", "0 10000"}) {
        const QStringList v = QString::fromLatin1(xy).split(QLatin1Char(' '));
        groups << QStringLiteral("10") << v[0] << QStringLiteral("20") << v[1];
    }
    groups << QStringLiteral("0") << QStringLiteral("LINE") << QStringLiteral("8") << QStringLiteral("joints")
           << QStringLiteral("10") << QStringLiteral("0") << QStringLiteral("20") << QStringLiteral("3000")
           << QStringLiteral("11") << QStringLiteral("10000") << QStringLiteral("21") << QStringLiteral("7000")
           << QStringLiteral("0") << QStringLiteral("ENDSEC") << QStringLiteral("0") << QStringLiteral("EOF");
    file.write(groups.join(QLatin1Char('\n')).toLatin1() + "\n");
    file.close();
    window.setAskToSave(false);
    QVERIFY(window.importDxf(path));
    const Model& m = window.document()->model();
    QCOMPARE(m.regions.size(), std::size_t(1));
    QCOMPARE(m.materials.front().name, std::string("granite"));
    QCOMPARE(m.regions.front().boundary[2].x, 10.0);  // millimetres read as such
    QCOMPARE(m.joints.size(), std::size_t(1));
    QVERIFY(window.document()->path().isEmpty());  // untitled: Save asks where
    QVERIFY2(window.messages().contains(QStringLiteral("Imported square.dxf")), qPrintable(window.messages()));
    QTRY_VERIFY2(!window.isPreprocessing() && window.messages().contains(QStringLiteral("nothing is fixed")),
                 qPrintable(window.messages()));
    const view::Rgb rock = view::material_color(0);
    QVERIFY(guitest::count_around(*window.modelView(), 2.0, 8.0, rock) > 40);  // above the joint
    QVERIFY(guitest::count_around(*window.modelView(), 8.0, 2.0, rock) > 40);  // below it
    QVERIFY(!window.importDxf(dir.filePath(QStringLiteral("missing.dxf"))));
    QCOMPARE(window.document()->model().materials.front().name, std::string("granite"));  // kept
}

QTEST_MAIN(EditingTest)
#include "EditingTest.moc"
