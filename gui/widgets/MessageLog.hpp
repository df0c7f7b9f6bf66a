#pragma once
/// \file MessageLog.hpp
/// The Messages dock's text: what pre-processing found and the run's log, in a fixed-width
/// font, ten lines high, following the newest line.

#include <QPlainTextEdit>

namespace mcdda::gui {

class MessageLog : public QPlainTextEdit {
    Q_OBJECT

public:
    explicit MessageLog(QWidget* parent = nullptr);

    /// Adds `line` and scrolls to it, even when the user scrolled up earlier.
    void log(const QString& line);
    /// The height of ten lines (pixels), for the dock.
    int preferredHeight() const;
};

}  // namespace mcdda::gui
