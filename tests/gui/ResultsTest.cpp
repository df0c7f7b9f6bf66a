// The results features of the desktop program on a (virtual) X server: more fields and the
// deformed shape in the view, replaying saved steps, the history plot and the exports. One
// short run of the incline example is shared by the tests.

#include "MainWindow.hpp"
#include "results/HistoryPlot.hpp"
#include "results/StepSlider.hpp"
#include "results/UnbalancedPlot.hpp"
#include "widgets/ResultToolBar.hpp"
#include "session/RunController.hpp"
#include "view/SceneGeometry.hpp"
#include "widgets/ModelView.hpp"

#include <QChart>
#include <QChartView>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGuiApplication>
#include <QImageReader>
#include <QLineSeries>
#include <QScatterSeries>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSlider>
#include <QTemporaryDir>
#include <QtTest>

#include <map>
#include <memory>

using namespace mcdda;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;

namespace {

const QString incline = QStringLiteral(MCDDA_EXAMPLES_DIR "/incline-sliding.json");

bool saturated(QColor c) { return c.hsvSaturation() > 120 && c.value() > 80; }

void keep(const QImage& image, const QString& name)
{
    image.save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/results_") + name + QStringLiteral(".png"));
}

/// Pixels that differ clearly between two frames of the same size.
int differing(const QImage& a, const QImage& b)
{
    if (a.size() != b.size()) return a.width() * a.height();
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            if (std::abs(p.red() - q.red()) + std::abs(p.green() - q.green()) + std::abs(p.blue() - q.blue()) > 60) ++n;
        }
    return n;
}

/// Histogram of coarse colours (4 levels a channel) of the left part (the model, not the bar).
std::map<int, int> colour_histogram(const QImage& image)
{
    std::map<int, int> h;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width() * 6 / 10; ++x) {
            const QColor c = image.pixelColor(x, y);
            ++h[(c.red() / 64) * 16 + (c.green() / 64) * 4 + c.blue() / 64];
        }
    return h;
}

/// Non-white pixels in the right part of the frame, where the scalar bar is.
int legend_ink(const QImage& image)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = image.width() * 8 / 10; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() < 200 || c.green() < 200 || c.blue() < 200) ++n;
        }
    return n;
}

}  // namespace

class ResultsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void fieldsChangeThePicture();
    void stepSliderReplaysSavedSteps();
    void plotShowsTheHistory();
    void unbalancedRatioBesideTheHistory();
    void deformationScaleIsShownAndWarned();
    void unitsAreChosenOnce();
    void exportPngWritesTheFrame();
    void exportsCopyTheFiles();
    void cleanupTestCase();

private:
    QTemporaryDir out_;
    std::unique_ptr<MainWindow> window_;
};

void ResultsTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);  // the units chosen go to a test settings file
    gui::register_run_types();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
    QVERIFY(out_.isValid());
    window_ = std::make_unique<MainWindow>();
    const auto model = std::make_shared<const Preprocessed>(
        preprocess_file(incline.toStdString(), {"/analysis/steps=6", "/analysis/output_every=2"}));
    QVERIFY(model->ok);
    window_->showPreprocessed(model, incline);
    window_->setRunOutputFolder(out_.path());
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    QSignalSpy finished(window_.get(), &MainWindow::runFinished);
    QVERIFY(window_->startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    // The block slides down the incline: every step ran, but it is not in equilibrium.
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Unbalanced);
    QCOMPARE(window_->resultsFolder(), out_.path());
}

void ResultsTest::fieldsChangeThePicture()
{
    ModelView* view = window_->modelView();
    window_->setResultField(QStringLiteral("stress_1"));
    QCOMPARE(window_->resultField(), QStringLiteral("stress_1"));
    const QImage sigma1 = view->grabFrame();
    keep(sigma1, QStringLiteral("stress_1"));
    window_->setResultField(QStringLiteral("displacement"));
    const QImage displacement = view->grabFrame();
    keep(displacement, QStringLiteral("displacement"));
    QVERIFY(!sigma1.isNull() && sigma1.size() == displacement.size());

    // Both are coloured (a rainbow map) but differently distributed.
    const auto a = colour_histogram(sigma1), b = colour_histogram(displacement);
    QVERIFY(a != b);
    int moved = 0;  // pixels that change bins, summed over the bins
    for (const auto& [bin, count] : a) moved += std::abs(count - (b.count(bin) ? b.at(bin) : 0));
    QVERIFY2(moved > 2000, qPrintable(QString::number(moved)));
    QVERIFY2(differing(sigma1, displacement) > 2000, "the two fields look the same");
    // The scalar bar (colours, labels, title) is drawn at the right.
    QVERIFY2(legend_ink(sigma1) > 2000, qPrintable(QString::number(legend_ink(sigma1))));
    QVERIFY2(legend_ink(displacement) > 2000, qPrintable(QString::number(legend_ink(displacement))));

    // Every field of the chooser can be shown.
    for (const char* field : {"ux", "uy", "stress_xx", "stress_yy", "stress_xy", "stress_3", "plastic_strain",
                              "plastic_state"}) {
        window_->setResultField(QString::fromLatin1(field));
        QCOMPARE(window_->resultField(), QString::fromLatin1(field));
        QVERIFY2(view->result() != nullptr || !view->resultFile().isEmpty(), field);
    }
    window_->setResultField(QStringLiteral("displacement"));
}

void ResultsTest::stepSliderReplaysSavedSteps()
{
    gui::StepSlider* steps = window_->stepSlider();
    QVERIFY(steps != nullptr);
    const QStringList vtus = QDir(out_.path()).entryList({QStringLiteral("*.vtu")}, QDir::Files, QDir::Name);
    QVERIFY(vtus.size() >= 2);
    QCOMPARE(steps->count(), static_cast<int>(vtus.size()));
    QCOMPARE(steps->slider()->maximum() - steps->slider()->minimum() + 1, static_cast<int>(vtus.size()));
    QCOMPARE(steps->currentIndex(), steps->count() - 1);

    ModelView* view = window_->modelView();
    window_->setDeformFactor(20.0);
    steps->setCurrentIndex(steps->count() - 1);
    QCOMPARE(QFileInfo(view->resultFile()).fileName(), vtus.last());
    const QImage last = view->grabFrame();
    keep(last, QStringLiteral("step_last"));

    steps->slider()->setValue(0);  // as the user drags it
    QCOMPARE(QFileInfo(view->resultFile()).fileName(), vtus.first());
    const QImage first = view->grabFrame();
    keep(first, QStringLiteral("step_0"));
    QVERIFY2(differing(first, last) > 500, qPrintable(QString::number(differing(first, last))));

    // Nothing has moved at step 0: the deformation factor changes nothing and the displacement
    // is uniform (no red end of the map on the sliding block).
    window_->setDeformFactor(0.0);
    const QImage undeformed = view->grabFrame();
    window_->setDeformFactor(20.0);
    const QImage deformed = view->grabFrame();
    // Only joints (drawn undeformed only) may differ.
    QVERIFY2(differing(undeformed, deformed) < 2000, qPrintable(QString::number(differing(undeformed, deformed))));
    const QPoint block = view->toWidget(QPointF(4.82, 4.37)).toPoint();
    const QColor c0 = first.pixelColor(block), c1 = last.pixelColor(block);
    QVERIFY2(!(c0.red() > 180 && c0.blue() < 100), qPrintable(c0.name()));
    QVERIFY2(c1 != c0, qPrintable(c1.name()));
    window_->setDeformFactor(0.0);
}

void ResultsTest::plotShowsTheHistory()
{
    gui::HistoryPlot* plot = window_->historyPlot();
    QVERIFY(plot != nullptr);
    QFile csv(out_.filePath(QStringLiteral("history.csv")));
    QVERIFY(csv.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = csv.readAll().trimmed().split('\n');
    const int rows = static_cast<int>(lines.size()) - 1;
    QVERIFY(rows >= 6);
    QCOMPARE(static_cast<int>(plot->table().rows.size()), rows);
    QVERIFY(!plot->yColumn().isEmpty());
    QVERIFY(plot->yColumn().endsWith(QStringLiteral(":ux")) || plot->yColumn().endsWith(QStringLiteral(":uy")));
    QCOMPARE(plot->xColumn(), QStringLiteral("time"));
    QVERIFY(plot->chart() != nullptr);
    QCOMPARE(plot->chart()->series().size(), 2);  // the curve, and a strength reduction's failed trials
    QCOMPARE(plot->series()->count(), rows);
    QCOMPARE(plot->failedTrials()->count(), 0);

    // Against a load column when there is one (load-settlement).
    for (const QString& c : plot->table().columns)
        if (c.startsWith(QStringLiteral("load:"))) {
            plot->setColumns(plot->yColumn(), c);
            QCOMPARE(plot->xColumn(), c);
            QCOMPARE(plot->series()->count(), rows);
            plot->setColumns(plot->yColumn(), QStringLiteral("time"));
            break;
        }
    const int column = plot->table().column(plot->yColumn());
    QCOMPARE(plot->series()->at(rows - 1).y(), plot->table().rows.back()[column]);
}

// The unbalanced-force ratio per step under the history plot, with the equilibrium
// limit as a dashed line; both drawn.
void ResultsTest::unbalancedRatioBesideTheHistory()
{
    gui::HistoryPlot* plot = window_->historyPlot();
    gui::UnbalancedPlot* unbalanced = plot->unbalancedPlot();
    QVERIFY(unbalanced);
    const gui::HistoryTable& table = plot->table();
    const int step = table.column(QStringLiteral("step")), ratio = table.column(QStringLiteral("unbalanced_ratio"));
    QVERIFY(step >= 0 && ratio >= 0);
    QCOMPARE(unbalanced->series()->count(), static_cast<int>(table.rows.size()));
    for (int i = 0; i < unbalanced->series()->count(); ++i) {
        QCOMPARE(unbalanced->series()->at(i).x(), table.rows[static_cast<std::size_t>(i)][step]);
        QCOMPARE(unbalanced->series()->at(i).y(), std::max(table.rows[static_cast<std::size_t>(i)][ratio], unbalanced->axisFloor()));
    }
    QCOMPARE(unbalanced->limitSeries()->count(), 2);
    // Whole decades around the data and the limit, not down to 1e-12 for step 0's ratio of 0
    // (whose 14 decade labels did not fit and were elided).
    QVERIFY2(unbalanced->axisFloor() >= 1e-3, qPrintable(QString::number(unbalanced->axisFloor())));
    QCOMPARE(unbalanced->limitSeries()->at(0).y(), window_->modelView()->scene()->model.analysis.equilibrium_ratio);
    window_->findChild<QDockWidget*>(QStringLiteral("plots"))->raise();
    QTest::qWait(100);
    const QImage image = unbalanced->chartView()->grab().toImage();
    auto count = [&](QColor want) {
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (std::abs(c.red() - want.red()) < 40 && std::abs(c.green() - want.green()) < 40 &&
                    std::abs(c.blue() - want.blue()) < 40)
                    ++n;
            }
        return n;
    };
    QVERIFY2(count(gui::UnbalancedPlot::seriesColor()) > 30, qPrintable(QString::number(count(gui::UnbalancedPlot::seriesColor()))));
    QVERIFY2(count(gui::UnbalancedPlot::limitColor()) > 10, qPrintable(QString::number(count(gui::UnbalancedPlot::limitColor())) + QStringLiteral(" size %1x%2 axis %3..%4").arg(image.width()).arg(image.height()).arg(unbalanced->limitSeries()->at(0).y()).arg(unbalanced->limitSeries()->at(1).x())));
}

// The automatic deformation scale is used and shown beside the field; a
// scale that turns elements inside out is warned about.
void ResultsTest::deformationScaleIsShownAndWarned()
{
    auto* bar = window_->findChild<gui::ResultToolBar*>();
    QVERIFY(bar);
    window_->stepSlider()->setCurrentIndex(window_->stepSlider()->count() - 1);  // the block has slid
    window_->setResultField(QStringLiteral("displacement"));
    bar->setDeformAuto(true);
    const view::ResultInfo& info = window_->modelView()->resultInfo();
    QVERIFY(info.max_displacement > 0.0);
    const double size = view::model_box(*window_->modelView()->scene()).size();
    QVERIFY2(std::abs(info.deform_factor * info.max_displacement - 0.05 * size) < 1e-9 * size,
             qPrintable(QString::number(info.deform_factor)));
    QVERIFY2(bar->infoText().contains(QStringLiteral("(auto)")), qPrintable(bar->infoText()));
    QVERIFY(!bar->infoText().contains(QStringLiteral("inside out")));
    view::ResultInfo bad = info;
    bad.inverted_elements = 12;
    bar->showInfo(bad);
    QVERIFY2(bar->infoText().contains(QStringLiteral("12 element")) && bar->infoText().contains(QStringLiteral("inside out")),
             qPrintable(bar->infoText()));
    bar->setDeformFactor(0.0);
    QVERIFY(!bar->deformAuto());
    QCOMPARE(window_->modelView()->resultInfo().deform_factor, 0.0);
    QVERIFY(bar->infoText().isEmpty());
}

// One choice of units for stresses and displacements, used by the legend, the
// cursor read-out and query lines (the probe), and kept for the next session.
void ResultsTest::unitsAreChosenOnce()
{
    auto* bar = window_->findChild<gui::ResultToolBar*>();
    ModelView* view = window_->modelView();
    window_->stepSlider()->setCurrentIndex(window_->stepSlider()->count() - 1);
    window_->setResultField(QStringLiteral("displacement"));
    bar->setUnits(view::StressUnit::Automatic, view::LengthUnit::Metre);
    QCOMPARE(view->resultProbe().units, std::string("m"));
    const Point2 block{4.82, 4.37};  // on the sliding block
    double metres = 0.0, millimetres = 0.0;
    QVERIFY(view->resultProbe().valueAt(block.x, block.y, &metres));
    window_->findChild<QAction*>(QStringLiteral("lengthUnitMm"))->trigger();
    QCOMPARE(bar->lengthUnit(), view::LengthUnit::Millimetre);
    QCOMPARE(view->resultProbe().units, std::string("mm"));
    QVERIFY(view->resultProbe().valueAt(block.x, block.y, &millimetres));
    QVERIFY2(std::abs(millimetres - 1e3 * metres) <= 1e-9 * std::abs(millimetres), qPrintable(QString::number(millimetres)));
    QCOMPARE(QSettings().value(QStringLiteral("units/length")).toInt(), int(view::LengthUnit::Millimetre));
    window_->setResultField(QStringLiteral("stress_yy"));
    window_->findChild<QAction*>(QStringLiteral("stressUnitMPa"))->trigger();
    QCOMPARE(view->resultProbe().units, std::string("MPa"));
    window_->findChild<QAction*>(QStringLiteral("stressUnitKPa"))->trigger();
    QCOMPARE(view->resultProbe().units, std::string("kPa"));
    bar->setUnits(view::StressUnit::Automatic, view::LengthUnit::Metre);
    window_->setResultField(QStringLiteral("displacement"));
}

void ResultsTest::exportPngWritesTheFrame()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("view.png"));
    const QImage frame = window_->modelView()->grabFrame();
    QVERIFY(window_->exportPng(path));
    QImage saved;
    QVERIFY(saved.load(path));
    QCOMPARE(saved.size(), frame.size());
    int coloured = 0;
    for (int y = 0; y < saved.height(); ++y)
        for (int x = 0; x < saved.width(); ++x)
            if (saturated(saved.pixelColor(x, y))) ++coloured;
    QVERIFY2(coloured > 10000, qPrintable(QString::number(coloured)));
    // No temporary file is left beside it.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("view.png")});

    // A folder that cannot be written: false, and the window says why.
    QVERIFY(!window_->exportPng(dir.filePath(QStringLiteral("missing/sub/view.png"))));
    QVERIFY(window_->messages().contains(QStringLiteral("view.png")));
}

void ResultsTest::exportsCopyTheFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString target = dir.filePath(QStringLiteral("copy"));
    QVERIFY(window_->exportSteps(target));
    const QStringList vtus = QDir(out_.path()).entryList({QStringLiteral("*.vtu")}, QDir::Files, QDir::Name);
    QCOMPARE(QDir(target).entryList({QStringLiteral("*.vtu")}, QDir::Files, QDir::Name), vtus);
    QVERIFY(QFile::exists(QDir(target).filePath(QStringLiteral("incline-sliding.pvd"))));

    const QString csv = dir.filePath(QStringLiteral("h.csv"));
    QVERIFY(window_->exportHistory(csv));
    QFile a(csv), b(out_.filePath(QStringLiteral("history.csv")));
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    QCOMPARE(a.readAll(), b.readAll());
}

void ResultsTest::cleanupTestCase()
{
    if (window_) window_->close();
    window_.reset();
}

QTEST_MAIN(ResultsTest)
#include "ResultsTest.moc"
