#pragma once
/// \file ChartWithMessage.hpp
/// A chart that says in words why it is empty: before a run (or a query line) a plot shows a
/// short message where its axes would be, rather than bare axes with meaningless ticks.

#include <QStackedWidget>
#include <QString>

class QLabel;
QT_BEGIN_NAMESPACE
class QChart;
class QChartView;
QT_END_NAMESPACE

namespace mcdda::gui {

class ChartWithMessage : public QStackedWidget {
    Q_OBJECT

public:
    /// Takes `chart` into a chart view of its own.
    explicit ChartWithMessage(QChart* chart, QWidget* parent = nullptr);

    QChartView* chartView() const { return view_; }
    /// Shows `text` instead of the chart.
    void showMessage(const QString& text);
    /// Shows the chart.
    void showChart();
    /// Whether the chart (not the message) is shown.
    bool chartShown() const;
    /// The message shown instead of the chart (empty while the chart is shown).
    QString message() const;

private:
    QChartView* view_ = nullptr;
    QLabel* message_ = nullptr;
};

}  // namespace mcdda::gui
