#include "results/QueryLine.hpp"

#include <QCoreApplication>
#include <QSaveFile>
#include <QTextStream>

#include <algorithm>
#include <cmath>

namespace mcdda::gui {

std::vector<QuerySample> sample_line(const view::ResultProbe& probe, const Point2& from, const Point2& to, int count)
{
    count = std::max(count, 2);
    const double length = std::hypot(to.x - from.x, to.y - from.y);
    std::vector<QuerySample> samples(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const double t = static_cast<double>(i) / (count - 1);
        QuerySample& s = samples[static_cast<std::size_t>(i)];
        s.distance = t * length;
        s.point = {from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)};
        s.inside = !probe.empty() && probe.valueAt(s.point.x, s.point.y, &s.value);
    }
    return samples;
}

bool write_query_csv(const std::vector<QuerySample>& samples, const QString& field, const QString& units,
                     const QString& path, QString& error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        error = QCoreApplication::translate("mcdda::gui::QueryLine", "Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    QTextStream out(&file);
    out.setRealNumberPrecision(10);
    const QString value = units.isEmpty() || units == QLatin1String("-") ? field : field + QStringLiteral(" (") + units + QLatin1Char(')');
    out << "distance (m),x (m),y (m)," << QString(value).replace(QLatin1Char(','), QLatin1Char(';')) << '\n';
    for (const QuerySample& s : samples)
        if (s.inside) out << s.distance << ',' << s.point.x << ',' << s.point.y << ',' << s.value << '\n';
    out.flush();
    if (!file.commit()) {
        error = QCoreApplication::translate("mcdda::gui::QueryLine", "Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

}  // namespace mcdda::gui
