#pragma once
/// \file WindowStatusBar.hpp
/// The main window's status bar: messages on the left; on the right the factor of safety of a
/// strength reduction, a progress bar (runs and file loads), the mesh figures, and the cursor
/// position with the result value under it.

#include <QStatusBar>

class QLabel;
class QPointF;
class QProgressBar;

namespace mcdda::gui {

class WindowStatusBar : public QStatusBar {
    Q_OBJECT

public:
    explicit WindowStatusBar(QWidget* parent = nullptr);

    /// Shows the cursor at `model_pos` with as many decimals as a pixel of `metres_per_pixel`
    /// resolves, followed by `value` (the result under it; may be empty).
    void showCursor(const QPointF& model_pos, double metres_per_pixel, const QString& value);
    void clearCursor();
    QString cursorText() const;
    void setStatistics(const QString& text);
    QString statistics() const;
    /// A progress bar of `maximum` steps (0 = busy without a fraction); hideProgress() ends it.
    void showProgress(int maximum);
    void setProgress(int value);
    void hideProgress();
    /// Work without a fraction (reading a file): a busy cursor and bar and `message`, until
    /// hideBusy().
    void showBusy(const QString& message);
    void hideBusy();
    /// The factor of safety of the last strength reduction, large and bold beside the
    /// progress bar; an empty text hides it (another run, another model).
    void setFactorOfSafety(const QString& text, const QString& tooltip = {});
    QString factorOfSafety() const;

private:
    QLabel* cursor_ = nullptr;
    QLabel* statistics_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* factor_ = nullptr;
};

}  // namespace mcdda::gui
