// Ground water in the desktop program on a (virtual) X server: the Water Table tool (clicks and
// typed points, a line that folds back refused in plain words, undo), a stage's water from the
// Stages dock, the blue line in the picture (pixels checked, and none when dry), selecting,
// dragging and deleting it, and the Results toolbar's total/effective choice on a short run.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "document/ModelDocument.hpp"
#include "session/RunController.hpp"
#include "session/RunSession.hpp"
#include "tools/DrawTool.hpp"
#include "tools/EditingTools.hpp"
#include "view/Palette.hpp"
#include "view/SceneGeometry.hpp"
#include "view/SceneLegend.hpp"
#include "widgets/ModelView.hpp"
#include "widgets/ResultToolBar.hpp"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGuiApplication>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace mcdda;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;
using namespace mcdda::guitest;

namespace {

Water line_at(std::vector<Point2> points)
{
    Water w;
    w.piezometric_line = std::move(points);
    return w;
}

QAction* water_action(MainWindow& window) { return window.findChild<QAction*>(QStringLiteral("waterTableAction")); }

/// Water-blue pixels in the 7×7 device pixels around each of `points` (model coordinates).
int blue_at(ModelView& view, std::initializer_list<Point2> points)
{
    int n = 0;
    for (const Point2& p : points) n += count_around(view, p.x, p.y, view::palette::water, 3);
    return n;
}

/// A picture value of the probe in pascals (the legend's unit undone).
double pascals(const view::ResultProbe& probe, double x, double y)
{
    double v = std::nan("");
    if (!probe.valueAt(x, y, &v)) return std::nan("");
    return v * (probe.units == "MPa" ? 1e6 : probe.units == "kPa" ? 1e3 : 1.0);
}

}  // namespace

class WaterTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void toolDrawsTheModelsWater();
    void stageWaterFromTheStagesDock();
    void viewDrawsTheWaterTable();
    void selectDragAndDeleteTheWaterTable();
    void totalOrEffectiveStress();
};

void WaterTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    gui::register_run_types();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

// Clicks draw the model's water; undo makes the ground dry again; a line that folds back is
// refused with a message in plain words and the tool stays for the next try.
void WaterTest::toolDrawsTheModelsWater()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    ModelView* view = window.modelView();
    QAction* tool = water_action(window);
    QVERIFY(tool);
    QVERIFY(!tool->icon().isNull());
    QVERIFY(tool->text().contains(QStringLiteral("Water Table")));
    auto* weight = window.findChild<QDoubleSpinBox*>(QStringLiteral("waterUnitWeightBox"));
    QVERIFY(weight);
    QCOMPARE(weight->value(), 9.81);
    QVERIFY(weight->suffix().contains(QStringLiteral("kN/m³")));

    tool->trigger();
    QVERIFY(window.activeTool() != nullptr);
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, -2.1, 6.1));
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 4.9, 7.05));
    QTest::mouseDClick(view, Qt::LeftButton, {}, pixel_of(*view, 12.1, 5.9));
    const std::vector<Point2> drawn{{-2, 6}, {5, 7}, {12, 6}};  // snapped to the 0.5 m grid
    QCOMPARE(doc->model().water.piezometric_line.size(), drawn.size());
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        QCOMPARE(doc->model().water.piezometric_line[i].x, drawn[i].x);
        QCOMPARE(doc->model().water.piezometric_line[i].y, drawn[i].y);
    }
    QCOMPARE(doc->model().water.unit_weight, 9810.0);
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("water table")));
    doc->undoStack()->undo();
    QVERIFY(!doc->model().water.present());
    QVERIFY(!has_water(doc->model()));
    doc->undoStack()->redo();
    QCOMPARE(doc->model().water.piezometric_line.size(), std::size_t(3));

    // Typed points that fold back: refused, nothing changes, the tool stays.
    const int edits = doc->undoStack()->count();
    for (const char* typed : {"0, 5", "6, 5", "4, 6"}) QVERIFY(window.enterCoordinates(QString::fromLatin1(typed)));
    QVERIFY(window.enterCoordinates(QString()));  // Enter on the empty field finishes
    QCOMPARE(doc->undoStack()->count(), edits);
    QCOMPARE(doc->model().water.piezometric_line.size(), std::size_t(3));
    QVERIFY2(window.messages().contains(
                 QStringLiteral("The water table must run from left to right: point 3 is left of point 2.")),
             qPrintable(window.messages()));
    QVERIFY(!window.messages().contains(QStringLiteral("/water")));  // no JSON pointers
    QVERIFY(window.activeTool() != nullptr && tool->isChecked());
    QVERIFY(view->preview().empty());

    // Drawn again, left to right, with water of another unit weight: replaces the line.
    weight->setValue(10.0);
    for (const char* typed : {"0; 4", "10 4"}) QVERIFY(window.enterCoordinates(QString::fromLatin1(typed)));
    QVERIFY(window.enterCoordinates(QString()));
    QCOMPARE(doc->model().water.piezometric_line.size(), std::size_t(2));
    QCOMPARE(doc->model().water.piezometric_line[1].x, 10.0);
    QCOMPARE(doc->model().water.piezometric_line[1].y, 4.0);
    QCOMPARE(doc->model().water.unit_weight, 10000.0);
    QTRY_VERIFY(settled(window));  // the checker has nothing against it
    QVERIFY2(!window.messages().contains(QStringLiteral("error")), qPrintable(window.messages()));

    // The Material form shows the saturated unit weight in kN/m³; 0 reads "the unit weight".
    auto* saturated = window.findChild<QDoubleSpinBox*>(QStringLiteral("material_saturated_density"));
    QVERIFY(saturated);
    QVERIFY(saturated->suffix().contains(QStringLiteral("kN/m³")));
    QCOMPARE(saturated->value(), 0.0);
    QCOMPARE(saturated->text(), QStringLiteral("the unit weight"));
}

// With a stage chosen in the Stages dock, the tool draws that stage's water; the dock's buttons
// make it dry or as the stage before; the other stages and the model keep theirs.
void WaterTest::stageWaterFromTheStagesDock()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    auto* add = window.findChild<QPushButton*>(QStringLiteral("addStage"));
    auto* list = window.findChild<QListWidget*>(QStringLiteral("stageList"));
    auto* words = window.findChild<QLabel*>(QStringLiteral("stageWater"));
    auto* draw = window.findChild<QPushButton*>(QStringLiteral("stageWaterDraw"));
    auto* dry = window.findChild<QPushButton*>(QStringLiteral("stageWaterDry"));
    auto* inherit = window.findChild<QPushButton*>(QStringLiteral("stageWaterInherit"));
    QVERIFY(add && list && words && draw && dry && inherit);
    doc->setWater(-1, line_at({{0, 8}, {10, 8}}));  // the model's water, kept below
    add->click();
    add->click();
    QCOMPARE(doc->model().stages.size(), std::size_t(2));
    list->setCurrentRow(2);  // the second stage
    QCOMPARE(words->text(), QStringLiteral("as the stage before (line with 2 points)"));
    QVERIFY(!inherit->isEnabled());

    draw->click();
    QVERIFY(water_action(window)->isChecked());
    for (const char* typed : {"-1, 3", "5, 2", "11, 3"}) QVERIFY(window.enterCoordinates(QString::fromLatin1(typed)));
    QVERIFY(window.enterCoordinates(QString()));
    const Model& m = doc->model();
    QVERIFY(m.stages[1].water.has_value());
    QCOMPARE(m.stages[1].water->piezometric_line.size(), std::size_t(3));
    QCOMPARE(m.stages[1].water->piezometric_line[1].y, 2.0);
    QVERIFY(!m.stages[0].water.has_value());  // the first stage keeps the model's
    QCOMPARE(m.water.piezometric_line.size(), std::size_t(2));
    QCOMPARE(m.water.piezometric_line[0].y, 8.0);
    QCOMPARE(water_of_stage(m, 0).piezometric_line[0].y, 8.0);
    QCOMPARE(water_of_stage(m, 1).piezometric_line[0].y, 3.0);
    QCOMPARE(words->text(), QStringLiteral("line with 3 points"));
    QVERIFY(inherit->isEnabled());

    dry->click();
    QVERIFY(m.stages[1].water.has_value() && !m.stages[1].water->present());
    QCOMPARE(words->text(), QStringLiteral("dry"));
    QVERIFY(!dry->isEnabled());
    inherit->click();
    QVERIFY(!m.stages[1].water.has_value());
    QCOMPARE(words->text(), QStringLiteral("as the stage before (line with 2 points)"));
    QCOMPARE(m.water.piezometric_line[0].y, 8.0);

    doc->undoStack()->undo();  // back to dry
    QVERIFY(m.stages[1].water.has_value() && !m.stages[1].water->present());
    doc->undoStack()->undo();  // back to the drawn line
    QCOMPARE(m.stages[1].water->piezometric_line.size(), std::size_t(3));
    doc->undoStack()->undo();  // as the stage before
    QVERIFY(!m.stages[1].water.has_value());
    QVERIFY(!m.stages[0].water.has_value());

    // The model as drawn: the buttons act on the model's water.
    list->setCurrentRow(0);
    QCOMPARE(words->text(), QStringLiteral("line with 2 points"));
    QVERIFY(!inherit->isEnabled());
    dry->click();
    QVERIFY(!doc->model().water.present());
    QCOMPARE(words->text(), QStringLiteral("dry"));
}

// The picture draws the water in force in the stage shown as a blue line held level to the
// model's sides, with the ▽ symbol above the middle; nothing blue when dry.
void WaterTest::viewDrawsTheWaterTable()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    ModelView* view = window.modelView();
    view::SceneOptions plain = view->sceneOptions();
    plain.show_mesh = false;  // no mesh lines near the pixels looked at
    view->setSceneOptions(plain);
    view->showBox(-1.0, -1.0, 11.0, 11.0);  // the symbol a dozen pixels tall

    const std::initializer_list<Point2> at_six{{0.8, 6.0}, {3.0, 6.0}, {7.0, 6.0}, {9.2, 6.0}};
    QCOMPARE(blue_at(*view, at_six), 0);
    // Drawn from x = 2 to 8 only: held level beyond its ends.
    doc->setWater(-1, line_at({{2, 6}, {8, 6}}));
    QTRY_VERIFY(settled(window) && view->scene()->model.water.present());
    for (const Point2& p : at_six)
        QVERIFY2(count_around(*view, p.x, p.y, view::palette::water, 3) >= 3,
                 qPrintable(QStringLiteral("no water blue at (%1, %2)").arg(p.x).arg(p.y)));
    QCOMPARE(blue_at(*view, {{3.0, 3.0}, {7.0, 8.5}, {5.0, 2.0}}), 0);  // only along the line
    // The symbol over the middle of the model: the ▽'s top edge above the line and its dashes
    // under it, and not elsewhere along the line.
    const double size = 1.5 * view::symbol_size(view::model_box(*view->scene()));
    QVERIFY2(size / view->metresPerPixel() > 8.0, qPrintable(QString::number(size / view->metresPerPixel())));
    QVERIFY(count_around(*view, 5.0, 6.0 + 0.8 * size, view::palette::water, 2) >= 2);
    QVERIFY(count_around(*view, 5.0, 6.0 - 0.6 * size, view::palette::water, 2) >= 2);
    QCOMPARE(count_around(*view, 2.5, 6.0 + 0.8 * size, view::palette::water, 2), 0);
    QCOMPARE(count_around(*view, 2.5, 6.0 - 0.6 * size, view::palette::water, 2), 0);
    view->grabFrame().save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/water_model.png"));
    // The legend names it.
    const auto entries = view::legend_entries(*view->scene(), view->sceneOptions());
    QVERIFY(std::any_of(entries.begin(), entries.end(),
                        [](const view::LegendEntry& e) { return e.icon == view::LegendEntry::Icon::WaterTable; }));

    // A stage lowering the water to y = 3: drawn when the stage is shown, the model's otherwise.
    window.findChild<QPushButton*>(QStringLiteral("addStage"))->click();
    doc->setWater(0, line_at({{0, 3}, {10, 3}}));
    auto* list = window.findChild<QListWidget*>(QStringLiteral("stageList"));
    list->setCurrentRow(1);
    QTRY_VERIFY(settled(window));
    QVERIFY(blue_at(*view, {{3.0, 3.0}, {7.0, 3.0}}) >= 6);
    QCOMPARE(blue_at(*view, {{3.0, 6.0}, {7.0, 6.0}}), 0);
    list->setCurrentRow(0);
    QVERIFY(blue_at(*view, {{3.0, 6.0}, {7.0, 6.0}}) >= 6);
    QCOMPARE(blue_at(*view, {{3.0, 3.0}, {7.0, 3.0}}), 0);

    // Dry again: no blue anywhere on the line.
    doc->setWater(-1, std::nullopt);
    QTRY_VERIFY(settled(window) && !view->scene()->model.water.present());
    QCOMPARE(blue_at(*view, at_six), 0);
    QCOMPARE(count_around(*view, 5.0, 6.0 + 0.8 * size, view::palette::water, 2), 0);
}

// The Select tool picks the line (and its vertices): a drag moves a vertex, one past its
// neighbour is refused, Delete makes the ground dry.
void WaterTest::selectDragAndDeleteTheWaterTable()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    ModelView* view = window.modelView();
    doc->setWater(-1, line_at({{0, 6}, {5, 6}, {10, 6}}));
    QTRY_VERIFY(settled(window));
    window.editingTools()->useSelect();

    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 2.5, 6.0));
    const gui::ItemRef whole = window.selection();
    QCOMPARE(whole.kind, gui::ItemRef::Kind::WaterTable);
    QCOMPARE(whole.index, 0);
    QCOMPARE(whole.vertex, -1);
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, -3.0, -3.0));  // off: nothing selected

    // The middle vertex dragged up 1 m (snapped to the grid).
    QTest::mousePress(view, Qt::LeftButton, {}, pixel_of(*view, 5.0, 6.0));
    QCOMPARE(window.selection().vertex, 1);
    QTest::mouseMove(view, pixel_of(*view, 5.0, 6.5));
    QTest::mouseMove(view, pixel_of(*view, 5.04, 7.03));
    QTest::mouseRelease(view, Qt::LeftButton, {}, pixel_of(*view, 5.04, 7.03));
    QCOMPARE(doc->model().water.piezometric_line[1].x, 5.0);
    QCOMPARE(doc->model().water.piezometric_line[1].y, 7.0);

    // Past its right neighbour: refused, said in words.
    const int edits = doc->undoStack()->count();
    QTest::mousePress(view, Qt::LeftButton, {}, pixel_of(*view, 5.0, 7.0));
    QTest::mouseMove(view, pixel_of(*view, 8.0, 7.0));
    QTest::mouseMove(view, pixel_of(*view, 11.0, 7.0));
    QTest::mouseRelease(view, Qt::LeftButton, {}, pixel_of(*view, 11.0, 7.0));
    QCOMPARE(doc->undoStack()->count(), edits);
    QCOMPARE(doc->model().water.piezometric_line[1].x, 5.0);
    QVERIFY2(window.messages().contains(QStringLiteral("must run from left to right")), qPrintable(window.messages()));

    // Edit ▸ Delete on the whole line: dry; undo brings it back.
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 2.5, 6.5));
    QCOMPARE(window.selection().kind, gui::ItemRef::Kind::WaterTable);
    QCOMPARE(window.selection().vertex, -1);
    QAction* remove = window.findChild<QAction*>(QStringLiteral("deleteAction"));
    QVERIFY(remove && remove->isEnabled());
    remove->trigger();
    QVERIFY(!doc->model().water.present());
    QVERIFY(!window.selection().valid());
    doc->undoStack()->undo();
    QCOMPARE(doc->model().water.piezometric_line.size(), std::size_t(3));
}

// A short run with water: its results offer the pore pressure and the effective stresses, and
// the toolbar's choice maps σxx, σyy, σ1, σ3 to them (τxy stays); a dry model offers neither.
void WaterTest::totalOrEffectiveStress()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTemporaryDir out;
    QVERIFY(out.isValid());
    window.setRunOutputFolder(out.path());
    gui::ModelDocument* doc = window.document();
    AnalysisSettings short_run = doc->model().analysis;
    short_run.steps = 2;
    doc->setAnalysisSettings(short_run);
    auto* bar = window.findChild<gui::ResultToolBar*>();
    auto* fields = window.findChild<QComboBox*>(QStringLiteral("fieldBox"));
    auto* basis = window.findChild<QComboBox*>(QStringLiteral("stressBasisBox"));
    QVERIFY(bar && fields && basis);
    QTRY_VERIFY(settled(window));
    QCOMPARE(fields->findData(QStringLiteral("pore_pressure")), -1);  // dry: not offered
    QVERIFY(!basis->isEnabled());

    doc->setWater(-1, line_at({{0, 6}, {10, 6}}));
    QTRY_VERIFY(settled(window) && has_water(window.modelView()->scene()->model));
    QVERIFY(fields->findData(QStringLiteral("pore_pressure")) >= 0);
    QVERIFY(basis->isEnabled());
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY2(!window.shownStep().isEmpty(), qPrintable(window.messages()));

    ModelView* view = window.modelView();
    bar->setEffectiveStress(false);
    for (const char* field : {"stress_xx", "stress_yy", "stress_xy", "stress_1", "stress_3"}) {
        window.setResultField(QString::fromLatin1(field));
        QCOMPARE(window.resultField(), QString::fromLatin1(field));
    }
    bar->setEffectiveStress(true);
    for (const char* field : {"stress_xx", "stress_yy", "stress_1", "stress_3"}) {
        window.setResultField(QString::fromLatin1(field));
        QCOMPARE(window.resultField(), QStringLiteral("effective_") + QString::fromLatin1(field));
        QCOMPARE(QString::fromStdString(bar->options().field), QStringLiteral("effective_") + QString::fromLatin1(field));
        QVERIFY2(QString::fromStdString(view->resultInfo().title).startsWith(QStringLiteral("effective")),
                 view->resultInfo().title.c_str());
    }
    window.setResultField(QStringLiteral("stress_xy"));  // shear: the same total and effective
    QCOMPARE(window.resultField(), QStringLiteral("stress_xy"));
    window.setResultField(QStringLiteral("effective_stress_3"));  // an effective name picks σ3 and Effective
    QCOMPARE(fields->currentData().toString(), QStringLiteral("stress_3"));
    QCOMPARE(window.resultField(), QStringLiteral("effective_stress_3"));

    // What is drawn: compression positive, the total vertical stress exceeds the effective one by
    // the pore pressure below the water (at y = 2, 4 m under it: about 39 kPa).
    const double x = 5.0, y = 2.0;
    window.setResultField(QStringLiteral("stress_yy"));
    const double effective = pascals(view->resultProbe(), x, y);
    bar->setEffectiveStress(false);
    QCOMPARE(window.resultField(), QStringLiteral("stress_yy"));
    const double total = pascals(view->resultProbe(), x, y);
    window.setResultField(QStringLiteral("pore_pressure"));
    QVERIFY(QString::fromStdString(view->resultInfo().title).startsWith(QStringLiteral("pore pressure")));
    const double u = pascals(view->resultProbe(), x, y);
    QVERIFY2(std::isfinite(effective) && std::isfinite(total) && std::isfinite(u), "no values at (5, 2)");
    QVERIFY2(u > 2.5e4 && u < 5e4, qPrintable(QString::number(u)));
    QVERIFY2(std::fabs(total - effective - u) < 0.02 * u,
             qPrintable(QStringLiteral("total %1, effective %2, u %3").arg(total).arg(effective).arg(u)));
    view->grabFrame().save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/water_pore_pressure.png"));
    // The live picture (the run's last snapshot) carries the same fields.
    QVERIFY(window.runSession()->lastSnapshot());
    view::ResultOptions live = bar->options();
    live.field = "effective_stress_1";
    QVERIFY(view->setResult(window.runSession()->lastSnapshot(), live));
    QVERIFY(view->result() != nullptr);
    QVERIFY(QString::fromStdString(view->resultInfo().title).startsWith(QStringLiteral("effective principal stress 1")));

    // Dry again: the pore pressure is no longer offered, the choice falls back to total.
    bar->setEffectiveStress(true);
    doc->setWater(-1, std::nullopt);
    QTRY_VERIFY(settled(window) && !has_water(window.modelView()->scene()->model));
    QCOMPARE(fields->findData(QStringLiteral("pore_pressure")), -1);
    QCOMPARE(fields->currentData().toString(), QStringLiteral("displacement"));
    QVERIFY(!basis->isEnabled());
    QVERIFY(!bar->effectiveStress());
}

QTEST_MAIN(WaterTest)
#include "WaterTest.moc"
