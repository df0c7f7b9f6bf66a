#include "results/UnbalancedPlot.hpp"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPen>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace mcdda::gui {

namespace {

/// A log axis cannot show 0: a ratio of exactly 0 (nothing loaded yet) is drawn at this floor.
constexpr double floor_ratio = 1e-12;

}  // namespace

UnbalancedPlot::UnbalancedPlot(QWidget* parent) : QWidget(parent)
{
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(4, 4, 4, 4));
    series_ = new QLineSeries(chart);
    series_->setName(tr("unbalanced-force ratio"));
    series_->setPen(QPen(seriesColor(), 2.0));
    limit_ = new QLineSeries(chart);
    limit_->setName(tr("equilibrium limit"));
    QPen dashed(limitColor());
    dashed.setStyle(Qt::DashLine);
    dashed.setWidthF(2.0);  // as wide as the series: whole pixels of its colour at any height
    limit_->setPen(dashed);
    chart->addSeries(series_);
    chart->addSeries(limit_);
    x_axis_ = new QValueAxis(chart);
    x_axis_->setTitleText(tr("step"));
    x_axis_->setLabelFormat(QStringLiteral("%d"));
    y_axis_ = new QLogValueAxis(chart);
    y_axis_->setTitleText(tr("unbalanced-force ratio"));
    y_axis_->setLabelFormat(QStringLiteral("%.0e"));
    chart->addAxis(x_axis_, Qt::AlignBottom);
    chart->addAxis(y_axis_, Qt::AlignLeft);
    for (QLineSeries* s : {series_, limit_}) {
        s->attachAxis(x_axis_);
        s->attachAxis(y_axis_);
    }
    view_ = new QChartView(chart, this);
    view_->setObjectName(QStringLiteral("unbalancedChart"));
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setMinimumSize(240, 140);
    view_->setToolTip(tr("Largest out-of-balance nodal force over the largest applied force, per step; a run "
                         "ending above the dashed limit is not in equilibrium"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(view_);
    show(HistoryTable{});
}

QColor UnbalancedPlot::seriesColor() { return QColor(0, 90, 180); }

QColor UnbalancedPlot::limitColor() { return QColor(200, 30, 30); }

void UnbalancedPlot::show(const HistoryTable& table)
{
    const int si = table.column(QStringLiteral("step")), ri = table.column(QStringLiteral("unbalanced_ratio"));
    QList<QPointF> points;
    double lo = limit_ratio_, hi = limit_ratio_;
    last_step_ = 1.0;
    if (si >= 0 && ri >= 0)
        for (const auto& row : table.rows) {
            const double ratio = std::max(row[ri], floor_ratio);
            points.append(QPointF(row[si], ratio));
            lo = std::min(lo, ratio), hi = std::max(hi, ratio);
            last_step_ = std::max(last_step_, row[si]);
        }
    series_->replace(points);
    x_axis_->setRange(0.0, last_step_);
    // Whole decades around the data and the limit.
    y_axis_->setRange(std::pow(10.0, std::floor(std::log10(lo))), std::pow(10.0, std::ceil(std::log10(hi)) + 0.0));
    redrawLimit();
}

void UnbalancedPlot::setLimit(double ratio)
{
    if (!(ratio > 0.0)) return;
    limit_ratio_ = ratio;
    redrawLimit();
}

void UnbalancedPlot::redrawLimit() { limit_->replace({QPointF(0.0, limit_ratio_), QPointF(last_step_, limit_ratio_)}); }

}  // namespace mcdda::gui
