// The Qt 6 view of a model on a (virtual) X server: the frame is read back and its pixels are
// checked, before and after zooming and panning; the main window shows figures and messages.

#include "Language.hpp"
#include "MainWindow.hpp"
#include "TunnelModel.hpp"
#include "view/Palette.hpp"
#include "view/SceneLegend.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QGuiApplication>
#include <QIcon>
#include <QLabel>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPixmap>
#include <QScreen>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QTimer>
#include <QtTest>

#include <cmath>
#include <functional>
#include <memory>

using namespace mcdda;
using namespace mcdda::guitest;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;

namespace {

QColor to_qcolor(const view::Rgb& c) { return QColor::fromRgbF(float(c[0]), float(c[1]), float(c[2])); }

bool near(QColor a, QColor b, int tolerance = 6)
{
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

const QColor background = to_qcolor(view::palette::background);
const QColor rock = to_qcolor(view::material_color(0));

int count_pixels(const QImage& image, const std::function<bool(QColor)>& test)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (test(image.pixelColor(x, y))) ++n;
    return n;
}

/// Pixels of `color` in the 7×7 window around `at` (widget = image coordinates at ratio 1).
int count_around(const QImage& image, QPointF at, QColor color)
{
    int n = 0;
    const int cx = qRound(at.x()), cy = qRound(at.y());
    for (int y = cy - 3; y <= cy + 3; ++y)
        for (int x = cx - 3; x <= cx + 3; ++x)
            if (image.valid(x, y) && near(image.pixelColor(x, y), color)) ++n;
    return n;
}

/// Keeps a frame in the build folder (tests/gui/view_<name>.png) for a look by eye.
void keep(const QImage& image, const QString& name)
{
    image.save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/view_") + name + QStringLiteral(".png"));
}

QPointF widget_pos(const ModelView& view, Point2 q) { return view.toWidget(QPointF(q.x, q.y)); }

std::shared_ptr<const Preprocessed> meshed_tunnel()
{
    static const auto p = std::make_shared<const Preprocessed>(preprocess_model(tunnel_model()));
    return p;
}

void send_wheel(QWidget* w, QPointF pos, int notches)
{
    QWheelEvent wheel(pos, w->mapToGlobal(pos), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &wheel);
}

void send_drag(QWidget* w, QPointF from, QPointF to, Qt::MouseButton button)
{
    QMouseEvent press(QEvent::MouseButtonPress, from, w->mapToGlobal(from), button, button, Qt::NoModifier);
    QApplication::sendEvent(w, &press);
    const QPointF mid = (from + to) / 2;
    QMouseEvent move1(QEvent::MouseMove, mid, w->mapToGlobal(mid), Qt::NoButton, button, Qt::NoModifier);
    QApplication::sendEvent(w, &move1);
    QMouseEvent move2(QEvent::MouseMove, to, w->mapToGlobal(to), Qt::NoButton, button, Qt::NoModifier);
    QApplication::sendEvent(w, &move2);
    QMouseEvent release(QEvent::MouseButtonRelease, to, w->mapToGlobal(to), button, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(w, &release);
}

QAction* find_action(QWidget* window, const QString& text)
{
    for (QAction* a : window->findChildren<QAction*>())
        if (a->text() == text) return a;
    return nullptr;
}

}  // namespace

class ModelViewTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void showsModelColours();
    void wheelZoomsAboutTheCursor();
    void dragPans();
    void screenGrabMatchesReadBack();
    void emptyViewShowsBackground();
    void mainWindowShowsFiguresAndToggles();
    void mainWindowReportsBadFile();
    void mainWindowOpensExample();
    void resourcesHoldTheIcon();
    void legendSpeaksTheWindowLanguage();
    void jointSetTracesStopAtTheOpening();
};

void ModelViewTest::initTestCase()
{
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
    QVERIFY2(meshed_tunnel()->ok, "the test model should pre-process");
}

void ModelViewTest::showsModelColours()
{
    ModelView view;
    view.resize(640, 480);
    view.setScene(meshed_tunnel());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));

    const QImage frame = view.grabFrame();
    keep(frame, QStringLiteral("fitted"));
    QCOMPARE(frame.size(), QSize(640, 480) * view.devicePixelRatio());
    for (QPoint corner : {QPoint(1, 1), QPoint(638, 1), QPoint(1, 478), QPoint(638, 478)})
        QVERIFY2(near(frame.pixelColor(corner), background), qPrintable(frame.pixelColor(corner).name()));
    for (const Point2& q : rock_samples())
        QVERIFY2(count_around(frame, widget_pos(view, q), rock) >= 20,
                 qPrintable(QStringLiteral("rock colour expected at (%1, %2)").arg(q.x).arg(q.y)));
    for (const Point2& q : opening_samples())
        QVERIFY2(count_around(frame, widget_pos(view, q), background) >= 45, "background expected in the opening");
    // The model is fitted: its 10 m square spans most of the height.
    const double square_px = widget_pos(view, {0, 0}).y() - widget_pos(view, {0, 10}).y();
    QVERIFY2(square_px > 0.6 * 480 && square_px < 480, qPrintable(QString::number(square_px)));

    // Resizing a view nobody navigated in keeps the model fitted.
    view.resize(900, 560);
    QTRY_COMPARE(view.size(), QSize(900, 560));
    const QImage larger = view.grabFrame();
    QCOMPARE(larger.size(), QSize(900, 560) * view.devicePixelRatio());
    const double larger_px = widget_pos(view, {0, 0}).y() - widget_pos(view, {0, 10}).y();
    QVERIFY2(larger_px > 0.6 * 560 && larger_px < 560, qPrintable(QString::number(larger_px)));
    for (const Point2& q : rock_samples()) QVERIFY(count_around(larger, widget_pos(view, q), rock) >= 20);
    QVERIFY(near(larger.pixelColor(898, 558), background));
}

void ModelViewTest::wheelZoomsAboutTheCursor()
{
    ModelView view;
    view.resize(640, 480);
    view.setScene(meshed_tunnel());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QImage before = view.grabFrame();
    const int rock_before = count_pixels(before, [](QColor c) { return near(c, rock); });

    const QPointF cursor = widget_pos(view, {2.0, 5.0});
    const QPointF model_under_cursor = view.toModel(cursor);
    const double scale_before = view.metresPerPixel();
    send_wheel(&view, cursor, 3);
    QVERIFY(view.metresPerPixel() < scale_before / 1.5);
    const QPointF after_zoom = view.toModel(cursor);
    QVERIFY(std::abs(after_zoom.x() - model_under_cursor.x()) < 1e-9);
    QVERIFY(std::abs(after_zoom.y() - model_under_cursor.y()) < 1e-9);

    const QImage after = view.grabFrame();
    keep(after, QStringLiteral("zoomed"));
    const int rock_after = count_pixels(after, [](QColor c) { return near(c, rock); });
    QVERIFY2(rock_after > rock_before * 1.2,
             qPrintable(QStringLiteral("rock pixels %1 -> %2").arg(rock_before).arg(rock_after)));
    QVERIFY(count_around(after, cursor, rock) >= 20);  // still rock under the cursor

    // Zooming out again returns to the same scale.
    send_wheel(&view, cursor, -3);
    QVERIFY(std::abs(view.metresPerPixel() / scale_before - 1.0) < 1e-9);
}

void ModelViewTest::dragPans()
{
    ModelView view;
    view.resize(640, 480);
    view.setScene(meshed_tunnel());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QImage before = view.grabFrame();

    const Point2 in_opening = opening_samples().front();  // the hole's centre is on the joint
    const QPointF hole_before = widget_pos(view, in_opening);
    QVERIFY(count_around(before, hole_before, background) >= 45);
    const double radius_px = hole_radius / view.metresPerPixel();
    const QPointF shift(1.6 * radius_px, -0.3 * radius_px);
    send_drag(&view, QPointF(300, 240), QPointF(300, 240) + shift, Qt::LeftButton);

    const QPointF hole_after = widget_pos(view, in_opening);
    QVERIFY(std::abs(hole_after.x() - (hole_before.x() + shift.x())) < 1e-6);
    QVERIFY(std::abs(hole_after.y() - (hole_before.y() + shift.y())) < 1e-6);
    const QImage after = view.grabFrame();
    keep(after, QStringLiteral("panned"));
    QVERIFY2(count_around(after, hole_after, background) >= 45, "the opening moved with the drag");
    QVERIFY2(count_around(after, hole_before, rock) >= 15, "rock now where the opening was");

    int changed = 0;
    for (int y = 0; y < before.height(); y += 2)
        for (int x = 0; x < before.width(); x += 2)
            if (!near(before.pixelColor(x, y), after.pixelColor(x, y))) ++changed;
    QVERIFY2(changed > before.width() * before.height() / 4 / 20, qPrintable(QString::number(changed)));

    // The middle button pans too.
    send_drag(&view, QPointF(300, 240), QPointF(250, 240), Qt::MiddleButton);
    QVERIFY(std::abs(widget_pos(view, in_opening).x() - (hole_after.x() - 50)) < 1e-6);
}

void ModelViewTest::screenGrabMatchesReadBack()
{
    // What is on the X screen, not only what VTK reads back from its own buffers.
    ModelView view;
    view.resize(640, 480);
    view.setScene(meshed_tunnel());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.grabFrame();  // renders and swaps buffers
    QApplication::processEvents();

    QScreen* screen = QGuiApplication::primaryScreen();
    QVERIFY(screen != nullptr);
    const QImage shot = screen->grabWindow(view.winId()).toImage();
    keep(shot, QStringLiteral("screen"));
    QCOMPARE(shot.size(), QSize(640, 480));
    for (const Point2& q : rock_samples())
        QVERIFY2(count_around(shot, widget_pos(view, q), rock) >= 20, "rock colour on screen");
    for (const Point2& q : opening_samples())
        QVERIFY2(count_around(shot, widget_pos(view, q), background) >= 45, "background on screen");
    QVERIFY(near(shot.pixelColor(1, 1), background));
}

void ModelViewTest::emptyViewShowsBackground()
{
    ModelView view;
    view.resize(320, 240);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QImage frame = view.grabFrame();
    QCOMPARE(count_pixels(frame, [](QColor c) { return near(c, background); }), frame.width() * frame.height());
    view.fitView();  // nothing to fit: no crash
    send_wheel(&view, QPointF(100, 100), 2);
    send_drag(&view, QPointF(100, 100), QPointF(150, 120), Qt::LeftButton);
    frame = view.grabFrame();
    QCOMPARE(count_pixels(frame, [](QColor c) { return near(c, background); }), frame.width() * frame.height());

    // An empty pre-processing result (e.g. an unreadable file) is an empty picture too.
    view.setScene(Preprocessed{});
    frame = view.grabFrame();
    QCOMPARE(count_pixels(frame, [](QColor c) { return near(c, background); }), frame.width() * frame.height());
}

void ModelViewTest::mainWindowShowsFiguresAndToggles()
{
    MainWindow window;
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const auto p = meshed_tunnel();
    window.showPreprocessed(p, QStringLiteral("tunnel (built in code)"));
    QVERIFY(window.statisticsText().contains(QString::number(p->statistics.elements)));
    QVERIFY(window.messages().contains(QStringLiteral("tunnel (built in code)")));
    QVERIFY(window.windowTitle().contains(QStringLiteral("Test tunnel")));

    ModelView* view = window.modelView();
    const QImage with_mesh = view->grabFrame();
    for (const Point2& q : rock_samples()) QVERIFY(count_around(with_mesh, widget_pos(*view, q), rock) >= 20);
    auto dark = [](QColor c) { return c.red() < 110 && c.green() < 110 && c.blue() < 110; };
    const int dark_with_mesh = count_pixels(with_mesh, dark);

    QAction* mesh = find_action(&window, MainWindow::tr("&Mesh"));
    QVERIFY(mesh != nullptr);
    mesh->trigger();  // off
    QVERIFY(!view->sceneOptions().show_mesh);
    const QImage without_mesh = view->grabFrame();
    QVERIFY2(count_pixels(without_mesh, dark) * 2 < dark_with_mesh, "hiding the mesh removes most dark pixels");

    QAction* joints = find_action(&window, MainWindow::tr("&Joints"));
    QVERIFY(joints != nullptr);
    // Joint red, not the orange of pressures (g ≈ 84) or the purple of point loads.
    auto red = [](QColor c) { return c.red() > 170 && c.green() < 60 && c.blue() < 60; };
    QVERIFY(count_pixels(without_mesh, red) > 200);
    joints->trigger();  // off
    QCOMPARE(count_pixels(view->grabFrame(), red), 0);

    // Cursor position in model units in the status bar.
    const QPointF at = widget_pos(*view, {2.5, 7.5});
    QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(view, &move);
    bool found = false;
    for (QLabel* label : window.findChildren<QLabel*>())
        if (label->text().contains(QStringLiteral("x = 2.5")) && label->text().contains(QStringLiteral("y = 7.5")))
            found = true;
    QVERIFY2(found, "cursor coordinates in the status bar");
}

void ModelViewTest::mainWindowReportsBadFile()
{
    MainWindow window;
    window.resize(800, 600);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const QString missing = folder.filePath(QStringLiteral("missing.json"));
    QVERIFY(!window.openModel(missing));
    QVERIFY(window.messages().contains(QStringLiteral("error")));
    QVERIFY(window.statisticsText().contains(QStringLiteral("error")));

    const QString broken = folder.filePath(QStringLiteral("broken.json"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ \"format\": ");
    file.close();
    QVERIFY(!window.openModel(broken));
    QVERIFY(window.messages().contains(QStringLiteral("error")));

    // The failure is also shown in a message box that does not block.
    QMessageBox* box = nullptr;
    QTRY_VERIFY((box = window.findChild<QMessageBox*>()) != nullptr);
    QCOMPARE(box->icon(), QMessageBox::Critical);
    const QImage frame = window.modelView()->grabFrame();  // the view is still usable
    QVERIFY(!frame.isNull());
    for (QMessageBox* b : window.findChildren<QMessageBox*>()) b->close();
}

void ModelViewTest::mainWindowOpensExample()
{
    const QString path = QStringLiteral(MCDDA_EXAMPLES_DIR "/jointed-tunnel.json");
    if (!QFile::exists(path)) QSKIP("examples/jointed-tunnel.json is not there yet");
    MainWindow window;
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // The file is read and meshed off the GUI thread: timers (and painting) go on meanwhile,
    // and a second file is refused until the first is shown.
    bool loading_seen = false, second_refused = false;
    QTimer::singleShot(0, &window, [&] {
        loading_seen = window.isLoading();
        second_refused = loading_seen && !window.openModel(path);
    });
    QVERIFY2(window.openModel(path), qPrintable(window.messages()));
    QVERIFY(loading_seen);
    QVERIFY(second_refused);
    QVERIFY(!window.isLoading());
    QCOMPARE(window.modelPath(), path);
    const QImage frame = window.modelView()->grabFrame();
    QTest::qWait(50);  // let the dock and status bar repaint for the screenshot
    keep(QGuiApplication::primaryScreen()->grabWindow(window.winId()).toImage(), QStringLiteral("main_window"));
    const int coloured = count_pixels(frame, [](QColor c) { return !near(c, background, 10); });
    QVERIFY2(coloured > frame.width() * frame.height() / 10, "the example model covers the view");

    // Reload keeps the view where the user put it.
    ModelView* view = window.modelView();
    send_wheel(view, QPointF(view->width() / 2.0, view->height() / 2.0), 2);
    const double scale = view->metresPerPixel();
    const QPointF centre = view->toModel(QPointF(100, 100));
    window.reload();
    QCOMPARE(view->metresPerPixel(), scale);
    QCOMPARE(view->toModel(QPointF(100, 100)), centre);
    QVERIFY(view->scene() && view->scene()->ok);
}

void ModelViewTest::resourcesHoldTheIcon()
{
    QVERIFY(QFile::exists(QStringLiteral(":/icons/mcdda.svg")));
    const QImage icon = QIcon(QStringLiteral(":/icons/mcdda.svg")).pixmap(128, 128).toImage();
    QVERIFY(!icon.isNull());
    keep(icon, QStringLiteral("icon"));
    auto joint_red = [](QColor c) { return c.red() > 170 && c.green() < 60 && c.blue() < 60; };
    QVERIFY(count_pixels(icon, joint_red) > 100);  // the SVG was really drawn
}

// The legend is drawn by VTK, but its texts come from the Qt translations once a view exists.
void ModelViewTest::legendSpeaksTheWindowLanguage()
{
    Preprocessed p = preprocess_model(guitest::tunnel_model(), PreprocessStage::Cut);
    QVERIFY(p.ok);
    auto labels = [&p] {
        QStringList out;
        for (const view::LegendEntry& e : view::legend_entries(p, view::SceneOptions{}))
            out << QString::fromStdString(e.label);
        return out;
    };
    ModelView view;  // installs the translator
    QVERIFY2(labels().contains(QStringLiteral("Joint")), qPrintable(labels().join(QLatin1Char('|'))));
    {
        QObject owner;  // the translators go with it
        QVERIFY(i18n::install_translations(QLocale(QStringLiteral("de")), &owner).mcdda);
        const QStringList german = labels();
        QVERIFY2(german.contains(QStringLiteral("Kluft")) && german.contains(QStringLiteral("Festpunkt")),
                 qPrintable(german.join(QLatin1Char('|'))));
    }
    QVERIFY(labels().contains(QStringLiteral("Joint")));
}

// A joint set's traces are drawn where they cut rock, not across the tunnel
// opening or empty space (an explicit joint's stray parts still are, lightly).
void ModelViewTest::jointSetTracesStopAtTheOpening()
{
    Model m = guitest::tunnel_model();
    m.joints.clear();
    JointSet set;
    set.name = "horizontal";
    set.angle = 0.0;
    set.spacing = 3.0;
    set.origin = {0.0, hole_centre.y};  // one trace through the opening's centre
    m.joint_sets.push_back(set);
    const auto p = std::make_shared<const Preprocessed>(preprocess_model(m, PreprocessStage::Mesh));
    QVERIFY2(p->ok, p->diagnostics.empty() ? "" : p->diagnostics.front().message.c_str());
    ModelView view;
    view.resize(640, 480);
    view::SceneOptions options = view.sceneOptions();
    options.show_mesh = false;
    view.setSceneOptions(options);
    view.setScene(p);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QImage frame = view.grabFrame();
    keep(frame, QStringLiteral("joint_set_opening"));
    const QColor joint = to_qcolor(view::palette::joint);
    const QColor stray = to_qcolor(view::palette::joint_outside);
    QVERIFY(count_around(frame, widget_pos(view, {1.5, hole_centre.y}), joint) > 0);  // in rock
    QVERIFY(count_around(frame, widget_pos(view, {8.5, hole_centre.y}), joint) > 0);
    for (const Point2& q : {hole_centre, Point2{hole_centre.x - 1.0, hole_centre.y}, Point2{hole_centre.x + 1.0, hole_centre.y}}) {
        QCOMPARE(count_around(frame, widget_pos(view, q), joint), 0);
        QCOMPARE(count_around(frame, widget_pos(view, q), stray), 0);
    }
}

QTEST_MAIN(ModelViewTest)
#include "ModelViewTest.moc"
