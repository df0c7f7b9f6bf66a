// The Run feature of the desktop program on a (virtual) X server: the solver runs on a worker
// thread, the view follows its snapshots (pixels checked), and a stopped run leaves readable
// results while the GUI stays responsive.

#include "MainWindow.hpp"
#include "results/QueryPlot.hpp"
#include "document/ModelDocument.hpp"
#include "results/HistoryPlot.hpp"
#include "results/StepSlider.hpp"
#include "session/RunController.hpp"
#include "tools/EditingTools.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QChartView>
#include <QDockWidget>
#include <QFile>
#include <QGuiApplication>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <QLineSeries>

#include <memory>

using namespace mcdda;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;
using mcdda::gui::RunController;
using mcdda::gui::RunProgress;

namespace {

const QString incline = QStringLiteral(MCDDA_EXAMPLES_DIR "/incline-sliding.json");

std::shared_ptr<const Preprocessed> incline_with(const std::vector<std::string>& overrides)
{
    return std::make_shared<const Preprocessed>(preprocess_file(incline.toStdString(), overrides));
}

/// A strongly coloured pixel: neither the white background nor a grey or black line.
bool saturated(QColor c) { return c.hsvSaturation() > 120 && c.value() > 80; }

void keep(const QImage& image, const QString& name)
{
    image.save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/run_") + name + QStringLiteral(".png"));
}

QAction* find_action(QWidget* window, const QString& name)
{
    return window->findChild<QAction*>(name);
}

}  // namespace

class RunTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void controllerRunsWithoutAWindow();
    void runShowsResultColours();
    void stopKeepsResultsAndGuiResponsive();
    void closingStopsTheRun();
    void salenconOpenMeshRunShowsPlasticZone();
    void longStepShowsItsIterations();
    void lookBackWhileRunning();
    void contactsAndQueryLineOnTheStagedTunnel();
};

void RunTest::initTestCase()
{
    gui::register_run_types();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

void RunTest::controllerRunsWithoutAWindow()
{
    const auto model = incline_with({"/analysis/steps=4"});
    QVERIFY(model->ok);
    QThread thread;
    RunController controller(*model, QString(), QStringLiteral("incline"));
    controller.setThrottle(0, 0);
    controller.moveToThread(&thread);
    // Received on this (the main) thread through queued connections.
    std::vector<RunProgress> progress;
    std::shared_ptr<const ResultSnapshot> last;
    int snapshots = 0;
    std::vector<RunStatus> finished;
    connect(&controller, &RunController::progress, this, [&](const RunProgress& p) { progress.push_back(p); });
    connect(&controller, &RunController::snapshot, this, [&](std::shared_ptr<const ResultSnapshot> s) {
        last = std::move(s);
        ++snapshots;
    });
    connect(&controller, &RunController::finished, this, [&](RunStatus s, const QString&) { finished.push_back(s); });
    connect(&thread, &QThread::started, &controller, &RunController::start);
    thread.start();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), std::size_t(1), 60000);
    thread.quit();
    QVERIFY(thread.wait(10000));
    // The block slides down the incline: every step ran, but it is not in equilibrium.
    QCOMPARE(finished.front(), RunStatus::Unbalanced);
    QCOMPARE(progress.size(), std::size_t(4));  // no throttling: every step
    QCOMPARE(progress.back().step, 4);
    QCOMPARE(snapshots, 5);  // the start and every step
    QVERIFY(last != nullptr);
    QCOMPARE(last->step, 4);
    QCOMPARE(last->displacement.size(), 2 * model->mesh.nodes.size());
    QCOMPARE(last->plastic_state.size(), model->mesh.triangles.size());
}

void RunTest::runShowsResultColours()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    MainWindow window;
    window.showPreprocessed(incline_with({"/analysis/steps=6", "/analysis/output_every=2"}), incline);
    window.setRunOutputFolder(out.path());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QAction* run = find_action(&window, QStringLiteral("runAction"));
    QAction* stop = find_action(&window, QStringLiteral("stopAction"));
    QAction* pause = find_action(&window, QStringLiteral("pauseAction"));
    QVERIFY(run && stop && pause);
    QVERIFY(run->isEnabled());
    QVERIFY(!stop->isEnabled() && !pause->isEnabled());

    const QImage before = window.modelView()->grabFrame();
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QVERIFY(!run->isEnabled());
    QVERIFY(stop->isEnabled() && pause->isEnabled());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    // The block slides down the incline: every step ran, but it is not in equilibrium.
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Unbalanced);
    QVERIFY2(window.messages().contains(QStringLiteral("not in equilibrium")), qPrintable(window.messages()));
    QVERIFY(!window.isRunning());
    QVERIFY(run->isEnabled() && !stop->isEnabled() && !pause->isEnabled());
    QVERIFY(window.messages().contains(QStringLiteral("step 6/6")));
    QVERIFY(QFile::exists(out.filePath(QStringLiteral("incline-sliding.pvd"))));

    // The last step is shown (its saved file, with its contacts), coloured by the displacement
    // magnitude (a rainbow map), where the model picture had only its material colours.
    QVERIFY2(window.modelView()->resultFile().endsWith(QStringLiteral("_000006.vtu")),
             qPrintable(window.modelView()->resultFile()));
    QCOMPARE(window.resultField(), QStringLiteral("displacement"));
    const QImage frame = window.modelView()->grabFrame();
    keep(frame, QStringLiteral("displacement"));
    const int width = frame.width();
    auto count_model_area = [width](const QImage& image, auto test) {
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < width * 6 / 10; ++x)  // left of the scalar bar
                if (test(image.pixelColor(x, y))) ++n;
        return n;
    };
    const int coloured = count_model_area(frame, saturated);
    QVERIFY2(coloured > 20000, qPrintable(QString::number(coloured)));
    QVERIFY2(count_model_area(before, saturated) < coloured / 4, "the model picture has few saturated colours");
    // A model point inside the slope is coloured, not background.
    const QPointF inside = window.modelView()->toWidget(QPointF(9.0, 2.0));
    QVERIFY(saturated(frame.pixelColor(inside.toPoint())));
    // The sliding block moved most: the red end of the map.
    // (Around the block's centre: the contact-force lines are drawn over the block.)
    const QPoint centre = window.modelView()->toWidget(QPointF(4.82, 4.37)).toPoint();
    int red_pixels = 0;
    for (int dy = -6; dy <= 6; ++dy)
        for (int dx = -6; dx <= 6; ++dx) {
            const QColor c = frame.pixelColor(centre + QPoint(dx, dy));
            red_pixels += c.red() > 180 && c.blue() < 100;
        }
    QVERIFY2(red_pixels > 40, qPrintable(QString::number(red_pixels) + " red pixels around the block's centre"));

    // Plastic state: elastic everywhere (plasticity is off) → the light grey category.
    window.setResultField(QStringLiteral("plastic_state"));
    const QImage states = window.modelView()->grabFrame();
    keep(states, QStringLiteral("plastic_state"));
    const QColor grey = states.pixelColor(inside.toPoint());
    QVERIFY2(std::abs(grey.red() - 209) <= 6 && std::abs(grey.green() - 209) <= 6 && std::abs(grey.blue() - 209) <= 6,
             qPrintable(grey.name()));
}

void RunTest::stopKeepsResultsAndGuiResponsive()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    MainWindow window;
    window.showPreprocessed(incline_with({"/analysis/steps=100000", "/analysis/output_every=1000"}), incline);
    window.setRunOutputFolder(out.path());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    int ticks = 0;
    QTimer timer;
    connect(&timer, &QTimer::timeout, [&ticks] { ++ticks; });
    timer.start(10);
    QSignalSpy progress(&window, &MainWindow::runProgressed);
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 0, 60000);
    const int ticks_at_progress = ticks;
    QTest::qWait(300);  // the solver keeps running; the event loop must too
    QVERIFY2(ticks > ticks_at_progress + 5, qPrintable(QStringLiteral("%1 -> %2").arg(ticks_at_progress).arg(ticks)));
    QVERIFY(window.isRunning());

    // The plot follows the history while the run goes on (re-read about once a second).
    QTRY_VERIFY_WITH_TIMEOUT(window.historyPlot()->series()->count() > 0, 5000);
    QVERIFY(window.isRunning());
    const int rows_seen = window.historyPlot()->series()->count();
    QTRY_VERIFY_WITH_TIMEOUT(window.historyPlot()->series()->count() > rows_seen, 5000);

    // Paused: no more progress; Stop still ends it.
    QAction* pause = window.findChild<QAction*>(QStringLiteral("pauseAction"));
    QVERIFY(pause != nullptr);
    window.togglePause();
    QCOMPARE(pause->text(), QStringLiteral("Res&ume"));
    QTest::qWait(300);  // the step under way and its queued signals
    const auto paused_at = progress.count();
    QTest::qWait(400);
    QCOMPARE(progress.count(), paused_at);
    window.stopRun();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Cancelled);
    QVERIFY(!window.isRunning());

    QFile pvd(out.filePath(QStringLiteral("incline-sliding.pvd")));
    QVERIFY(pvd.open(QIODevice::ReadOnly));
    const QByteArray text = pvd.readAll();
    QVERIFY(text.contains("</VTKFile>"));
    QVERIFY(text.contains(".vtu"));
    QFile summary(out.filePath(QStringLiteral("summary.json")));
    QVERIFY(summary.open(QIODevice::ReadOnly));
    QVERIFY(summary.readAll().contains("cancelled"));
}

void RunTest::closingStopsTheRun()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    auto window = std::make_unique<MainWindow>();
    window->showPreprocessed(incline_with({"/analysis/steps=100000", "/analysis/output_every=1000"}), incline);
    window->setRunOutputFolder(out.path());
    window->show();
    QVERIFY(QTest::qWaitForWindowExposed(window.get()));
    QSignalSpy progress(window.get(), &MainWindow::runProgressed);
    QVERIFY(window->startRun());
    QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 0, 60000);
    QVERIFY(window->close());  // stops the worker and joins its thread
    QVERIFY(!window->isRunning());
    QVERIFY(window->findChildren<QThread*>().isEmpty());
    window.reset();  // and nothing is left to crash later
    QTest::qWait(100);
    QFile summary(out.filePath(QStringLiteral("summary.json")));
    QVERIFY(summary.open(QIODevice::ReadOnly));
    QVERIFY(summary.readAll().contains("cancelled"));
}

// A first user's path through the window: File ▸ Open an example, Run ▸ Mesh, a few steps of Run,
// and the plastic zone around the tunnel in the picture (yellow/red cells near the wall, grey
// ones far away).
void RunTest::salenconOpenMeshRunShowsPlasticZone()
{
    const QString path = QStringLiteral(MCDDA_EXAMPLES_DIR "/salencon-tunnel.json");
    QTemporaryDir out;
    QVERIFY(out.isValid());
    MainWindow window;
    window.setAskToSave(false);
    window.setRunOutputFolder(out.path());
    window.resize(1100, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY2(window.openModel(path), qPrintable(window.messages()));

    // Fewer steps for the test (an edit: undoable, re-meshed in the background).
    AnalysisSettings settings = window.document()->model().analysis;
    settings.steps = 2;
    settings.output_every = 1;
    window.document()->setAnalysisSettings(settings);
    QAction* mesh = find_action(&window, QStringLiteral("meshAction"));
    QVERIFY(mesh && mesh->isEnabled());
    mesh->trigger();
    QVERIFY(window.isPreprocessing());
    QTRY_VERIFY_WITH_TIMEOUT(!window.isPreprocessing(), 60000);
    QVERIFY2(window.statisticsText().contains(QStringLiteral("13415 elements")), qPrintable(window.statisticsText()));
    QVERIFY(window.messages().contains(QStringLiteral("13415")));

    window.setResultField(QStringLiteral("plastic_state"));
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 240000);
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Completed);
    window.modelView()->showBox(0, 0, 6, 6);  // the tunnel's quarter and the plastic ring
    const QImage frame = window.modelView()->grabFrame();
    keep(frame, QStringLiteral("salencon_plastic_zone"));
    auto yielded = [](QColor c) {  // the yellow or red categories, not grey
        return c.hsvSaturation() > 120 && c.value() > 120 && (c.hsvHue() < 65 || c.hsvHue() > 340);
    };
    auto share = [&](double x, double y) {
        const QPointF centre = window.modelView()->toWidget(QPointF(x, y)) * window.modelView()->devicePixelRatioF();
        int n = 0;
        for (int dy = -3; dy <= 3; ++dy)
            for (int dx = -3; dx <= 3; ++dx) n += yielded(frame.pixelColor(qRound(centre.x()) + dx, qRound(centre.y()) + dy));
        return n / 49.0;
    };
    // Closed form: plastic radius 2.505 m. Inside it (r = 1.8 m) yielded, outside (r = 3.5 m) not.
    QVERIFY2(share(1.8 * 0.7071, 1.8 * 0.7071) > 0.8, qPrintable(QString::number(share(1.27, 1.27))));
    QVERIFY2(share(3.5 * 0.7071, 3.5 * 0.7071) < 0.2, qPrintable(QString::number(share(2.47, 2.47))));

    // The status bar tells what is under the cursor: the state inside the ring, and with σ1
    // shown, a compressive stress in MPa near the far field (−10 MPa at the outer boundary).
    ModelView* view = window.modelView();
    QTest::mouseMove(view, view->toWidget(QPointF(1.27, 1.27)).toPoint());
    QTRY_VERIFY2(window.cursorText().contains(QStringLiteral("plastic state: yield")), qPrintable(window.cursorText()));
    window.setResultField(QStringLiteral("stress_3"));
    window.modelView()->showBox(0, 0, 20, 20);
    QTest::mouseMove(view, view->toWidget(QPointF(15.0, 15.0)).toPoint());
    // The window's default is the geotechnical convention: compression positive, said so.
    QTRY_VERIFY2(window.cursorText().contains(QStringLiteral("principal stress 3 (compression +) = ")) &&
                     window.cursorText().contains(QStringLiteral("MPa")),
                 qPrintable(window.cursorText()));
    QString text = window.cursorText();
    const double sigma3 = text.section(QStringLiteral("= "), -1).section(QLatin1Char(' '), 0, 0).toDouble();
    QVERIFY2(sigma3 > 9.0 && sigma3 < 12.0, qPrintable(text));
    // The files' convention on request: the same stress, tension positive; and σ1 (compression)
    // is minus the tension-positive σ3.
    window.findChild<QComboBox*>(QStringLiteral("stressSignBox"))->setCurrentIndex(1);
    QTest::mouseMove(view, view->toWidget(QPointF(15.2, 15.0)).toPoint());
    QTest::mouseMove(view, view->toWidget(QPointF(15.0, 15.0)).toPoint());
    QTRY_VERIFY2(window.cursorText().contains(QStringLiteral("principal stress 3 (tension +) = -")), qPrintable(window.cursorText()));
    text = window.cursorText();
    const double tension3 = text.section(QStringLiteral("= "), -1).section(QLatin1Char(' '), 0, 0).toDouble();
    window.setResultField(QStringLiteral("stress_1"));
    window.findChild<QComboBox*>(QStringLiteral("stressSignBox"))->setCurrentIndex(0);
    QTest::mouseMove(view, view->toWidget(QPointF(15.2, 15.0)).toPoint());
    QTest::mouseMove(view, view->toWidget(QPointF(15.0, 15.0)).toPoint());
    QTRY_VERIFY2(window.cursorText().contains(QStringLiteral("principal stress 1 (compression +) = ")), qPrintable(window.cursorText()));
    text = window.cursorText();
    const double compression1 = text.section(QStringLiteral("= "), -1).section(QLatin1Char(' '), 0, 0).toDouble();
    QVERIFY2(std::abs(compression1 + tension3) < 0.01, qPrintable(QStringLiteral("%1 %2").arg(compression1).arg(tension3)));
}

// Inside a long step (Salençon's excavation, dozens of equilibrium
// iterations) the status bar tells the iterations and the out-of-balance force.
void RunTest::longStepShowsItsIterations()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    const QString path = QStringLiteral(MCDDA_EXAMPLES_DIR "/salencon-tunnel.json");
    auto model = std::make_shared<const Preprocessed>(
        preprocess_file(path.toStdString(), {"/analysis/steps=1", "/mesh/local/0/size=0.15"}));
    QVERIFY(model->ok);
    MainWindow window;
    window.showPreprocessed(model, path);
    window.setRunOutputFolder(out.path());
    window.setRunThrottle(0, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy iterating(&window, &MainWindow::runIterating);
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_VERIFY_WITH_TIMEOUT(window.statusBar()->currentMessage().contains(QStringLiteral("equilibrium iteration")), 60000);
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Step 1: equilibrium iteration")),
             qPrintable(window.statusBar()->currentMessage()));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    QVERIFY(iterating.count() >= 5);
    const auto last = iterating.last().at(0).value<IterationInfo>();
    QCOMPARE(last.step, 1);
    QVERIFY(last.iteration >= 5);
    QVERIFY(last.yielding > 0);
    QVERIFY(last.out_of_balance > 0.0);
}

// During a run the Steps dock lists the steps saved so far; choosing an
// earlier one shows it and keeps it shown while the run goes on; the last one follows the run.
void RunTest::lookBackWhileRunning()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    MainWindow window;
    window.showPreprocessed(incline_with({"/analysis/steps=100000", "/analysis/output_every=2"}), incline);
    window.setRunOutputFolder(out.path());
    window.setRunThrottle(0, 50);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    gui::StepSlider* steps = window.stepSlider();
    QTRY_VERIFY_WITH_TIMEOUT(steps->count() >= 3, 60000);
    QVERIFY(window.isRunning());
    steps->setCurrentIndex(0);
    QVERIFY2(window.shownStep().endsWith(QStringLiteral("_000000.vtu")), qPrintable(window.shownStep()));
    const int seen = steps->count();
    QTRY_VERIFY_WITH_TIMEOUT(steps->count() > seen, 60000);  // the list grows, the choice stays
    QCOMPARE(steps->currentIndex(), 0);
    QVERIFY(window.shownStep().endsWith(QStringLiteral("_000000.vtu")));
    steps->setCurrentIndex(steps->count() - 1);  // back to the newest: the run is followed
    QVERIFY(window.shownStep().isEmpty());
    window.stopRun();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
}

// Contacts on screen and query lines: after a run of the staged jointed tunnel
// (shortened: one step for the bolts and the bench) the last saved step is shown with its contact
// forces and bolts, which the Contacts toggle takes away; a query line across the tunnel plots
// the field with a gap in the opening and exports it.
void RunTest::contactsAndQueryLineOnTheStagedTunnel()
{
    const QString path = QStringLiteral(MCDDA_EXAMPLES_DIR "/jointed-tunnel-staged.json");
    const auto model = std::make_shared<const Preprocessed>(preprocess_file(
        path.toStdString(), {"/stages/2/analysis/steps=1", "/stages/3/analysis/steps=1", "/analysis/output_every=1"}));
    QVERIFY(model->ok);
    QTemporaryDir out;
    MainWindow window;
    window.resize(1100, 750);
    window.showPreprocessed(model, path);
    window.setRunOutputFolder(out.path());
    window.setResultField(QStringLiteral("plastic_state"));  // greys, yellow, red: no blue or green
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 240000);
    QVERIFY2(window.shownStep().endsWith(QStringLiteral("_000008.vtu")), qPrintable(window.shownStep()));
    auto count = [](const QImage& image, QColor want) {
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (std::abs(c.red() - want.red()) < 30 && std::abs(c.green() - want.green()) < 30 &&
                    std::abs(c.blue() - want.blue()) < 30)
                    ++n;
            }
        return n;
    };
    const QColor force_blue = QColor::fromRgbF(0.0, 0.40, 0.75);  // view/ResultScene: contact forces
    const QColor bolt_green = QColor::fromRgbF(0.0, 0.55, 0.25);   // and bolts
    const QImage with = window.modelView()->grabFrame();
    keep(with, QStringLiteral("staged_tunnel_contacts"));
    const int forces = count(with, force_blue), bolts = count(with, bolt_green);
    QVERIFY2(forces > 200, qPrintable(QString::number(forces)));
    QVERIFY2(bolts > 20, qPrintable(QString::number(bolts)));
    window.findChild<QAction*>(QStringLiteral("contactsAction"))->trigger();  // off
    const QImage without = window.modelView()->grabFrame();
    QVERIFY2(count(without, force_blue) < forces / 20, qPrintable(QString::number(count(without, force_blue))));
    QVERIFY(count(without, bolt_green) < bolts / 5);

    // A query line through the tunnel's springlines, drawn with two clicks.
    window.setResultField(QStringLiteral("stress_yy"));
    window.editingTools()->useQueryLine();
    ModelView* view = window.modelView();
    QVERIFY(!view->resultProbe().empty());  // the tool keeps the result picture
    for (const QPointF& p : {QPointF(-19.0, 0.5), QPointF(19.0, 0.5)})
        QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->toWidget(p).toPoint());
    gui::QueryPlot* query = window.queryPlot();
    QTRY_VERIFY(query->hasLine());
    const auto& samples = query->samples();
    QCOMPARE(samples.size(), std::size_t(200));
    QVERIFY(std::abs(samples.front().point.x + 19.0) < 0.3 && std::abs(samples.back().point.x - 19.0) < 0.3);
    int in_rock = 0, in_opening = 0;
    for (const gui::QuerySample& q : samples) {
        if (std::abs(q.point.x) < 2.5) {
            QVERIFY2(!q.inside, "the tunnel opening is a gap");
            ++in_opening;
        } else if (std::abs(q.point.x) > 3.5 && std::abs(q.point.x) < 18.5) {
            QVERIFY(q.inside);
            double v = 0.0;
            QVERIFY(view->resultProbe().valueAt(q.point.x, q.point.y, &v));
            QCOMPARE(q.value, v);  // what the picture shows there
            ++in_rock;
        }
    }
    QVERIFY(in_opening > 10 && in_rock > 100);
    window.findChild<QDockWidget*>(QStringLiteral("query"))->raise();
    QTest::qWait(100);
    const QImage chart = query->chartView()->grab().toImage();
    keep(chart, QStringLiteral("query_chart"));
    keep(window.grab().toImage(), QStringLiteral("query_window"));
    QVERIFY2(count(chart, gui::QueryPlot::curveColor()) > 50, qPrintable(QString::number(count(chart, gui::QueryPlot::curveColor()))));
    // A step change redraws the query (the first saved step has no excavation yet).
    const double last = samples[20].value;
    window.stepSlider()->setCurrentIndex(0);
    QVERIFY(query->samples()[20].value != last);
    // CSV: a header and one row per point on the mesh.
    QString error;
    const QString csv = out.filePath(QStringLiteral("query.csv"));
    QVERIFY2(query->exportCsv(csv, error), qPrintable(error));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    QVERIFY(lines.front().startsWith("distance (m),x (m),y (m),"));
    int inside = 0;
    for (const gui::QuerySample& q : query->samples()) inside += q.inside ? 1 : 0;
    QCOMPARE(static_cast<int>(lines.size()) - 1, inside);
}

QTEST_MAIN(RunTest)
#include "RunTest.moc"
