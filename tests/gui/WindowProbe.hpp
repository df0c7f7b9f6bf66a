#pragma once
// Helpers shared by the tests that drive the main window: where a model point lands on the
// screen, what colour the picture has around it, and a small ready model.

#include "MainWindow.hpp"
#include "view/Palette.hpp"
#include "widgets/ModelView.hpp"

#include <QColor>
#include <QPoint>
#include <QString>

#include <memory>

namespace mcdda::guitest {

/// The widget pixel (logical) under the model point (x, y).
QPoint pixel_of(const gui::ModelView& view, double x, double y);

/// Whether `c` is `rgb` within `tolerance` per channel (0–1).
bool near(QColor c, const view::Rgb& rgb, double tolerance = 0.06);

/// Pixels of `colour` in the (2·half + 1)² device pixels around the model point (x, y) of a
/// freshly rendered frame.
int count_around(gui::ModelView& view, double x, double y, const view::Rgb& colour, int half = 4);

/// Shows `window` (1100 × 750) and makes it File ▸ New with a 10 m square region and a roller
/// holding its base (x and y); false when the window could not be shown.
bool show_square(gui::MainWindow& window);
/// Shows `window` at `width` × `height` and makes it File ▸ New (an empty model); false when the
/// window could not be shown.
bool show_new_model(gui::MainWindow& window, int width = 1000, int height = 700);
/// Shows `window` at 1100 × 750 with the model file at `path` open; false when it cannot.
bool show_model(gui::MainWindow& window, const QString& path);

/// The same in a window of its own; null when it could not be shown.
std::unique_ptr<gui::MainWindow> square_window();

/// Pre-processing is done and its model is usable.
bool settled(const gui::MainWindow& window);

}  // namespace mcdda::guitest
