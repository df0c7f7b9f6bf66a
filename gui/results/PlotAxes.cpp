#include "results/PlotAxes.hpp"

#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace mcdda::gui {

namespace {

/// 1, 2 or 5 × 10ⁿ, the smallest such step of at least `raw`.
double nice_step(double raw)
{
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= raw * (1.0 - 1e-12)) return m * decade;
    return 10.0 * decade;
}

}  // namespace

QString axis_label_format() { return QStringLiteral("%.4g"); }

QString axis_label(double value) { return QString::asprintf("%.4g", value); }

void set_value_range(QValueAxis* axis, double lo, double hi)
{
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) lo = 0.0, hi = 1.0;
    const double size = std::max(std::abs(lo), std::abs(hi));
    if (hi - lo <= 1e-9 * size || size == 0.0) {
        // Flat: a padding of 1e-9 gave ticks like 0.00000000100 around a constant.
        const double pad = size > 0.0 ? 0.1 * size : 1.0;
        lo -= pad, hi += pad;
    }
    // Ticks anchored at 0 and a round step apart: 0 is drawn as "0", not as a sum's
    // round-off ("-5.551e-17") that evenly divided ranges give.
    const double step = nice_step((hi - lo) / 4.0);
    lo = std::floor(lo / step + 1e-9) * step;
    hi = std::ceil(hi / step - 1e-9) * step;
    if (hi <= lo) hi = lo + step;
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(step);
    axis->setRange(lo, hi);
    axis->setLabelFormat(axis_label_format());
}

}  // namespace mcdda::gui
