#include "results/QueryPlot.hpp"

#include <QChart>
#include <QChartView>
#include <QFileDialog>
#include <QLabel>
#include <QLineSeries>
#include <QMessageBox>
#include <QPushButton>
#include <QHBoxLayout>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace mcdda::gui {

QueryPlot::QueryPlot(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("queryPlot"));
    note_ = new QLabel(tr("Draw a line with Edit ▸ Query Line to plot the field shown along it."), this);
    note_->setWordWrap(true);
    export_ = new QPushButton(tr("Export CSV..."), this);
    export_->setObjectName(QStringLiteral("queryExport"));
    export_->setToolTip(tr("Save distance, x, y and value of the points on the mesh as CSV"));
    export_->setEnabled(false);
    connect(export_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export query line"), QString(), tr("CSV files (*.csv)"));
        QString error;
        if (!path.isEmpty() && !exportCsv(path, error)) QMessageBox::critical(this, tr("Export failed"), error);
    });
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(4, 4, 4, 4));
    x_axis_ = new QValueAxis(chart);
    x_axis_->setTitleText(tr("distance along the line (m)"));
    y_axis_ = new QValueAxis(chart);
    chart->addAxis(x_axis_, Qt::AlignBottom);
    chart->addAxis(y_axis_, Qt::AlignLeft);
    view_ = new QChartView(chart, this);
    view_->setObjectName(QStringLiteral("queryChart"));
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setMinimumSize(240, 140);
    auto* top = new QHBoxLayout;
    top->addWidget(note_, 1);
    top->addWidget(export_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(top);
    layout->addWidget(view_, 1);
}

QColor QueryPlot::curveColor() { return QColor(0, 120, 60); }

void QueryPlot::setLine(const Point2& from, const Point2& to)
{
    from_ = from;
    to_ = to;
    has_line_ = true;
}

void QueryPlot::refresh(const view::ResultProbe& probe)
{
    if (!has_line_) return;
    samples_ = sample_line(probe, from_, to_, 200);
    field_ = QString::fromStdString(probe.title);
    units_ = QString::fromStdString(probe.units);
    QChart* chart = view_->chart();
    chart->removeAllSeries();
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
            piece->attachAxis(y_axis_);
        }
        piece->append(s.distance, s.value);
        lo = std::min(lo, s.value), hi = std::max(hi, s.value);
        ++on_mesh;
    }
    x_axis_->setRange(0.0, std::max(samples_.back().distance, 1e-9));
    if (on_mesh > 0) {
        const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1e-9, 0.05 * std::abs(lo));
        y_axis_->setRange(lo - pad, hi + pad);
        y_axis_->applyNiceNumbers();
    }
    y_axis_->setTitleText(units_.isEmpty() || units_ == QLatin1String("-") ? field_ : field_ + QStringLiteral(" (") + units_ + QLatin1Char(')'));
    note_->setText(probe.empty() ? tr("The picture shows no result: run the model or choose a saved step.")
                                 : tr("%1 from (%2, %3) to (%4, %5) m: %n point(s) on the mesh", "", on_mesh)
                                       .arg(field_)
                                       .arg(from_.x, 0, 'g', 6)
                                       .arg(from_.y, 0, 'g', 6)
                                       .arg(to_.x, 0, 'g', 6)
                                       .arg(to_.y, 0, 'g', 6));
    export_->setEnabled(on_mesh > 0);
}

bool QueryPlot::exportCsv(const QString& path, QString& error) const
{
    return write_query_csv(samples_, field_, units_, path, error);
}

}  // namespace mcdda::gui
