#include "results/RecordPlot.hpp"

#include "model/Defaults.hpp"
#include "run/GroundShaking.hpp"

#include <QChart>
#include <QChartView>
#include <QFont>
#include <QLabel>
#include <QLocale>
#include <QLineSeries>
#include <QPainter>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace mcdda::gui {

RecordPlot::RecordPlot(QWidget* parent) : QWidget(parent)
{
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(4, 4, 4, 4));
    series_ = new QLineSeries(chart);
    series_->setObjectName(QStringLiteral("recordSeries"));
    series_->setPen(QPen(QColor(20, 90, 200), 1.5));
    chart->addSeries(series_);
    peak_ = new QScatterSeries(chart);
    peak_->setObjectName(QStringLiteral("recordPeak"));
    peak_->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    peak_->setMarkerSize(10.0);
    peak_->setColor(QColor(220, 30, 30));
    peak_->setBorderColor(QColor(220, 30, 30));
    chart->addSeries(peak_);
    x_axis_ = new QValueAxis(chart);
    y_axis_ = new QValueAxis(chart);
    x_axis_->setTitleText(tr("time (s)"));
    QFont title = x_axis_->titleFont();
    title.setPointSizeF(0.85 * title.pointSizeF());  // "acceleration (m/s²)" fits beside a short plot
    x_axis_->setTitleFont(title);
    y_axis_->setTitleFont(title);
    chart->addAxis(x_axis_, Qt::AlignBottom);
    chart->addAxis(y_axis_, Qt::AlignLeft);
    for (QXYSeries* s : {static_cast<QXYSeries*>(series_), static_cast<QXYSeries*>(peak_)}) {
        s->attachAxis(x_axis_);
        s->attachAxis(y_axis_);
    }
    view_ = new QChartView(chart, this);
    view_->setObjectName(QStringLiteral("recordChart"));
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setMinimumSize(240, 160);
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("recordSummary"));
    summary_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(summary_);
    layout->addWidget(view_, 1);
    showRecord(nullptr);
}

QString RecordPlot::summary() const { return summary_->text(); }

void RecordPlot::showRecord(const GroundMotion* g)
{
    QList<QPointF> points;
    peak_value_ = peak_time_ = duration_ = 0.0;
    bool increasing = g && g->points.size() >= 2;
    for (std::size_t k = 1; increasing && k < g->points.size(); ++k)
        increasing = g->points[k][0] > g->points[k - 1][0] && std::isfinite(g->points[k][1]);
    const bool in_g = g && g->units == GroundMotion::Units::G;
    const QString unit = in_g ? tr("g") : tr("m/s²");
    if (increasing) {
        // As the analysis shakes the base: scaled and corrected, in the record's units.
        const GroundShaking shaking(*g);
        const double per_unit = in_g ? standard_gravity : 1.0;
        for (const auto& p : g->points) {
            const double a = shaking.acceleration(p[0]) / per_unit;
            points.append({p[0], a});
            if (std::fabs(a) > std::fabs(peak_value_)) peak_value_ = a, peak_time_ = p[0];
        }
        duration_ = shaking.duration();
    }
    series_->replace(points);
    peak_->replace(points.isEmpty() ? QList<QPointF>{} : QList<QPointF>{{peak_time_, peak_value_}});
    const double top = std::max(std::fabs(peak_value_), 1e-6);
    y_axis_->setRange(-1.1 * top, 1.1 * top);
    y_axis_->applyNiceNumbers();
    x_axis_->setRange(points.isEmpty() ? 0.0 : points.front().x(), points.isEmpty() ? 1.0 : points.back().x());
    x_axis_->applyNiceNumbers();  // ticks at round times
    y_axis_->setTitleText(tr("acceleration (%1)").arg(unit));
    peak_value_ = std::fabs(peak_value_);
    if (!g)
        summary_->setText(tr("No record chosen."));
    else if (!increasing)
        summary_->setText(tr("The record has no usable points (at least two, times increasing)."));
    else
        summary_->setText(tr("Peak %1 %2 at %3 s, duration %4 s")
                              .arg(QLocale().toString(peak_value_, 'g', 3), unit, QLocale().toString(peak_time_, 'f', 2),
                                   QLocale().toString(duration_, 'f', 2)));
}

}  // namespace mcdda::gui
