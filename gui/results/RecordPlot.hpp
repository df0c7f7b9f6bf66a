#pragma once
/// \file RecordPlot.hpp
/// An earthquake acceleration record plotted against time before any run, as the analysis will
/// use it (units and scale applied, baseline-corrected when asked: run/GroundShaking.hpp), in
/// the record's own units (g or m/s²), with its peak marked and a line giving the peak, when
/// it comes and the record's duration.

#include "model/Model.hpp"

#include <QString>
#include <QWidget>

class QLabel;

QT_BEGIN_NAMESPACE
class QChartView;
class QLineSeries;
class QScatterSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace mcdda::gui {

class RecordPlot : public QWidget {
    Q_OBJECT

public:
    explicit RecordPlot(QWidget* parent = nullptr);

    /// Plots `motion` (null or fewer than two points: an empty plot saying so).
    void showRecord(const GroundMotion* motion);

    /// The curve (one point per sample) and the peak's marker.
    QLineSeries* series() const { return series_; }
    QScatterSeries* peakMarker() const { return peak_; }
    /// "Peak 0.300 g at 1.23 s, duration 3.00 s" (empty without a record).
    QString summary() const;
    /// The peak's absolute value in the record's units, its time (s) and the duration (s).
    double peak() const { return peak_value_; }
    double peakTime() const { return peak_time_; }
    double duration() const { return duration_; }

private:
    QChartView* view_ = nullptr;
    QLineSeries* series_ = nullptr;
    QScatterSeries* peak_ = nullptr;
    QValueAxis* x_axis_ = nullptr;
    QValueAxis* y_axis_ = nullptr;
    QLabel* summary_ = nullptr;
    double peak_value_ = 0.0, peak_time_ = 0.0, duration_ = 0.0;
};

}  // namespace mcdda::gui
