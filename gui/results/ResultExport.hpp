#pragma once
/// \file ResultExport.hpp
/// Writing results out of the desktop program: a picture as PNG, a run's saved steps (.pvd and
/// its .vtu files) and its history. Files are written atomically (a temporary file renamed into
/// place). On failure they return false and say why in `error`.

#include <QImage>
#include <QString>

namespace mcdda::gui {

/// Saves `image` as a PNG at `path`.
bool export_png(const QImage& image, const QString& path, QString& error);

/// Copies the collection `pvd_path` and the .vtu files it lists into the folder `target`
/// (created when missing). Returns the number of files copied through `copied`.
bool export_steps(const QString& pvd_path, const QString& target, QString& error, int* copied = nullptr);

/// Copies the file `source` (e.g. history.csv) to `target`.
bool export_file(const QString& source, const QString& target, QString& error);

}  // namespace mcdda::gui
