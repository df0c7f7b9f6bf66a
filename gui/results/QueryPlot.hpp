#pragma once
/// \file QueryPlot.hpp
/// The Query dock: the field shown in the picture along a line drawn with Edit ▸ Query Line,
/// plotted against the distance from its start, redrawn when the step or the field changes, and
/// exported as CSV. Openings and space outside the mesh leave gaps in the curve.

#include "results/QueryLine.hpp"

#include <QWidget>

class QLabel;
class QPushButton;
QT_BEGIN_NAMESPACE
class QChartView;
class QLineSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace mcdda::gui {

class QueryPlot : public QWidget {
    Q_OBJECT

public:
    explicit QueryPlot(QWidget* parent = nullptr);

    /// The line to query (m); nothing is sampled until refresh().
    void setLine(const Point2& from, const Point2& to);
    bool hasLine() const { return has_line_; }
    /// Samples what `probe` shows along the line (200 points) and redraws.
    void refresh(const view::ResultProbe& probe);
    const std::vector<QuerySample>& samples() const { return samples_; }
    /// The curve's pieces (one series per stretch on the mesh).
    QChartView* chartView() const { return view_; }
    /// Writes the samples as CSV; false with `error` set when it cannot.
    bool exportCsv(const QString& path, QString& error) const;

    static QColor curveColor();

private:
    QLabel* note_ = nullptr;
    QPushButton* export_ = nullptr;
    QChartView* view_ = nullptr;
    QValueAxis* x_axis_ = nullptr;
    QValueAxis* y_axis_ = nullptr;
    Point2 from_, to_;
    bool has_line_ = false;
    std::vector<QuerySample> samples_;
    QString field_, units_;
};

}  // namespace mcdda::gui
