// Earthquakes in the desktop program on a (virtual) X server: a record imported from a CSV file
// and plotted before any run (its pixels, peak and duration), a bad file refused in the reader's
// words, the Absorbing Boundary tool (the dashpots' pixels, the legend row, picking, deleting,
// undo), the base motion and the seismic coefficient from the Earthquake dock, the model saved
// and read back with the record's file relative to it, and the history plot offering a point's
// velocities and accelerations and the base's input.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "document/ModelDocument.hpp"
#include "document/ModelItems.hpp"
#include "io/ModelReader.hpp"
#include "panels/EarthquakePanel.hpp"
#include "results/HistoryPlot.hpp"
#include "results/RecordPlot.hpp"
#include "session/RunController.hpp"
#include "tools/EditingTools.hpp"
#include "view/Palette.hpp"
#include "view/SceneLegend.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QPushButton>
#include <QLineSeries>
#include <QListWidget>
#include <QScatterSeries>
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

/// Two seconds of a 1 Hz sine of 0.3 g sampled every 0.01 s, with a header line.
QByteArray sine_csv()
{
    QByteArray text = "time,acceleration\n";
    for (int k = 0; k <= 200; ++k) {
        const double t = 0.01 * k;
        text += QByteArray::number(t, 'f', 2) + ',' + QByteArray::number(0.3 * std::sin(2.0 * M_PI * t), 'f', 9) + '\n';
    }
    return text;
}

bool write(const QString& path, const QByteArray& text)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

/// Pixels of `colour` (within 40 of each channel) in `image`.
int pixels_like(const QImage& image, QColor colour)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) < 40 && std::abs(c.green() - colour.green()) < 40 &&
                std::abs(c.blue() - colour.blue()) < 40)
                ++n;
        }
    return n;
}

gui::EarthquakePanel* show_panel(MainWindow& window)
{
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("earthquake"));
    if (!dock) return nullptr;
    dock->show();
    dock->raise();
    return window.earthquakePanel();
}

}  // namespace

class EarthquakeTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void importedRecordIsPlotted();
    void at2RecordInG();
    void badRecordIsRefusedInWords();
    void absorbingBoundaryTool();
    void baseAndSeismicCoefficientSavedAndReadBack();
    void stageSeismicCoefficient();
    void historyOffersVelocitiesAndAccelerations();
    void slidingBlockRunInTheWindow();

private:
    QTemporaryDir dir_;
};

void EarthquakeTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    gui::register_run_types();
    QVERIFY(dir_.isValid());
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

// A CSV record imported into an unsaved model: its points loaded, its file as given, plotted in g
// with its peak (0.3 g at 0.25 s, baseline correction off) and duration; every change undoable.
void EarthquakeTest::importedRecordIsPlotted()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    gui::EarthquakePanel* panel = show_panel(window);
    QVERIFY(panel);
    const QString path = dir_.filePath(QStringLiteral("sine.csv"));
    QVERIFY(write(path, sine_csv()));

    QVERIFY(panel->importRecord(path));
    QCOMPARE(doc->model().ground_motions.size(), std::size_t(1));
    const GroundMotion& g = doc->model().ground_motions[0];
    QCOMPARE(QString::fromStdString(g.name), QStringLiteral("sine"));
    QCOMPARE(QString::fromStdString(g.file), path);  // no model file yet: as given
    QCOMPARE(g.points.size(), std::size_t(201));
    QVERIFY(g.units == GroundMotion::Units::G);
    QVERIFY(panel->recordStatus().contains(QStringLiteral("201")));
    QCOMPARE(panel->currentRecord(), 0);
    gui::RecordPlot* plot = panel->recordPlot();
    QCOMPARE(plot->series()->count(), 201);
    QCOMPARE(plot->duration(), 2.0);
    // Corrected, the trend a0 + a1·t that would leave the base moving is taken off: another peak.
    QVERIFY2(plot->peak() > 0.3 && plot->peak() < 0.6, qPrintable(QString::number(plot->peak())));

    // Without the correction the peak is the file's: 0.3 g at 0.25 s.
    auto* baseline = panel->findChild<QCheckBox*>(QStringLiteral("recordBaseline"));
    QVERIFY(baseline && baseline->isChecked());
    baseline->setChecked(false);
    QVERIFY(!doc->model().ground_motions[0].baseline_correction);
    QVERIFY(std::fabs(plot->peak() - 0.3) < 1e-9);
    QCOMPARE(plot->peakTime(), 0.25);
    QCOMPARE(plot->peakMarker()->count(), 1);
    QVERIFY2(plot->summary().contains(QStringLiteral("0.3 g")) && plot->summary().contains(QStringLiteral("0.25 s")) &&
                 plot->summary().contains(QStringLiteral("2.00 s")),
             qPrintable(plot->summary()));

    // Drawn: the blue curve and the red peak marker.
    QTest::qWait(100);
    const QImage image = plot->grab().toImage();
    image.save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/earthquake_record.png"));
    QVERIFY2(pixels_like(image, QColor(20, 90, 200)) > 100, "the record's curve is not drawn");
    QVERIFY2(pixels_like(image, QColor(220, 30, 30)) > 20, "the peak is not marked");

    // Scaled to 0.5: the plot follows; undo goes back step by step.
    auto* scale = panel->findChild<QDoubleSpinBox*>(QStringLiteral("recordScale"));
    QVERIFY(scale);
    scale->setValue(0.5);
    emit scale->editingFinished();  // leaving the field: not applied behind the user's back
    QCOMPARE(doc->model().ground_motions[0].scale, 1.0);
    QTest::keyClick(scale, Qt::Key_Return);
    QCOMPARE(doc->model().ground_motions[0].scale, 0.5);
    QVERIFY(std::fabs(plot->peak() - 0.15) < 1e-9);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().ground_motions[0].scale, 1.0);
    doc->undoStack()->undo();
    QVERIFY(doc->model().ground_motions[0].baseline_correction);
    doc->undoStack()->undo();
    QVERIFY(doc->model().ground_motions.empty());
    QCOMPARE(plot->series()->count(), 0);
    doc->undoStack()->redo();
    QCOMPARE(doc->model().ground_motions.size(), std::size_t(1));
    QCOMPARE(plot->series()->count(), 201);
}

// A PEER .AT2 file (the shipped synthetic record) is read in g: its peak is 0.3 g.
void EarthquakeTest::at2RecordInG()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::EarthquakePanel* panel = show_panel(window);
    QVERIFY(panel->importRecord(QStringLiteral(MCDDA_EXAMPLES_DIR "/records/synthetic-0.3g.AT2")));
    const GroundMotion& g = window.document()->model().ground_motions.at(0);
    QVERIFY(g.units == GroundMotion::Units::G);
    QCOMPARE(g.points.size(), std::size_t(1400));
    auto* baseline = panel->findChild<QCheckBox*>(QStringLiteral("recordBaseline"));
    baseline->setChecked(false);  // the file's own peak
    QVERIFY2(std::fabs(panel->recordPlot()->peak() - 0.3) < 0.005, qPrintable(panel->recordPlot()->summary()));
    QVERIFY(std::fabs(panel->recordPlot()->duration() - 13.99) < 0.011);
}

// A file the reader refuses (a word among the numbers, or no file at all) changes nothing and is
// reported with the reader's message, naming the file and line.
void EarthquakeTest::badRecordIsRefusedInWords()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    gui::EarthquakePanel* panel = show_panel(window);
    const QString bad = dir_.filePath(QStringLiteral("bad.csv"));
    QVERIFY(write(bad, "time,acceleration\n0,0\n0.01,0.1\n0.02,strong\n"));
    const int edits = doc->undoStack()->count();
    QVERIFY(!panel->importRecord(bad));
    QCOMPARE(doc->undoStack()->count(), edits);
    QVERIFY(doc->model().ground_motions.empty());
    QVERIFY2(panel->recordStatus().contains(QStringLiteral("not imported")) &&
                 panel->recordStatus().contains(QStringLiteral("bad.csv")),
             qPrintable(panel->recordStatus()));
    QVERIFY2(window.messages().contains(QStringLiteral("bad.csv")), qPrintable(window.messages()));

    QVERIFY(!panel->importRecord(dir_.filePath(QStringLiteral("missing.at2"))));
    QVERIFY2(panel->recordStatus().contains(QStringLiteral("missing.at2")), qPrintable(panel->recordStatus()));
    QVERIFY(doc->model().ground_motions.empty());
}

// Two typed points draw an absorbing boundary along the square's right side: dashpots in their
// colour in the picture, a legend row; it is picked, deleted and brought back by undo.
void EarthquakeTest::absorbingBoundaryTool()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    ModelView* view = window.modelView();
    auto* tool = window.findChild<QAction*>(QStringLiteral("absorbingBoundaryAction"));
    QVERIFY(tool);
    QVERIFY(!tool->icon().isNull());
    const int before = count_around(*view, 10.0, 5.0, view::palette::absorbing, 40);
    QCOMPARE(before, 0);

    tool->trigger();
    QVERIFY(window.activeTool() != nullptr);
    QVERIFY(window.enterCoordinates(QStringLiteral("10, 0")));
    QVERIFY(window.enterCoordinates(QStringLiteral("10, 10")));
    QCOMPARE(doc->model().absorbing_boundaries.size(), std::size_t(1));
    const AbsorbingBoundary& a = doc->model().absorbing_boundaries[0];
    QCOMPARE(a.from.x, 10.0);
    QCOMPARE(a.to.y, 10.0);
    QCOMPARE(QString::fromStdString(a.name), QStringLiteral("absorbing boundary 1"));
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("absorbing boundary")));
    QTRY_VERIFY(settled(window));

    // The dashpots stand outside the rock (x > 10), in their own colour.
    view->grabFrame().save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/earthquake_absorbing.png"));
    int outside = 0;
    for (double y : {2.0, 4.0, 5.0, 6.0, 8.0}) outside += count_around(*view, 10.3, y, view::palette::absorbing, 12);
    QVERIFY2(outside > 20, qPrintable(QString::number(outside)));
    bool legend = false;
    for (const view::LegendEntry& e : view::legend_entries(*view->scene(), view->sceneOptions()))
        legend = legend || (e.icon == view::LegendEntry::Icon::Dashpot && e.label == "Absorbing boundary");
    QVERIFY(legend);

    // Picked on its line (before the region's edge under it), deleted, undone.
    const gui::ItemRef picked = gui::pick_item(doc->model(), {10.0, 5.0}, 0.2);
    QVERIFY(picked.kind == gui::ItemRef::Kind::AbsorbingBoundary && picked.index == 0 && picked.vertex < 0);
    window.selectItem(picked);
    QVERIFY(window.editingTools()->deleteAction()->isEnabled());
    window.editingTools()->deleteAction()->trigger();
    QVERIFY(doc->model().absorbing_boundaries.empty());
    QTRY_VERIFY(settled(window));
    outside = 0;
    for (double y : {2.0, 4.0, 5.0, 6.0, 8.0}) outside += count_around(*view, 10.3, y, view::palette::absorbing, 12);
    QCOMPARE(outside, 0);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().absorbing_boundaries.size(), std::size_t(1));
    doc->undoStack()->undo();
    QVERIFY(doc->model().absorbing_boundaries.empty());
    doc->undoStack()->redo();
    QCOMPARE(doc->model().absorbing_boundaries.size(), std::size_t(1));
}

// The base (rigid, then compliant drawn with two typed points) and kh from the dock; saved, the
// record's file is relative to the model and everything reads back.
void EarthquakeTest::baseAndSeismicCoefficientSavedAndReadBack()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    gui::EarthquakePanel* panel = show_panel(window);
    QTemporaryDir folder;
    const QString model_path = folder.filePath(QStringLiteral("quake.json"));
    QVERIFY(window.saveModelAs(model_path));
    const QString record = folder.filePath(QStringLiteral("records/sine.csv"));
    QVERIFY(write(record, sine_csv()));
    QVERIFY(panel->importRecord(record));
    QCOMPARE(QString::fromStdString(doc->model().ground_motions[0].file), QStringLiteral("records/sine.csv"));

    auto* kind = panel->findChild<QComboBox*>(QStringLiteral("baseKind"));
    QVERIFY(kind);
    kind->setCurrentIndex(1);  // rigid: takes the first record for x
    QVERIFY(doc->model().base_motion.kind == BaseMotion::Kind::Rigid);
    QCOMPARE(doc->model().base_motion.x, 0);
    QCOMPARE(doc->model().base_motion.y, -1);
    auto* y = panel->findChild<QComboBox*>(QStringLiteral("baseY"));
    y->setCurrentIndex(1);
    QCOMPARE(doc->model().base_motion.y, 0);

    auto* kh = panel->findChild<QDoubleSpinBox*>(QStringLiteral("seismicKh"));
    QVERIFY(kh);
    kh->setValue(0.15);
    emit kh->editingFinished();
    QCOMPARE(doc->model().seismic_coefficient.kh, 0.0);  // waits for Apply or Enter
    auto* apply = panel->findChild<QPushButton*>(QStringLiteral("earthquakeApply"));
    QVERIFY(apply);
    apply->click();
    QCOMPARE(doc->model().seismic_coefficient.kh, 0.15);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().seismic_coefficient.kh, 0.0);
    doc->undoStack()->redo();

    // The compliant base drawn from the dock's Draw button.
    auto* draw = panel->findChild<QPushButton*>(QStringLiteral("baseDraw"));
    QVERIFY(draw && draw->isEnabled());
    draw->click();
    QVERIFY(window.activeTool() != nullptr);
    QVERIFY(window.enterCoordinates(QStringLiteral("0, 0")));
    QVERIFY(window.enterCoordinates(QStringLiteral("10, 0")));
    QVERIFY(doc->model().base_motion.kind == BaseMotion::Kind::Compliant);
    QCOMPARE(doc->model().base_motion.to.x, 10.0);
    QCOMPARE(doc->model().base_motion.x, 0);
    QCOMPARE(kind->currentIndex(), 2);
    QTRY_VERIFY(settled(window));
    bool legend = false;
    for (const view::LegendEntry& e : view::legend_entries(*window.modelView()->scene(), window.modelView()->sceneOptions()))
        legend = legend || e.icon == view::LegendEntry::Icon::CompliantBase;
    QVERIFY(legend);
    window.modelView()->grabFrame().save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/earthquake_compliant_base.png"));
    // Picked on its line (over the roller there), deleted with its base motion, undone.
    const gui::ItemRef base = gui::pick_item(doc->model(), {5.0, 0.0}, 0.2);
    QVERIFY(base.kind == gui::ItemRef::Kind::CompliantBase);
    QCOMPARE(doc->itemName(base), QStringLiteral("the compliant base"));
    QVERIFY(doc->deleteItem(base));
    QVERIFY(!doc->model().base_motion.present());
    QCOMPARE(kind->currentIndex(), 0);
    doc->undoStack()->undo();
    QVERIFY(doc->model().base_motion.kind == BaseMotion::Kind::Compliant);
    doc->undoStack()->undo();
    QVERIFY(doc->model().base_motion.kind == BaseMotion::Kind::Rigid);
    doc->undoStack()->redo();

    QVERIFY(window.save());
    const ReadResult back = read_model_file(QFile::encodeName(model_path).toStdString());
    QVERIFY(back.model);
    const Model& m = *back.model;
    QCOMPARE(m.ground_motions.size(), std::size_t(1));
    QCOMPARE(m.ground_motions[0].file, std::string("records/sine.csv"));
    QCOMPARE(m.ground_motions[0].points.size(), std::size_t(201));
    QVERIFY(m.base_motion.kind == BaseMotion::Kind::Compliant);
    QCOMPARE(m.base_motion.x, 0);
    QCOMPARE(m.base_motion.y, 0);
    QCOMPARE(m.base_motion.from.x, 0.0);
    QCOMPARE(m.base_motion.to.x, 10.0);
    QCOMPARE(m.seismic_coefficient.kh, 0.15);

    // Removing the record takes it off the base, which then has none and goes.
    auto* remove = panel->findChild<QPushButton*>(QStringLiteral("removeRecordButton"));
    remove->click();
    QVERIFY(doc->model().ground_motions.empty());
    QVERIFY(!doc->model().base_motion.present());
    doc->undoStack()->undo();
    QVERIFY(doc->model().base_motion.kind == BaseMotion::Kind::Compliant);
}

// The Stages dock sets a stage's own kh (from it on) and gives it back to the stage before's.
void EarthquakeTest::stageSeismicCoefficient()
{
    MainWindow window;
    QVERIFY(show_square(window));
    QTRY_VERIFY(settled(window));
    gui::ModelDocument* doc = window.document();
    Model m = doc->model();
    Stage first, second;
    first.name = "gravity";
    second.name = "earthquake";
    first.analysis = second.analysis = m.analysis;
    m.stages = {first, second};
    doc->replaceModel(m, QStringLiteral("Add stages"));
    auto* stages = window.findChild<QListWidget*>(QStringLiteral("stageList"));
    auto* own = window.findChild<QCheckBox*>(QStringLiteral("stageSeismicOwn"));
    auto* kh = window.findChild<QDoubleSpinBox*>(QStringLiteral("stageSeismicKh"));
    QVERIFY(own && kh);
    QVERIFY(stages);
    stages->setCurrentRow(2);  // the second stage
    QVERIFY(own->isEnabled() && !own->isChecked() && !kh->isEnabled());
    own->setChecked(true);
    QVERIFY(doc->model().stages[1].seismic_coefficient.has_value());
    kh->setValue(0.1);
    QTest::keyClick(kh, Qt::Key_Return);  // typed values are applied on Enter (or Apply)
    QCOMPARE(doc->model().stages[1].seismic_coefficient->kh, 0.1);
    QCOMPARE(seismic_of_stage(doc->model(), 1).kh, 0.1);
    QCOMPARE(seismic_of_stage(doc->model(), 0).kh, 0.0);
    own->setChecked(false);
    QVERIFY(!doc->model().stages[1].seismic_coefficient.has_value());
    doc->undoStack()->undo();
    QCOMPARE(doc->model().stages[1].seismic_coefficient->kh, 0.1);
}

// A dynamic run's history: a point's velocities and accelerations and the base's input are
// offered and plotted against time.
void EarthquakeTest::historyOffersVelocitiesAndAccelerations()
{
    const QString path = dir_.filePath(QStringLiteral("history.csv"));
    QByteArray text = "step,time,crest:ux,crest:uy,crest:vx,crest:vy,crest:ax,crest:ay,base:ax,base:ay,base:vx,base:vy,base:ux,base:uy\n";
    for (int k = 0; k < 5; ++k)
        text += QByteArray::number(k) + ',' + QByteArray::number(0.1 * k) + ",0,0,0.1,0,1,0,2,0,0.2,0,0.01,0\n";
    QVERIFY(write(path, text));
    gui::HistoryPlot plot;
    QCOMPARE(plot.load(path), 5);
    auto* column = plot.findChild<QComboBox*>(QStringLiteral("historyColumn"));
    QVERIFY(column);
    QVERIFY(column->findData(QStringLiteral("crest:vx")) >= 0);
    QVERIFY(column->findData(QStringLiteral("crest:ay")) >= 0);
    const int base = column->findData(QStringLiteral("base:ax"));
    QVERIFY(base >= 0);
    QCOMPARE(column->itemText(base), QStringLiteral("base input ax (m/s²)"));
    QCOMPARE(column->itemText(column->findData(QStringLiteral("crest:vx"))), QStringLiteral("crest:vx (m/s)"));
    plot.setColumns(QStringLiteral("crest:ax"), QStringLiteral("time"));
    QCOMPARE(plot.series()->count(), 5);
    QCOMPARE(plot.series()->at(4).y(), 1.0);
    plot.setColumns(QStringLiteral("base:ax"), QStringLiteral("time"));
    QCOMPARE(plot.series()->at(2).y(), 2.0);
}

// The shipped sliding block, opened with its record beside it: the dock lists and plots the
// record (0.3 g); the Analysis tab shows Newmark's γ and the damping for this dynamic model
// only; the run logs the permanent displacement, and the Plots dock offers the block's
// velocity and acceleration and the base's input.
void EarthquakeTest::slidingBlockRunInTheWindow()
{
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString model = folder.filePath(QStringLiteral("newmark-sliding-block.json"));
    QVERIFY(QFile::copy(QStringLiteral(MCDDA_EXAMPLES_DIR "/newmark-sliding-block.json"), model));
    QVERIFY(QDir(folder.path()).mkpath(QStringLiteral("records")));
    QVERIFY(QFile::copy(QStringLiteral(MCDDA_EXAMPLES_DIR "/records/sine-2hz-3-cycles.csv"),
                        folder.filePath(QStringLiteral("records/sine-2hz-3-cycles.csv"))));
    MainWindow window;
    window.setAskToSave(false);
    QVERIFY(show_model(window, model));
    QTRY_VERIFY(settled(window));
    gui::EarthquakePanel* panel = show_panel(window);
    panel->parentWidget()->resize(380, 900);
    QCOMPARE(panel->currentRecord(), 0);
    QVERIFY(std::fabs(panel->recordPlot()->peak() - 0.3) < 0.01);
    auto* kind = panel->findChild<QComboBox*>(QStringLiteral("baseKind"));
    QCOMPARE(kind->currentIndex(), 1);  // rigid

    // Newmark's γ and the damping: rows of a dynamic analysis only.
    auto* gamma = window.findChild<QDoubleSpinBox*>(QStringLiteral("analysis_newmark_gamma"));
    QVERIFY(gamma);
    QVERIFY(!gamma->isHidden());
    AnalysisSettings still = window.document()->model().analysis;
    still.kind = AnalysisSettings::Kind::Static;
    window.document()->setAnalysisSettings(still);
    QVERIFY(gamma->isHidden());
    window.document()->undoStack()->undo();
    QVERIFY(!gamma->isHidden());
    QTRY_VERIFY(settled(window));

    QTemporaryDir out;
    window.setRunOutputFolder(out.path());
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    QVERIFY2(window.messages().contains(QStringLiteral("Permanent displacement (relative to the base): largest")),
             qPrintable(window.messages()));
    gui::HistoryPlot* plot = window.historyPlot();
    auto* column = plot->findChild<QComboBox*>(QStringLiteral("historyColumn"));
    for (const char* c : {"block:ux", "block:vx", "block:ay", "base:ax", "base:vx"})
        QVERIFY2(column->findData(QString::fromLatin1(c)) >= 0, c);
    plot->setColumns(QStringLiteral("base:ax"), QStringLiteral("time"));
    QVERIFY(plot->series()->count() > 100);
    double peak = 0.0;
    for (const QPointF& p : plot->series()->points()) peak = std::max(peak, std::fabs(p.y()));
    QVERIFY2(std::fabs(peak - 0.3 * 9.81) < 0.1, qPrintable(QString::number(peak)));  // the record, in m/s²
    plot->setColumns(QStringLiteral("block:vx"), QStringLiteral("time"));
    QVERIFY(plot->series()->count() > 100);
    panel->grab().save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/earthquake_dock.png"));

    // Saved into another folder, the record is named from there and the copy reads back.
    QVERIFY(QDir(folder.path()).mkpath(QStringLiteral("copy")));
    const QString copy = folder.filePath(QStringLiteral("copy/block.json"));
    QVERIFY(window.saveModelAs(copy));
    QCOMPARE(QString::fromStdString(window.document()->model().ground_motions[0].file),
             QStringLiteral("../records/sine-2hz-3-cycles.csv"));
    const ReadResult back = read_model_file(QFile::encodeName(copy).toStdString());
    QVERIFY(back.model);
    QCOMPARE(back.model->ground_motions[0].points.size(), window.document()->model().ground_motions[0].points.size());
}

QTEST_MAIN(EarthquakeTest)
#include "EarthquakeTest.moc"
