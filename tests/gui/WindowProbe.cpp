#include "WindowProbe.hpp"

#include "document/ModelDocument.hpp"

#include <QAction>
#include <QImage>
#include <QtTest>

#include <cmath>

namespace mcdda::guitest {

QPoint pixel_of(const gui::ModelView& view, double x, double y) { return view.toWidget(QPointF(x, y)).toPoint(); }

bool near(QColor c, const view::Rgb& rgb, double tolerance)
{
    return std::abs(c.redF() - rgb[0]) < tolerance && std::abs(c.greenF() - rgb[1]) < tolerance &&
           std::abs(c.blueF() - rgb[2]) < tolerance;
}

int count_around(gui::ModelView& view, double x, double y, const view::Rgb& colour, int half)
{
    const QImage frame = view.grabFrame();
    const QPointF centre = view.toWidget(QPointF(x, y)) * view.devicePixelRatioF();
    int n = 0;
    for (int dy = -half; dy <= half; ++dy)
        for (int dx = -half; dx <= half; ++dx) {
            const QPoint p(qRound(centre.x()) + dx, qRound(centre.y()) + dy);
            if (frame.rect().contains(p) && near(frame.pixelColor(p), colour)) ++n;
        }
    return n;
}

bool show_square(gui::MainWindow& window)
{
    window.setAskToSave(false);
    window.resize(1100, 750);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return false;
    window.findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    gui::ModelDocument* doc = window.document();
    doc->addRegion({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, 0);
    Roller base;
    base.name = "base";
    base.from = {0, 0};
    base.to = {10, 0};
    base.fix_x = base.fix_y = true;
    doc->addRoller(base);
    return true;
}

bool show_new_model(gui::MainWindow& window, int width, int height)
{
    window.resize(width, height);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return false;
    window.findChild<QAction*>(QStringLiteral("newAction"))->trigger();
    return true;
}

std::unique_ptr<gui::MainWindow> square_window()
{
    auto window = std::make_unique<gui::MainWindow>();
    return show_square(*window) ? std::move(window) : nullptr;
}

bool show_model(gui::MainWindow& window, const QString& path)
{
    window.resize(1100, 750);
    window.show();
    return QTest::qWaitForWindowExposed(&window) && window.openModel(path);
}

bool settled(const gui::MainWindow& window)
{
    return !window.isPreprocessing() && window.modelView()->scene() && window.modelView()->scene()->ok;
}

}  // namespace mcdda::guitest
