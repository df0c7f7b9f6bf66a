#include "dialogs/JointSetPreview.hpp"

#include "geometry/JointSets.hpp"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <limits>

namespace mcdda::gui {

JointSetPreview::JointSetPreview(const Model& model, QWidget* parent) : QWidget(parent), model_(model)
{
    setObjectName(QStringLiteral("jointSetPreview"));
    setMinimumSize(200, 140);
    model_.joint_sets.clear();
    model_.joints.clear();
    double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
    for (const Region& r : model_.regions)
        for (const Point2& p : r.boundary) {
            lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
            lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
        }
    if (lo_x < hi_x && lo_y < hi_y) xmin_ = lo_x, ymin_ = lo_y, xmax_ = hi_x, ymax_ = hi_y;
}

void JointSetPreview::setJointSet(const JointSet& set)
{
    Model m = model_;
    m.joint_sets = {set};
    traces_.clear();
    if (set.spacing > 0.0 && !m.regions.empty()) {
        expand_joint_sets(m);  // refuses (generates nothing for) sets the validator would refuse
        traces_ = std::move(m.joints);
    }
    update();
}

QPointF JointSetPreview::toPixel(const Point2& p) const
{
    constexpr double margin = 8.0;
    const double scale = std::min((width() - 2 * margin) / (xmax_ - xmin_), (height() - 2 * margin) / (ymax_ - ymin_));
    const double left = (width() - scale * (xmax_ - xmin_)) / 2.0;
    const double top = (height() - scale * (ymax_ - ymin_)) / 2.0;
    return {left + scale * (p.x - xmin_), top + scale * (ymax_ - p.y)};  // y up
}

QColor JointSetPreview::rockColor() { return QColor(200, 200, 200); }

QColor JointSetPreview::traceColor() { return QColor(140, 0, 153); }  // the joints' purple

void JointSetPreview::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    QPainterPath rock;
    rock.setFillRule(Qt::OddEvenFill);  // holes are rings inside their region
    auto add_ring = [&](const Ring& ring) {
        if (ring.size() < 3) return;
        QPolygonF polygon;
        for (const Point2& p : ring) polygon << toPixel(p);
        rock.addPolygon(polygon);
        rock.closeSubpath();
    };
    for (const Region& r : model_.regions) {
        add_ring(r.boundary);
        for (const Ring& h : r.holes) add_ring(h);
    }
    painter.fillPath(rock, rockColor());
    painter.setPen(QPen(Qt::darkGray, 1.0));
    painter.drawPath(rock);
    // Only where the traces cut rock: beyond it they cut nothing.
    painter.setClipPath(rock);
    painter.setPen(QPen(traceColor(), 1.5));
    for (const Joint& j : traces_)
        for (std::size_t i = 0; i + 1 < j.points.size(); ++i) painter.drawLine(toPixel(j.points[i]), toPixel(j.points[i + 1]));
}

}  // namespace mcdda::gui
