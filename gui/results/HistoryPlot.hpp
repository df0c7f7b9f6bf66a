#pragma once
/// \file HistoryPlot.hpp
/// Plots a run's history.csv with Qt Charts: one measurement-point column (…:ux or …:uy; of a
/// dynamic run also the velocities …:vx, …:vy and accelerations …:ax, …:ay, and the base's input
/// motion base:…)
/// against time or against a load column (load:<name>, a load–settlement curve), and under it
/// the unbalanced-force ratio per step. A strength reduction's history (a row per trial) is
/// drawn as RS2's SSR graph: the largest or a point's displacement against the factor, the
/// trials that stood joined by a line, those that did not as red squares.

#include "results/HistoryCsv.hpp"

#include <QString>
#include <QWidget>

class QComboBox;
namespace mcdda::gui { class UnbalancedPlot; class ChartWithMessage; }
class QLabel;

QT_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QLineSeries;
class QScatterSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace mcdda::gui {

class HistoryPlot : public QWidget {
    Q_OBJECT

public:
    explicit HistoryPlot(QWidget* parent = nullptr);

    /// Reads the history at `csv_path` (again) and redraws, keeping the chosen columns when
    /// they are still there. A missing file empties the plot. Returns the number of rows.
    int load(const QString& csv_path);
    void clear();

    const HistoryTable& table() const { return table_; }
    /// The plotted curve (one point per history row; of a strength reduction, per trial that stood).
    QLineSeries* series() const { return series_; }
    /// A strength reduction's trials that did not stand.
    QScatterSeries* failedTrials() const { return failed_; }
    /// A line over the chart (the factor of safety); empty: none. Cleared with the plot.
    void setTitle(const QString& title);
    QChart* chart() const;
    /// Chooses the plotted column (e.g. "crest:uy") and the abscissa ("time" or "load:<name>").
    void setColumns(const QString& y_column, const QString& x_column);
    QString yColumn() const;
    QString xColumn() const;
    /// How a history column is offered ("crest:vx (m/s)", "base input ax (m/s²)"); empty for a
    /// column that is not a point's or the base's displacement, velocity or acceleration.
    static QString quantityLabel(const QString& column);
    /// A static run's history: plotted against the load step (column "step") instead of time
    /// in seconds, which a static analysis does not have. Takes effect at the next load().
    void setLoadSteps(bool load_steps) { load_steps_ = load_steps; }
    /// Whether the curve is drawn; before a run (nothing to plot) a message stands instead.
    bool chartShown() const;
    QString emptyMessage() const;
    /// The unbalanced-force ratio of the same history, under the plot.
    UnbalancedPlot* unbalancedPlot() const { return unbalanced_; }

private:
    void redraw();

    QComboBox* y_box_ = nullptr;
    QComboBox* x_box_ = nullptr;
    QLabel* note_ = nullptr;
    UnbalancedPlot* unbalanced_ = nullptr;
    ChartWithMessage* area_ = nullptr;
    QChartView* view_ = nullptr;
    QLineSeries* series_ = nullptr;
    QScatterSeries* failed_ = nullptr;
    QValueAxis* x_axis_ = nullptr;
    QValueAxis* y_axis_ = nullptr;
    HistoryTable table_;
    bool load_steps_ = false;
};

}  // namespace mcdda::gui
