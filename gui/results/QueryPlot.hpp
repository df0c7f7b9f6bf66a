#pragma once
/// \file QueryPlot.hpp
/// The Query dock: the field shown in the picture along a line drawn with Edit ▸ Query Line,
/// plotted against the distance from its start, redrawn when the step or the field changes, and
/// exported as CSV. Openings and space outside the mesh leave gaps in the curve. The field and
/// its units are named above the chart (a long name no longer fits along the y axis); the
/// plastic state is plotted against its named states. Without a line or a result the dock
/// says so instead of drawing empty axes.

#include "results/QueryLine.hpp"

#include <QWidget>

class QLabel;
class QPushButton;
QT_BEGIN_NAMESPACE
class QCategoryAxis;
class QChartView;
class QLineSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace mcdda::gui {

class ChartWithMessage;

class QueryPlot : public QWidget {
    Q_OBJECT

public:
    explicit QueryPlot(QWidget* parent = nullptr);

    /// The line to query (m); nothing is sampled until refresh().
    void setLine(const Point2& from, const Point2& to);
    bool hasLine() const { return has_line_; }
    /// Forgets the line and its samples (another model was opened).
    void clear();
    /// Samples what `probe` shows along the line (200 points) and redraws.
    void refresh(const view::ResultProbe& probe);
    const std::vector<QuerySample>& samples() const { return samples_; }
    /// The curve's pieces (one series per stretch on the mesh).
    QChartView* chartView() const;
    /// The chart, or the message shown instead of it.
    ChartWithMessage* chartArea() const { return area_; }
    /// The text above the chart: the field, its units and the line's ends.
    QString heading() const;
    /// Writes the samples as CSV; false with `error` set when it cannot.
    bool exportCsv(const QString& path, QString& error) const;
    /// A file name for the CSV: the model's and the field's (e.g. "tunnel-query-stress_1.csv").
    void setFileStem(const QString& stem) { file_stem_ = stem; }
    QString suggestedFileName() const;

    static QColor curveColor();

private:
    QLabel* note_ = nullptr;
    QPushButton* export_ = nullptr;
    ChartWithMessage* area_ = nullptr;
    QValueAxis* x_axis_ = nullptr;
    QValueAxis* y_axis_ = nullptr;
    QCategoryAxis* state_axis_ = nullptr;  ///< the plastic state's names instead of numbers
    Point2 from_, to_;
    bool has_line_ = false;
    std::vector<QuerySample> samples_;
    QString field_, units_;
    QString file_stem_;
};

}  // namespace mcdda::gui
