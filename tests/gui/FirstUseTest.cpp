// What a new user met in the desktop window, each checked on screen (a virtual X server): the
// query line drawn on the picture and forgotten with the model, an automatic deformation scale
// that turns no element inside out, an untitled model's results in a named new folder, named
// tools whose options show alone and give way to Select for results, and the smaller things
// (no contact legend without contacts, plots that say why they are empty, a query's y axis that
// fits and names the plastic states, export dialogs that suggest a name). One short run of a
// drawn, never saved square is shared by the tests.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "document/ModelDocument.hpp"
#include "results/ChartWithMessage.hpp"
#include "results/ExportMenu.hpp"
#include "results/HistoryPlot.hpp"
#include "results/QueryPlot.hpp"
#include "results/UnbalancedPlot.hpp"
#include "session/RunController.hpp"
#include "session/RunSession.hpp"
#include "tools/EditingTools.hpp"
#include "view/SceneGeometry.hpp"
#include "widgets/ModelView.hpp"
#include "widgets/ResultToolBar.hpp"

#include <QAbstractAxis>
#include <QAbstractItemView>
#include <QAction>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QLineSeries>
#include <QSet>
#include <QSignalSpy>
#include <QToolBar>
#include <QToolButton>
#include <QValueAxis>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace mcdda;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;

namespace {

/// Pixels of clearly different colour between two frames at the model points (x0 + k·dx, y).
int differing_along(ModelView& view, const QImage& a, const QImage& b, double x0, double x1, double y, int* samples)
{
    int n = 0;
    *samples = 0;
    for (double x = x0; x <= x1 + 1e-9; x += 0.2) {
        const QPoint p = (view.toWidget(QPointF(x, y)) * view.devicePixelRatioF()).toPoint();
        if (!a.rect().contains(p)) continue;
        ++*samples;
        const QColor c = a.pixelColor(p), d = b.pixelColor(p);
        if (std::abs(c.red() - d.red()) + std::abs(c.green() - d.green()) + std::abs(c.blue() - d.blue()) > 60) ++n;
    }
    return n;
}

/// The labels of a value axis' ticks as the chart draws them (its label format on each tick).
QStringList tick_labels(const QValueAxis* axis)
{
    QStringList labels;
    const double step = axis->tickInterval();
    if (!(step > 0.0)) return {QString::asprintf(axis->labelFormat().toLatin1().constData(), axis->min())};
    const double first = axis->tickAnchor() + std::ceil((axis->min() - axis->tickAnchor()) / step - 1e-9) * step;
    for (double v = first; v <= axis->max() + 1e-9 * step; v += step)
        labels << QString::asprintf(axis->labelFormat().toLatin1().constData(), v);
    return labels;
}

/// The y axis the query curve is drawn against.
QAbstractAxis* query_y_axis(gui::QueryPlot* query)
{
    const auto series = query->chartView()->chart()->series();
    if (series.isEmpty()) return nullptr;
    for (QAbstractAxis* axis : series.first()->attachedAxes())
        if (axis->orientation() == Qt::Vertical) return axis;
    return nullptr;
}

}  // namespace

class FirstUseTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void plotsSayWhyTheyAreEmpty();
    void toolsAreNamedAndShowOnlyTheirOptions();
    void untitledRunGoesToANewFolderWithSelectActive();
    void contactLegendOnlyWithContacts();
    void queryLineIsDrawnOnThePicture();
    void queryAxesAreReadable();
    void exportSuggestsAName();
    void newModelForgetsTheQueryLine();
    void automaticScaleTurnsNoElementInsideOut();
    void fieldListDropsDownBelowTheBox();
    void cleanupTestCase();

private:
    std::unique_ptr<MainWindow> window_;
    QString results_;
};

void FirstUseTest::initTestCase()
{
    gui::register_run_types();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
    window_ = std::make_unique<MainWindow>();
    QVERIFY(guitest::show_square(*window_));  // drawn, never saved: untitled
    AnalysisSettings short_run = window_->document()->model().analysis;
    short_run.steps = 2;
    short_run.output_every = 1;
    window_->document()->setAnalysisSettings(short_run);
    QTRY_VERIFY_WITH_TIMEOUT(guitest::settled(*window_), 60000);
    QVERIFY(window_->document()->path().isEmpty());
}

// Before a run the history and unbalanced-force plots show a sentence, not bare axes whose
// ticks read "0 0 0 0 1".
void FirstUseTest::plotsSayWhyTheyAreEmpty()
{
    gui::HistoryPlot* plot = window_->historyPlot();
    QVERIFY(!plot->chartShown());
    QVERIFY2(plot->emptyMessage().contains(QStringLiteral("run the model")), qPrintable(plot->emptyMessage()));
    QVERIFY(!plot->unbalancedPlot()->chartShown());
    QVERIFY(!window_->queryPlot()->chartArea()->chartShown());
    QVERIFY(window_->queryPlot()->chartArea()->message().contains(QStringLiteral("Query Line")));
}

// The Tools bar names every tool under its icon (Fixed Point was taken for Roller), with a
// tooltip; Tool Options shows the active tool's options only.
void FirstUseTest::toolsAreNamedAndShowOnlyTheirOptions()
{
    auto* tools = window_->findChild<QToolBar*>(QStringLiteral("tools"));
    QVERIFY(tools);
    QVERIFY(tools->toolButtonStyle() == Qt::ToolButtonTextBesideIcon ||
            tools->toolButtonStyle() == Qt::ToolButtonTextUnderIcon);
    QStringList names;
    for (QAction* action : tools->actions()) {
        if (action->isSeparator()) continue;
        auto* button = qobject_cast<QToolButton*>(tools->widgetForAction(action));
        QVERIFY(button);
        QVERIFY2(!button->text().isEmpty(), qPrintable(action->objectName()));
        QVERIFY2(button->toolButtonStyle() != Qt::ToolButtonIconOnly, qPrintable(action->objectName()));
        QVERIFY2(!action->toolTip().isEmpty() && action->toolTip() != button->text(), qPrintable(action->objectName()));
        QVERIFY(button->isVisible());
        names << button->text();
    }
    QVERIFY(names.size() >= 12);
    QVERIFY(names.contains(QStringLiteral("Fixed Point")) && names.contains(QStringLiteral("Roller")));
    QCOMPARE(QSet<QString>(names.begin(), names.end()).size(), names.size());

    gui::EditingTools* editing = window_->editingTools();
    ModelView* view = window_->modelView();
    QTest::qWait(50);
    const QSize picture = view->size();
    auto* roller_box = window_->findChild<QComboBox*>(QStringLiteral("rollerFixBox"));
    QVERIFY(roller_box);
    QVERIFY2(editing->visibleToolOptions().isEmpty(), qPrintable(editing->visibleToolOptions().join(u',')));
    QVERIFY(!roller_box->isVisible());
    editing->useRoller();
    QCOMPARE(editing->visibleToolOptions(), (QStringList{QStringLiteral("rollerFixBox"), QStringLiteral("coordinateEdit")}));
    QTRY_VERIFY(roller_box->isVisible());
    editing->usePointLoad();
    const QStringList load = editing->visibleToolOptions();
    QVERIFY(load.contains(QStringLiteral("loadFxBox")) && load.contains(QStringLiteral("loadFyBox")));
    QVERIFY(!load.contains(QStringLiteral("rollerFixBox")) && !load.contains(QStringLiteral("pressureBox")));
    QTRY_VERIFY(!roller_box->isVisible());
    QTest::qWait(50);
    QCOMPARE(view->size(), picture);  // the picture does not jump when the options change
    editing->useSelect();
    QVERIFY(editing->visibleToolOptions().isEmpty());
    QTest::qWait(50);
    QCOMPARE(view->size(), picture);
}

// An untitled model runs into a new, named temporary folder, said in the log, not into the
// current folder; a drawing tool active at the start gives way to Select, so neither the grid
// nor the snap marker covers the result.
void FirstUseTest::untitledRunGoesToANewFolderWithSelectActive()
{
    ModelView* view = window_->modelView();
    window_->editingTools()->useRoller();
    QVERIFY(window_->activeTool());
    const QPoint where = guitest::pixel_of(*view, 5.25, 5.25);
    QTest::mouseMove(view, where);
    QTRY_VERIFY(view->snapMarker());
    QVERIFY(view->gridSpacing() > 0.0);

    QSignalSpy finished(window_.get(), &MainWindow::runFinished);
    QVERIFY(window_->startRun());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    results_ = window_->resultsFolder();
    QVERIFY2(QFileInfo(results_).isDir(), qPrintable(results_));
    QVERIFY2(QFileInfo(results_).absolutePath() == QFileInfo(QDir::tempPath()).absoluteFilePath(), qPrintable(results_));
    QVERIFY2(QFileInfo(results_).fileName().startsWith(QStringLiteral("mcdda-untitled-")), qPrintable(results_));
    QVERIFY(results_ != QDir::current().absoluteFilePath(QStringLiteral("model-results")));
    QVERIFY2(window_->messages().contains(QDir::toNativeSeparators(results_)) &&
                 window_->messages().contains(QStringLiteral("not saved")),
             qPrintable(window_->messages()));
    QVERIFY(!window_->shownStep().isEmpty());  // the last saved step is shown

    QVERIFY(window_->activeTool() == nullptr);  // Select
    QVERIFY(!view->snapMarker());
    QCOMPARE(view->gridSpacing(), 0.0);
    QVERIFY(window_->editingTools()->visibleToolOptions().isEmpty());
    QTest::mouseMove(view, where);  // Select shows no marker when the cursor moves either
    QVERIFY(!view->snapMarker());
    window_->setResultField(QStringLiteral("plastic_state"));  // greys here: no orange of a colour map
    QCOMPARE(guitest::count_around(*view, 5.25, 5.25, view::palette::snap_marker, 6), 0);
}

// The square has no joints: its plastic-state legend has no "contact force, largest (0 kN/m)".
void FirstUseTest::contactLegendOnlyWithContacts()
{
    // The run wrote contacts files (with no contact in them) and the step is drawn with them.
    QVERIFY(!QDir(results_).entryList({QStringLiteral("*contacts*")}, QDir::Files).isEmpty());
    window_->setResultField(QStringLiteral("plastic_state"));
    const view::ResultInfo& info = window_->modelView()->resultInfo();
    QVERIFY(info.legend.size() >= 4);  // the three states and the block boundary
    for (const std::string& row : info.legend)
        QVERIFY2(row.find("contact force") == std::string::npos, row.c_str());
}

// The query line is drawn on the picture while it is drawn and after (a dark line in a white
// halo with end markers), not only plotted.
void FirstUseTest::queryLineIsDrawnOnThePicture()
{
    ModelView* view = window_->modelView();
    window_->setResultField(QStringLiteral("displacement"));
    window_->editingTools()->useQueryLine();
    QVERIFY(!view->resultProbe().empty());
    QCOMPARE(view->gridSpacing(), 0.0);  // no grid over the result being queried
    const double y = 5.2;
    QTest::mouseMove(view, guitest::pixel_of(*view, 0.5, 9.5));
    const QImage without = view->grabFrame();
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, guitest::pixel_of(*view, 1.0, y));
    QTest::mouseMove(view, guitest::pixel_of(*view, 9.0, y));
    const QImage drawing = view->grabFrame();
    int samples = 0;
    const int while_drawing = differing_along(*view, without, drawing, 2.0, 8.0, y, &samples);
    QVERIFY(samples > 20);
    QVERIFY2(while_drawing >= samples * 8 / 10, qPrintable(QStringLiteral("%1 of %2").arg(while_drawing).arg(samples)));
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, guitest::pixel_of(*view, 9.0, y));
    QTRY_VERIFY(window_->queryPlot()->hasLine());
    QVERIFY(view->queryLineShown());
    QTest::mouseMove(view, guitest::pixel_of(*view, 0.5, 9.5));  // the marker away from the line
    const QImage with = view->grabFrame();
    const int after = differing_along(*view, without, with, 2.0, 8.0, y, &samples);
    QVERIFY2(after >= samples * 8 / 10, qPrintable(QStringLiteral("%1 of %2").arg(after).arg(samples)));
    // End markers: wider than the line at its ends.
    int marker = 0, line = 0;
    const QPointF end = view->toWidget(QPointF(9.0, y)) * view->devicePixelRatioF(),
                  mid = view->toWidget(QPointF(5.0, y)) * view->devicePixelRatioF();
    for (int dy = -5; dy <= 5; ++dy) {
        const QColor e = with.pixelColor(qRound(end.x()), qRound(end.y()) + dy);
        const QColor m = with.pixelColor(qRound(mid.x()), qRound(mid.y()) + dy);
        marker += e.value() < 60 ? 1 : 0;
        line += m.value() < 60 ? 1 : 0;
    }
    QVERIFY2(marker > line && line >= 1, qPrintable(QStringLiteral("marker %1, line %2").arg(marker).arg(line)));
    // The picture with the line, and the window, are kept for a look.
    with.save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/first_use_query_line.png"));
    window_->grab().toImage().save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/first_use_window.png"));
}

// The query's axes: ticks in %g style (never "0.00000000100"), also for a flat field; the y axis
// gives the units only, and its title fits (the field is named above the chart); the plastic
// state is plotted against its named states.
void FirstUseTest::queryAxesAreReadable()
{
    gui::QueryPlot* query = window_->queryPlot();
    window_->findChild<QDockWidget*>(QStringLiteral("query"))->raise();
    window_->setResultField(QStringLiteral("stress_1"));
    QTest::qWait(200);
    QVERIFY(query->chartArea()->chartShown());
    auto* y = qobject_cast<QValueAxis*>(query_y_axis(query));
    QVERIFY(y);
    QVERIFY2(query->heading().contains(QStringLiteral("principal stress 1")), qPrintable(query->heading()));
    const QChart* chart = query->chartView()->chart();
    const double room = chart->plotArea().height();
    const int title = QFontMetrics(y->titleFont()).horizontalAdvance(y->titleText());
    QVERIFY2(room > 20 && title < room, qPrintable(QStringLiteral("%1 in %2: %3").arg(title).arg(room).arg(y->titleText())));
    for (const auto* axis : {y, qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).first())})
        for (const QString& label : tick_labels(axis))
            QVERIFY2(!label.isEmpty() && label.size() <= 9 && !label.contains(QStringLiteral("0000")), qPrintable(label));

    window_->setResultField(QStringLiteral("plastic_strain"));  // elastic: 0 all along
    y = qobject_cast<QValueAxis*>(query_y_axis(query));
    QVERIFY(y);
    QVERIFY2(y->min() < 0.0 && y->max() > 0.0 && y->max() - y->min() >= 0.1,
             qPrintable(QStringLiteral("%1 .. %2").arg(y->min()).arg(y->max())));
    const QStringList flat = tick_labels(y);
    QVERIFY(flat.contains(QStringLiteral("0")));
    for (const QString& label : flat) QVERIFY2(label.size() <= 6, qPrintable(flat.join(u' ')));

    window_->setResultField(QStringLiteral("plastic_state"));
    auto* states = qobject_cast<QCategoryAxis*>(query_y_axis(query));
    QVERIFY(states);
    QCOMPARE(states->categoriesLabels(),
             (QStringList{QStringLiteral("elastic"), QStringLiteral("yielded before"), QStringLiteral("yielding now")}));
    QVERIFY(states->isVisible());
    window_->setResultField(QStringLiteral("displacement"));
}

// File ▸ Export suggests a file name from the model and what is shown.
void FirstUseTest::exportSuggestsAName()
{
    const QFileInfo picture(window_->exportMenu()->suggestedPicturePath());
    QVERIFY2(picture.fileName().startsWith(window_->modelStem() + QLatin1Char('-')) &&
                 picture.fileName().contains(QStringLiteral("displacement")) &&
                 picture.fileName().contains(QStringLiteral("step")) && picture.suffix() == QLatin1String("png"),
             qPrintable(picture.filePath()));
    QCOMPARE(picture.absolutePath(), QFileInfo(results_).absoluteFilePath());
    QVERIFY(QFileInfo(window_->exportMenu()->suggestedHistoryPath()).fileName().endsWith(QStringLiteral("history.csv")));
    QVERIFY2(window_->queryPlot()->suggestedFileName().contains(QStringLiteral("query")) &&
                 window_->queryPlot()->suggestedFileName().endsWith(QStringLiteral(".csv")),
             qPrintable(window_->queryPlot()->suggestedFileName()));
}

// File ▸ New: the query line and its plot are gone, and nothing is re-plotted on the new model.
void FirstUseTest::newModelForgetsTheQueryLine()
{
    gui::QueryPlot* query = window_->queryPlot();
    QVERIFY(query->hasLine());
    QVERIFY(window_->modelView()->queryLine());
    window_->findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    QVERIFY(!query->hasLine());
    QVERIFY(query->samples().empty());
    QVERIFY(query->chartView()->chart()->series().isEmpty());
    QVERIFY(!query->chartArea()->chartShown());
    QVERIFY(!window_->modelView()->queryLine());
    QVERIFY(!window_->modelView()->queryLineShown());
    QVERIFY(query->heading().isEmpty());
    // A new model's first run does not go to the untitled model's folder before.
    QVERIFY(window_->runSession()->outputFolder().isEmpty());
}

// A displacement that moves one corner of the flattest element towards its opposite side: the
// old rule (largest displacement drawn as 5 % of the model) turns elements inside out; auto
// now stays below that.
void FirstUseTest::automaticScaleTurnsNoElementInsideOut()
{
    MainWindow window;
    QVERIFY(guitest::show_square(window));
    QTRY_VERIFY_WITH_TIMEOUT(guitest::settled(window), 60000);
    const auto scene = window.modelView()->scene();
    const Mesh& mesh = scene->mesh;
    QVERIFY(mesh.triangles.size() > 50);
    // The corner with the smallest height over its opposite side.
    double lowest = 1e300;
    int corner = -1;
    Point2 towards;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Point2 c = mesh.nodes[t[k]], a = mesh.nodes[t[(k + 1) % 3]], b = mesh.nodes[t[(k + 2) % 3]];
            const double ex = b.x - a.x, ey = b.y - a.y, len = std::hypot(ex, ey);
            const double h = std::abs(ex * (c.y - a.y) - ey * (c.x - a.x)) / len;
            if (h < lowest) {
                lowest = h;
                corner = t[k];
                const double s = ((c.x - a.x) * ex + (c.y - a.y) * ey) / (len * len);
                towards = {a.x + s * ex - c.x, a.y + s * ey - c.y};  // to the foot of the height
            }
        }
    QVERIFY(corner >= 0 && lowest > 0.0);
    auto snapshot = std::make_shared<ResultSnapshot>();
    snapshot->step = 1;
    snapshot->total_steps = 1;
    snapshot->displacement.assign(2 * mesh.nodes.size(), 0.0);
    const double n = std::hypot(towards.x, towards.y);
    snapshot->displacement[2 * corner] = 0.01 * towards.x / n;  // 1 cm, nothing else moves
    snapshot->displacement[2 * corner + 1] = 0.01 * towards.y / n;
    snapshot->stress.assign(mesh.triangles.size(), {0.0, 0.0, 0.0, 0.0});
    snapshot->plastic_strain.assign(mesh.triangles.size(), 0.0);
    snapshot->plastic_state.assign(mesh.triangles.size(), 0);

    ModelView* view = window.modelView();
    view::ResultOptions options;
    options.field = "displacement";
    // The old automatic scale: the largest displacement drawn as 5 % of the model's size.
    options.deform = 0.05 * view::model_box(*scene).size() / 0.01;
    QVERIFY(view->setResult(snapshot, options));
    QVERIFY2(view->resultInfo().inverted_elements > 0,
             qPrintable(QStringLiteral("height %1, factor %2").arg(lowest).arg(options.deform)));
    options.deform = 0.0;
    options.deform_auto = true;
    QVERIFY(view->setResult(snapshot, options));
    const view::ResultInfo& info = view->resultInfo();
    QCOMPARE(info.inverted_elements, 0);
    QVERIFY(info.deform_factor > 0.0);
    QVERIFY2(info.deform_factor * 0.01 < lowest, qPrintable(QString::number(info.deform_factor)));
    // The toolbar shows the factor and no warning.
    auto* bar = window.findChild<gui::ResultToolBar*>();
    QVERIFY(bar);
    bar->showInfo(info);
    QVERIFY2(!bar->infoText().contains(QStringLiteral("inside out")), qPrintable(bar->infoText()));
}

void FirstUseTest::cleanupTestCase()
{
    if (window_) window_->close();
    window_.reset();
    if (!results_.isEmpty() && QFileInfo(results_).fileName().startsWith(QStringLiteral("mcdda-untitled-")))
        QDir(results_).removeRecursively();
}


// The result field list opens below its box whichever field is chosen (it opened with the
// chosen field under the pointer, the list reaching far above the toolbar).
void FirstUseTest::fieldListDropsDownBelowTheBox()
{
    MainWindow window;
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* fields = window.findChild<QComboBox*>(QStringLiteral("fieldBox"));
    QVERIFY(fields);
    fields->setEnabled(true);
    fields->setCurrentIndex(fields->count() - 1);
    fields->showPopup();
    QWidget* popup = fields->view()->window();
    QTRY_VERIFY(popup->isVisible());
    const int box_bottom = fields->mapToGlobal(QPoint(0, fields->height())).y();
    QVERIFY2(popup->geometry().top() >= box_bottom - 2,
             qPrintable(QStringLiteral("list top %1, box bottom %2").arg(popup->geometry().top()).arg(box_bottom)));
    fields->hidePopup();
}

QTEST_MAIN(FirstUseTest)
#include "FirstUseTest.moc"
