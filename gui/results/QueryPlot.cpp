#include "results/QueryPlot.hpp"

#include "results/ChartWithMessage.hpp"
#include "results/PlotAxes.hpp"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <limits>

namespace mcdda::gui {

QueryPlot::QueryPlot(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("queryPlot"));
    note_ = new QLabel(this);
    note_->setObjectName(QStringLiteral("queryHeading"));
    note_->setWordWrap(true);
    export_ = new QPushButton(tr("Export CSV..."), this);
    export_->setObjectName(QStringLiteral("queryExport"));
    export_->setToolTip(tr("Save distance, x, y and value of the points on the mesh as CSV"));
    export_->setEnabled(false);
    connect(export_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export query line"), suggestedFileName(),
                                                          tr("CSV files (*.csv)"));
        QString error;
        if (!path.isEmpty() && !exportCsv(path, error)) QMessageBox::critical(this, tr("Export failed"), error);
    });
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(4, 4, 4, 4));
    x_axis_ = new QValueAxis(chart);
    x_axis_->setTitleText(tr("distance along the line (m)"));
    x_axis_->setLabelFormat(axis_label_format());
    y_axis_ = new QValueAxis(chart);
    y_axis_->setLabelFormat(axis_label_format());
    // The plastic state is a category (0, 1, 2): its names on the axis, not −1 … 3.
    state_axis_ = new QCategoryAxis(chart);
    state_axis_->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    state_axis_->setStartValue(-0.5);
    state_axis_->append(QCoreApplication::translate("mcdda::view", "elastic"), 0.0);
    state_axis_->append(QCoreApplication::translate("mcdda::view", "yielded before"), 1.0);
    state_axis_->append(QCoreApplication::translate("mcdda::view", "yielding now"), 2.0);
    state_axis_->setRange(-0.5, 2.5);
    state_axis_->setVisible(false);
    chart->addAxis(x_axis_, Qt::AlignBottom);
    chart->addAxis(y_axis_, Qt::AlignLeft);
    chart->addAxis(state_axis_, Qt::AlignLeft);
    area_ = new ChartWithMessage(chart, this);
    area_->chartView()->setObjectName(QStringLiteral("queryChart"));
    area_->chartView()->setMinimumSize(240, 140);
    auto* top = new QHBoxLayout;
    top->addWidget(note_, 1);
    top->addWidget(export_, 0, Qt::AlignTop);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(top);
    layout->addWidget(area_, 1);
    clear();
}

QColor QueryPlot::curveColor() { return QColor(0, 120, 60); }

QChartView* QueryPlot::chartView() const { return area_->chartView(); }

QString QueryPlot::heading() const { return note_->text(); }

void QueryPlot::setLine(const Point2& from, const Point2& to)
{
    from_ = from;
    to_ = to;
    has_line_ = true;
}

void QueryPlot::clear()
{
    has_line_ = false;
    samples_.clear();
    field_.clear();
    units_.clear();
    chartView()->chart()->removeAllSeries();
    note_->clear();
    export_->setEnabled(false);
    area_->showMessage(tr("Draw a line with Edit ▸ Query Line to plot the field shown along it."));
}

QString QueryPlot::suggestedFileName() const
{
    QString name = file_stem_.isEmpty() ? QStringLiteral("query") : file_stem_ + QStringLiteral("-query");
    if (!field_.isEmpty()) {
        QString field = field_;
        field.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9]+")), QStringLiteral("_"));
        name += QLatin1Char('-') + field.section(QLatin1Char('_'), 0, 2, QString::SectionSkipEmpty);
    }
    return name + QStringLiteral(".csv");
}

void QueryPlot::refresh(const view::ResultProbe& probe)
{
    if (!has_line_) return;
    samples_ = sample_line(probe, from_, to_, 200);
    field_ = QString::fromStdString(probe.title);
    units_ = QString::fromStdString(probe.units);
    QChart* chart = chartView()->chart();
    chart->removeAllSeries();
    const bool states = probe.categorical;
    QAbstractAxis* y = states ? static_cast<QAbstractAxis*>(state_axis_) : y_axis_;
    y_axis_->setVisible(!states);
    state_axis_->setVisible(states);
    QLineSeries* piece = nullptr;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    int on_mesh = 0;
    for (const QuerySample& s : samples_) {
        if (!s.inside) {
            piece = nullptr;  // a gap: the opening or outside the mesh
            continue;
        }
        if (!piece) {
            piece = new QLineSeries(chart);
            piece->setPen(QPen(curveColor(), 2.0));
            chart->addSeries(piece);
            piece->attachAxis(x_axis_);
            piece->attachAxis(y);
        }
        piece->append(s.distance, s.value);
        lo = std::min(lo, s.value), hi = std::max(hi, s.value);
        ++on_mesh;
    }
    set_value_range(x_axis_, 0.0, samples_.back().distance);
    x_axis_->setMin(0.0);  // the distance starts at the line's first end
    if (on_mesh > 0 && !states) set_value_range(y_axis_, lo, hi);
    // The units only along the axis: "principal stress 1 (compression +) (MPa)" was cut to
    // "princip…" there. The field is named in full above the chart.
    const bool unitless = units_.isEmpty() || units_ == QLatin1String("-");
    y_axis_->setTitleText(unitless ? QString() : units_);
    const QString field = unitless ? field_ : field_ + QStringLiteral(" (") + units_ + QLatin1Char(')');
    if (probe.empty()) {
        note_->setText(tr("Query line from (%1, %2) to (%3, %4) m")
                           .arg(QLocale().toString(from_.x, 'g', 6))
                           .arg(QLocale().toString(from_.y, 'g', 6))
                           .arg(QLocale().toString(to_.x, 'g', 6))
                           .arg(QLocale().toString(to_.y, 'g', 6)));
        area_->showMessage(tr("The picture shows no result: run the model or choose a saved step."));
    } else {
        note_->setText(tr("%1 from (%2, %3) to (%4, %5) m: %n point(s) on the mesh", "", on_mesh)
                           .arg(field)
                           .arg(QLocale().toString(from_.x, 'g', 6))
                           .arg(QLocale().toString(from_.y, 'g', 6))
                           .arg(QLocale().toString(to_.x, 'g', 6))
                           .arg(QLocale().toString(to_.y, 'g', 6)));
        if (on_mesh > 0)
            area_->showChart();
        else
            area_->showMessage(tr("The line does not cross the mesh."));
    }
    export_->setEnabled(on_mesh > 0);
}

bool QueryPlot::exportCsv(const QString& path, QString& error) const
{
    return write_query_csv(samples_, field_, units_, path, error);
}

}  // namespace mcdda::gui
