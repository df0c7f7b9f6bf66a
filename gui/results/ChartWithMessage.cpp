#include "results/ChartWithMessage.hpp"

#include <QChart>
#include <QChartView>
#include <QLabel>
#include <QPainter>

namespace mcdda::gui {

ChartWithMessage::ChartWithMessage(QChart* chart, QWidget* parent) : QStackedWidget(parent)
{
    view_ = new QChartView(chart, this);
    view_->setRenderHint(QPainter::Antialiasing);
    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("emptyChartMessage"));
    message_->setWordWrap(true);
    message_->setAlignment(Qt::AlignCenter);
    message_->setMargin(12);
    message_->setForegroundRole(QPalette::PlaceholderText);  // a hint, not data
    addWidget(view_);
    addWidget(message_);
}

void ChartWithMessage::showMessage(const QString& text)
{
    message_->setText(text);
    setCurrentWidget(message_);
}

void ChartWithMessage::showChart() { setCurrentWidget(view_); }

bool ChartWithMessage::chartShown() const { return currentWidget() == view_; }

QString ChartWithMessage::message() const { return chartShown() ? QString() : message_->text(); }

}  // namespace mcdda::gui
