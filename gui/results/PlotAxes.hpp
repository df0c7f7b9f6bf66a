#pragma once
/// \file PlotAxes.hpp
/// Value axes of the result plots with readable ticks: labels in %g style with at most four
/// significant digits ("0.001", "1.5e+04", never "0.00000000100"), and a range that stays
/// meaningful for a flat curve (a field that is the same all along a line).

#include <QString>

QT_BEGIN_NAMESPACE
class QValueAxis;
QT_END_NAMESPACE

namespace mcdda::gui {

/// The label format of every value axis of the plots.
QString axis_label_format();

/// A tick's label as the axes draw it (axis_label_format applied to `value`).
QString axis_label(double value);

/// Sets `axis` to [lo, hi] widened a little and rounded to nice ticks, with the label format
/// above. A flat range (lo == hi) is widened to ±10 % of its value, or ±1 about 0.
void set_value_range(QValueAxis* axis, double lo, double hi);

}  // namespace mcdda::gui
