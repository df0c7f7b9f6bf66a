#include "results/UnbalancedPlot.hpp"

#include "results/ChartWithMessage.hpp"

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

/// The smallest ratio the axis goes down to.
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
    y_axis_->setTitleText(tr("ratio"));  // short: the dock is narrow; the tooltip says which ratio
    y_axis_->setLabelFormat(QStringLiteral("%.0e"));
    chart->addAxis(x_axis_, Qt::AlignBottom);
    chart->addAxis(y_axis_, Qt::AlignLeft);
    for (QLineSeries* s : {series_, limit_}) {
        s->attachAxis(x_axis_);
        s->attachAxis(y_axis_);
    }
    area_ = new ChartWithMessage(chart, this);
    view_ = area_->chartView();
    view_->setObjectName(QStringLiteral("unbalancedChart"));
    view_->setMinimumSize(240, 140);
    view_->setToolTip(tr("Largest out-of-balance nodal force over the largest applied force, per step; a run "
                         "ending above the dashed limit is not in equilibrium"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(area_);
    show(HistoryTable{});
}

QColor UnbalancedPlot::seriesColor() { return QColor(0, 90, 180); }

QColor UnbalancedPlot::limitColor() { return QColor(200, 30, 30); }

void UnbalancedPlot::show(const HistoryTable& table)
{
    const int si = table.column(QStringLiteral("step")), ri = table.column(QStringLiteral("unbalanced_ratio"));
    // Whole decades around the positive ratios and the limit. A ratio of exactly 0 (nothing
    // loaded yet) has no place on a log axis: it is drawn on the axis' floor, which it does not
    // push down (a floor of 1e-12 left 14 decades whose labels no longer fit).
    double lo = limit_ratio_ / 10.0, hi = limit_ratio_;  // the limit a decade above the floor, in sight
    last_step_ = 1.0;
    if (si >= 0 && ri >= 0)
        for (const auto& row : table.rows) {
            if (row[ri] > 0.0) lo = std::min(lo, row[ri]), hi = std::max(hi, row[ri]);
            last_step_ = std::max(last_step_, row[si]);
        }
    lo = std::max(lo, floor_ratio);
    const double bottom = std::pow(10.0, std::floor(std::log10(lo)));
    QList<QPointF> points;
    if (si >= 0 && ri >= 0)
        for (const auto& row : table.rows) points.append(QPointF(row[si], std::max(row[ri], bottom)));
    series_->replace(points);
    if (points.isEmpty())
        area_->showMessage(tr("The unbalanced-force ratio of each step is plotted here during a run."));
    else
        area_->showChart();
    x_axis_->setRange(0.0, last_step_);
    // Whole steps: "%d" on ticks a quarter step apart read "0 0 0 0 1".
    x_axis_->setTickType(QValueAxis::TicksDynamic);
    x_axis_->setTickAnchor(0.0);
    x_axis_->setTickInterval(std::max(1.0, std::ceil(last_step_ / 5.0)));
    y_axis_->setRange(bottom, std::pow(10.0, std::ceil(std::log10(hi))));
    redrawLimit();
}

bool UnbalancedPlot::chartShown() const { return area_->chartShown(); }

double UnbalancedPlot::axisFloor() const { return y_axis_->min(); }

void UnbalancedPlot::setLimit(double ratio)
{
    if (!(ratio > 0.0)) return;
    limit_ratio_ = ratio;
    redrawLimit();
}

void UnbalancedPlot::redrawLimit() { limit_->replace({QPointF(0.0, limit_ratio_), QPointF(last_step_, limit_ratio_)}); }

}  // namespace mcdda::gui
