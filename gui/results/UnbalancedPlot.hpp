#pragma once
/// \file UnbalancedPlot.hpp
/// The unbalanced-force ratio of a run against its steps, on a logarithmic axis, with the limit
/// a run must end below to be in equilibrium (UDEC's `solve ratio` plot). Beside the history
/// plot, it shows while running whether the model settles or keeps moving.

#include "results/HistoryCsv.hpp"

#include <QWidget>

QT_BEGIN_NAMESPACE
class QChartView;
class QLineSeries;
class QLogValueAxis;
class QValueAxis;
QT_END_NAMESPACE

namespace mcdda::gui {

class ChartWithMessage;

class UnbalancedPlot : public QWidget {
    Q_OBJECT

public:
    explicit UnbalancedPlot(QWidget* parent = nullptr);

    /// Plots the history's unbalanced_ratio column against its step column.
    void show(const HistoryTable& table);
    /// The equilibrium limit drawn as a dashed line (AnalysisSettings::equilibrium_ratio).
    void setLimit(double ratio);
    /// The ratio per step, and the limit line.
    QLineSeries* series() const { return series_; }
    QLineSeries* limitSeries() const { return limit_; }
    /// The bottom of the log axis, where ratios of 0 are drawn.
    double axisFloor() const;
    QChartView* chartView() const { return view_; }
    /// Whether the ratio is drawn; before a run a message stands instead.
    bool chartShown() const;
    /// The colours of the ratio and of the limit line.
    static QColor seriesColor();
    static QColor limitColor();

private:
    void redrawLimit();

    ChartWithMessage* area_ = nullptr;
    QChartView* view_ = nullptr;
    QLineSeries* series_ = nullptr;
    QLineSeries* limit_ = nullptr;
    QValueAxis* x_axis_ = nullptr;
    QLogValueAxis* y_axis_ = nullptr;
    double limit_ratio_ = 1e-2;
    double last_step_ = 1.0;
};

}  // namespace mcdda::gui
