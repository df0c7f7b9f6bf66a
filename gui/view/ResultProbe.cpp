#include "view/ResultProbe.hpp"

#include "view/PictureText.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mcdda::view {

bool ResultProbe::valueAt(double x, double y, double* value) const
{
    // A linear search: tens of microseconds for 50,000 triangles, once per cursor move.
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const Point2& a = points[triangles[t][0]];
        const Point2& b = points[triangles[t][1]];
        const Point2& c = points[triangles[t][2]];
        const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (det == 0.0) continue;
        const double l1 = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
        const double l2 = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
        const double l0 = 1.0 - l1 - l2;
        constexpr double slack = -1e-9;
        if (l0 < slack || l1 < slack || l2 < slack) continue;
        *value = point_values ? l0 * values[triangles[t][0]] + l1 * values[triangles[t][1]] +
                                    l2 * values[triangles[t][2]]
                              : values[t];
        return true;
    }
    return false;
}

namespace {

double distance_to_segment(double x, double y, Point2 a, Point2 b)
{
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    const double t = length2 > 0.0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(x - (a.x + t * dx), y - (a.y + t * dy));
}

}  // namespace

std::string ResultProbe::describe(double x, double y) const
{
    // A bolt under the point first: its force is what one points at a bolt for.
    const Bolt* nearest = nullptr;
    double nearest_distance = bolt_reach;
    for (const Bolt& b : bolts)
        if (const double d = distance_to_segment(x, y, b.from, b.to); d <= nearest_distance) {
            nearest = &b;
            nearest_distance = d;
        }
    std::string bolt;
    if (nearest) {
        bolt = picture_text(QT_TRANSLATE_NOOP("mcdda::view", "bolt, axial force")) + " " +
               picture_number("%.3g", nearest->force / 1e3) + " kN/m";
    }
    const std::string field = describe_field(x, y);
    if (bolt.empty()) return field;
    return field.empty() ? bolt : bolt + "; " + field;
}

std::string ResultProbe::describe_field(double x, double y) const
{
    double v = 0.0;
    if (empty() || !valueAt(x, y, &v)) return {};
    if (categorical) {
        static const char* const states[3] = {QT_TRANSLATE_NOOP("mcdda::view", "elastic"),
                                              QT_TRANSLATE_NOOP("mcdda::view", "yielded before"),
                                              QT_TRANSLATE_NOOP("mcdda::view", "yielding now")};
        const int s = std::lround(v) < 0 ? 0 : std::lround(v) > 2 ? 2 : static_cast<int>(std::lround(v));
        return title + ": " + picture_text(states[s]);
    }
    return title + " = " + picture_number("%.4g", v) + (units.empty() || units == "-" ? std::string() : " " + units);
}

}  // namespace mcdda::view
