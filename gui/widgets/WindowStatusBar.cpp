#include "widgets/WindowStatusBar.hpp"

#include <QApplication>
#include <QFont>
#include <QLabel>
#include <QLocale>
#include <QPointF>
#include <QProgressBar>

#include <algorithm>
#include <cmath>

namespace mcdda::gui {

WindowStatusBar::WindowStatusBar(QWidget* parent) : QStatusBar(parent)
{
    cursor_ = new QLabel(this);
    cursor_->setMinimumWidth(260);
    statistics_ = new QLabel(this);
    progress_ = new QProgressBar(this);
    progress_->setMaximumWidth(200);
    progress_->setTextVisible(true);
    progress_->setVisible(false);
    factor_ = new QLabel(this);
    factor_->setObjectName(QStringLiteral("factorOfSafety"));
    QFont font = factor_->font();
    font.setBold(true);
    font.setPointSizeF(font.pointSizeF() * 1.3);
    factor_->setFont(font);
    factor_->setVisible(false);
    addPermanentWidget(factor_);
    addPermanentWidget(progress_);
    addPermanentWidget(statistics_);
    addPermanentWidget(cursor_);
}

void WindowStatusBar::showCursor(const QPointF& model_pos, double metres_per_pixel, const QString& value)
{
    const int decimals = metres_per_pixel > 0.0
                             ? std::clamp(static_cast<int>(std::ceil(-std::log10(metres_per_pixel))), 0, 6)
                             : 3;
    QString text = tr("x = %1 m   y = %2 m").arg(QLocale().toString(model_pos.x(), 'f', decimals), QLocale().toString(model_pos.y(), 'f', decimals));
    if (!value.isEmpty()) text += QStringLiteral("   ") + value;
    cursor_->setText(text);
}

void WindowStatusBar::clearCursor() { cursor_->clear(); }

QString WindowStatusBar::cursorText() const { return cursor_->text(); }

void WindowStatusBar::setStatistics(const QString& text) { statistics_->setText(text); }

QString WindowStatusBar::statistics() const { return statistics_->text(); }

void WindowStatusBar::showProgress(int maximum)
{
    progress_->setRange(0, maximum);
    progress_->setValue(0);
    progress_->setVisible(true);
}

void WindowStatusBar::setProgress(int value) { progress_->setValue(std::min(value, progress_->maximum())); }

void WindowStatusBar::hideProgress() { progress_->setVisible(false); }

void WindowStatusBar::setFactorOfSafety(const QString& text, const QString& tooltip)
{
    factor_->setText(text.isEmpty() ? QString() : tr("Factor of safety %1").arg(text));
    factor_->setToolTip(tooltip);
    factor_->setVisible(!text.isEmpty());
}

QString WindowStatusBar::factorOfSafety() const { return factor_->text(); }

void WindowStatusBar::showBusy(const QString& message)
{
    QApplication::setOverrideCursor(Qt::BusyCursor);
    showMessage(message);
    showProgress(0);
}

void WindowStatusBar::hideBusy()
{
    hideProgress();
    QApplication::restoreOverrideCursor();
    clearMessage();
}

}  // namespace mcdda::gui
