#include "results/HistoryPlot.hpp"

#include "results/ChartWithMessage.hpp"
#include "results/PlotAxes.hpp"
#include "results/UnbalancedPlot.hpp"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QPainter>
#include <QScatterSeries>
#include <QXYSeries>
#include <QSignalBlocker>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcdda::gui {

HistoryPlot::HistoryPlot(QWidget* parent) : QWidget(parent)
{
    y_box_ = new QComboBox(this);
    y_box_->setObjectName(QStringLiteral("historyColumn"));
    y_box_->setToolTip(tr("Measured quantity plotted: a point's displacement, velocity or acceleration (x or y), or the "
                          "base's input motion"));
    x_box_ = new QComboBox(this);
    x_box_->setObjectName(QStringLiteral("historyAbscissa"));
    x_box_->setToolTip(tr("Plotted against the load step (a static analysis), time (a dynamic one) or a load "
                          "(load-settlement curve)"));
    note_ = new QLabel(this);

    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(4, 4, 4, 4));
    series_ = new QLineSeries(chart);
    series_->setPointsVisible(true);
    chart->addSeries(series_);
    // A strength reduction's trials that did not stand: red squares beside the curve of those
    // that did (RS2's SSR graph).
    failed_ = new QScatterSeries(chart);
    failed_->setObjectName(QStringLiteral("failedTrials"));
    failed_->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    failed_->setMarkerSize(9.0);
    failed_->setColor(QColor(210, 30, 30));
    failed_->setBorderColor(QColor(210, 30, 30));
    chart->addSeries(failed_);
    x_axis_ = new QValueAxis(chart);
    y_axis_ = new QValueAxis(chart);
    chart->addAxis(x_axis_, Qt::AlignBottom);
    chart->addAxis(y_axis_, Qt::AlignLeft);
    for (QXYSeries* s : {static_cast<QXYSeries*>(series_), static_cast<QXYSeries*>(failed_)}) {
        s->attachAxis(x_axis_);
        s->attachAxis(y_axis_);
    }
    area_ = new ChartWithMessage(chart, this);
    area_->setObjectName(QStringLiteral("historyChartArea"));
    view_ = area_->chartView();
    view_->setMinimumSize(240, 160);

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Plot"), this));
    controls->addWidget(y_box_, 1);
    controls->addWidget(new QLabel(tr("against"), this));
    controls->addWidget(x_box_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(controls);
    layout->addWidget(note_);
    layout->addWidget(area_, 1);
    unbalanced_ = new UnbalancedPlot(this);
    layout->addWidget(unbalanced_, 1);

    connect(y_box_, &QComboBox::currentIndexChanged, this, [this] { redraw(); });
    connect(x_box_, &QComboBox::currentIndexChanged, this, [this] { redraw(); });
    clear();
}

QString HistoryPlot::quantityLabel(const QString& column)
{
    // <point>:ux … <point>:ay (dynamic runs: velocities and accelerations too), base:… the input.
    const int colon = column.lastIndexOf(QLatin1Char(':'));
    if (colon < 0) return QString();
    const QString point = column.left(colon), q = column.mid(colon + 1);
    if (q.size() != 2 || (q[1] != QLatin1Char('x') && q[1] != QLatin1Char('y'))) return QString();
    QString unit;
    if (q[0] == QLatin1Char('u')) unit = tr("m");
    else if (q[0] == QLatin1Char('v')) unit = tr("m/s");
    else if (q[0] == QLatin1Char('a')) unit = tr("m/s²");
    else return QString();
    if (point == QLatin1String("base")) return tr("base input %1 (%2)").arg(q, unit);
    return tr("%1 (%2)").arg(column, unit);
}

QChart* HistoryPlot::chart() const { return view_->chart(); }

void HistoryPlot::setTitle(const QString& title) { view_->chart()->setTitle(title); }

void HistoryPlot::clear()
{
    table_ = {};
    setTitle(QString());
    {
        const QSignalBlocker a(y_box_), b(x_box_);
        y_box_->clear();
        x_box_->clear();
    }
    redraw();
}

int HistoryPlot::load(const QString& csv_path)
{
    const QString y = yColumn(), x = xColumn();
    HistoryTable table;
    if (!QFileInfo::exists(csv_path) || !read_history(csv_path, table)) {
        clear();
        return 0;
    }
    table_ = std::move(table);
    {
        const QSignalBlocker a(y_box_), b(x_box_);
        y_box_->clear();
        x_box_->clear();
        if (table_.isTrialTable()) {
            // One row per trial: displacements against the strength reduction factor.
            x_box_->addItem(tr("strength reduction factor"), QStringLiteral("factor"));
            y_box_->addItem(tr("largest displacement (m)"), QStringLiteral("max_displacement"));
        } else if (load_steps_ && table_.column(QStringLiteral("step")) >= 0) {
            x_box_->addItem(tr("load step"), QStringLiteral("step"));
        } else {
            x_box_->addItem(tr("time (s)"), QStringLiteral("time"));
        }
        for (const QString& c : table_.columns) {
            if (c.startsWith(QLatin1String("load:")))
                x_box_->addItem(tr("load %1").arg(c.mid(5)), c);
            else if (const QString label = quantityLabel(c); !label.isEmpty())
                y_box_->addItem(label, c);
        }
        if (const int i = y_box_->findData(y); i >= 0) y_box_->setCurrentIndex(i);
        if (const int i = x_box_->findData(x); i >= 0) x_box_->setCurrentIndex(i);
    }
    redraw();
    return static_cast<int>(table_.rows.size());
}

void HistoryPlot::setColumns(const QString& y_column, const QString& x_column)
{
    const QSignalBlocker a(y_box_), b(x_box_);
    if (const int i = y_box_->findData(y_column); i >= 0) y_box_->setCurrentIndex(i);
    if (const int i = x_box_->findData(x_column); i >= 0) x_box_->setCurrentIndex(i);
    redraw();
}

QString HistoryPlot::yColumn() const { return y_box_->currentData().toString(); }

QString HistoryPlot::xColumn() const { return x_box_->currentData().toString(); }

void HistoryPlot::redraw()
{
    unbalanced_->show(table_);
    const int xi = table_.column(xColumn()), yi = table_.column(yColumn());
    QList<QPointF> points, failed;
    const bool trials = table_.isTrialTable();
    const int stands = table_.column(QStringLiteral("stands"));
    if (xi >= 0 && yi >= 0)
        for (const auto& row : table_.rows) {
            const QPointF p(row[xi], row[yi]);
            if (!std::isfinite(p.x()) || !std::isfinite(p.y())) continue;
            (trials && row[stands] != 1.0 ? failed : points).append(p);
        }
    // Trials run in the search's order, not the factor's.
    if (trials)
        std::sort(points.begin(), points.end(), [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    series_->replace(points);
    failed_->replace(failed);
    if (table_.columns.isEmpty())
        note_->setText(tr("No history: run the model."));
    else if (yi < 0)
        note_->setText(tr("The model has no measurement points."));
    else if (trials)
        note_->setText(tr("%n trial(s) stood, %1 did not", "", static_cast<int>(points.size())).arg(failed.size()));
    else
        note_->setText(tr("%n step(s)", "", static_cast<int>(points.size())));
    double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double hi[2] = {-lo[0], -lo[1]};
    for (const QPointF& p : points + failed) {
        lo[0] = std::min(lo[0], p.x()), hi[0] = std::max(hi[0], p.x());
        lo[1] = std::min(lo[1], p.y()), hi[1] = std::max(hi[1], p.y());
    }
    QValueAxis* axes[2] = {x_axis_, y_axis_};
    for (int k = 0; k < 2; ++k) {
        if (!(lo[k] <= hi[k])) lo[k] = 0.0, hi[k] = 1.0;
        if (hi[k] - lo[k] <= 1e-12 * std::max(1.0, std::abs(lo[k]))) {
            const double pad = lo[k] != 0.0 ? 0.05 * std::abs(lo[k]) : 1e-6;
            lo[k] -= pad, hi[k] += pad;
        }
        axes[k]->setRange(lo[k], hi[k]);
        axes[k]->applyNiceNumbers();
    }
    x_axis_->setTitleText(x_box_->currentText());
    y_axis_->setTitleText(y_box_->currentText());
    x_axis_->setLabelFormat(axis_label_format());
    y_axis_->setLabelFormat(axis_label_format());
    // Bare axes with ticks "0 0 0 0 1" said nothing before a run: words instead.
    if (points.isEmpty() && failed.isEmpty())
        area_->showMessage(table_.columns.isEmpty()
                               ? tr("No history yet: run the model (Run ▸ Run, F5). The displacements of its "
                                    "measurement points are plotted here as it runs.")
                               : note_->text());
    else
        area_->showChart();
}

bool HistoryPlot::chartShown() const { return area_->chartShown(); }

QString HistoryPlot::emptyMessage() const { return area_->message(); }

}  // namespace mcdda::gui
