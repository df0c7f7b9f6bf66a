// A strength reduction in the desktop program on a (virtual) X server: chosen as the analysis
// type in the Properties dock, its trials logged as they end, the factor of safety shown in the
// status bar, the Plots dock drawing the factor–displacement curve (pixels checked) and the
// picture ending on the mechanism.
//
// The model is the planar wedge of examples/slope-wedge.json (rock elastic, the joint's friction
// reduced): F = tan 20° / tan 30° = 0.630.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "results/HistoryPlot.hpp"
#include "session/RunController.hpp"
#include "widgets/ModelView.hpp"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QGuiApplication>
#include <QLabel>
#include <QLineSeries>
#include <QRegularExpression>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace mcdda;
using mcdda::gui::MainWindow;

namespace {

const QString wedge = QStringLiteral(MCDDA_EXAMPLES_DIR "/slope-wedge.json");

void keep(const QImage& image, const QString& name)
{
    image.save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/safety_") + name + QStringLiteral(".png"));
}

/// Pixels of `image` within 40 per channel of `colour`.
int count_colour(const QImage& image, QColor colour)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            n += std::abs(c.red() - colour.red()) < 40 && std::abs(c.green() - colour.green()) < 40 &&
                 std::abs(c.blue() - colour.blue()) < 40;
        }
    return n;
}

}  // namespace

class SafetyRunTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void strengthReductionShowsFactorCurveAndMechanism();
};

void SafetyRunTest::initTestCase()
{
    gui::register_run_types();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

void SafetyRunTest::strengthReductionShowsFactorCurveAndMechanism()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    MainWindow window;
    QVERIFY(guitest::show_model(window, wedge));
    QTRY_VERIFY_WITH_TIMEOUT(guitest::settled(window), 60000);
    window.setRunOutputFolder(out.path());

    // The analysis type: "Strength reduction" in the Properties dock applies at once.
    auto* type = window.findChild<QComboBox*>(QStringLiteral("analysisKind"));
    QVERIFY(type != nullptr);
    QVERIFY(!window.modelView()->scene()->model.analysis.strength_reduction);
    const int item = type->findText(QStringLiteral("Strength reduction"));
    QVERIFY(item >= 0);
    type->setCurrentIndex(item);
    QTRY_VERIFY_WITH_TIMEOUT(guitest::settled(window) && window.modelView()->scene()->model.analysis.strength_reduction,
                             60000);

    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Completed);

    // Every trial in the log, the first at F = 1 (which does not stand: 1 > 0.630).
    const QString log = window.messages();
    QVERIFY2(log.contains(QStringLiteral("Trial 1: F = 1.0000 does not stand")), qPrintable(log));
    QVERIFY2(log.contains(QStringLiteral(" stands (largest displacement")), qPrintable(log));
    // The factor, prominently, within 1 % of tan 20° / tan 30°.
    const QString shown = window.factorOfSafetyText();
    const QRegularExpressionMatch number = QRegularExpression(QStringLiteral("(\\d+\\.\\d+)")).match(shown);
    QVERIFY2(number.hasMatch(), qPrintable(shown));
    const double expected = std::tan(20.0 * M_PI / 180.0) / std::tan(30.0 * M_PI / 180.0);
    QVERIFY2(std::abs(number.captured(1).toDouble() / expected - 1.0) < 0.01, qPrintable(shown));
    QVERIFY(log.contains(QStringLiteral("Factor of safety ") + number.captured(1)));
    QVERIFY(window.statusBar()->findChild<QLabel*>(QStringLiteral("factorOfSafety"))->isVisible());

    // The SSR graph: the trials that stood joined against the factor, those that did not apart.
    gui::HistoryPlot* plot = window.historyPlot();
    QCOMPARE(plot->xColumn(), QStringLiteral("factor"));
    QCOMPARE(plot->yColumn(), QStringLiteral("max_displacement"));
    const int stood = plot->series()->count(), fell = plot->failedTrials()->count();
    QVERIFY2(stood >= 3 && fell >= 3, qPrintable(QStringLiteral("%1 stood, %2 fell").arg(stood).arg(fell)));
    for (int i = 1; i < stood; ++i) QVERIFY(plot->series()->at(i).x() > plot->series()->at(i - 1).x());
    for (const QPointF& p : plot->series()->points()) QVERIFY(p.x() < expected * 1.01);
    for (const QPointF& p : plot->failedTrials()->points()) QVERIFY(p.x() > expected * 0.99);
    QVERIFY(plot->chart()->title().contains(number.captured(1)));
    auto* view = plot->findChild<QChartView*>();
    QVERIFY(view != nullptr);
    const QImage chart = view->grab().toImage();
    keep(chart, QStringLiteral("ssr_graph"));
    QVERIFY2(count_colour(chart, plot->failedTrials()->color()) > 100,
             "the trials that did not stand are drawn as red squares");
    QVERIFY2(count_colour(chart, plot->series()->color()) > 100, "the curve of the trials that stood is drawn");

    // The picture: the last saved step (the first factor that did not stand) coloured by the
    // displacement increment (only the joint slides: the rock is elastic); the wedge above the
    // joint moved, the ground below did not.
    QCOMPARE(window.resultField(), QStringLiteral("displacement_increment"));
    QVERIFY(!window.shownStep().isEmpty());
    QVERIFY2(window.modelView()->resultInfo().title.find("strengths divided by 0.63") != std::string::npos,
             window.modelView()->resultInfo().title.c_str());
    const QImage frame = window.modelView()->grabFrame();
    keep(frame, QStringLiteral("mechanism"));
    const QColor wedge_colour = frame.pixelColor(guitest::pixel_of(*window.modelView(), 22.0, 11.0));
    const QColor ground_colour = frame.pixelColor(guitest::pixel_of(*window.modelView(), 30.0, 2.0));
    QVERIFY2(wedge_colour.red() > 150 && wedge_colour.blue() < 120, qPrintable(wedge_colour.name()));
    QVERIFY2(ground_colour.blue() > 150 && ground_colour.red() < 120, qPrintable(ground_colour.name()));
}

QTEST_MAIN(SafetyRunTest)
#include "SafetyRunTest.moc"
