#include "tools/DrawTool.hpp"

#include "geometry/PolygonChecks.hpp"
#include "widgets/ModelView.hpp"

#include <Qt>

#include <algorithm>
#include <cmath>
#include <utility>

namespace mcdda::gui {

namespace {

bool same(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y) < 1e-9; }

}  // namespace

DrawTool::DrawTool(Shape shape, ModelView* view, std::function<const Model&()> model, QObject* parent)
    : QObject(parent), shape_(shape), view_(view), model_(std::move(model))
{
}

Point2 DrawTool::snapped(const QPointF& widget_pos) const
{
    const QPointF m = view_->toModel(widget_pos);
    SnapOptions options = snap_;
    options.vertex_tolerance = tolerance_px_ * view_->metresPerPixel();
    return snap_point({m.x(), m.y()}, model_(), points_, options);
}

bool DrawTool::pressed(const QPointF& widget_pos)
{
    addPoint(snapped(widget_pos));
    return true;
}

void DrawTool::addPoint(const Point2& p)
{
    if (!points_.empty() && same(points_.back(), p)) return;  // the second press of a double-click
    if (shape_ == Shape::Polygon && points_.size() >= 3 && same(points_.front(), p)) {
        finish();  // clicking the first vertex closes the polygon
        return;
    }
    points_.push_back(p);
    if (points_.size() == 1) emit started();
    cursor_ = p;
    has_cursor_ = true;
    if ((shape_ == Shape::Point || shape_ == Shape::Segment) && points_.size() >= needed()) {
        finish();
        return;
    }
    updatePreview();
}

std::size_t DrawTool::needed() const
{
    switch (shape_) {
        case Shape::Polygon: return 3;
        case Shape::Point: return 1;
        default: return 2;
    }
}

void DrawTool::moved(const QPointF& widget_pos)
{
    const Point2 landing = snapped(widget_pos);
    view_->showSnapMarker(landing);
    if (points_.empty() || shape_ == Shape::Point) return;
    cursor_ = landing;
    has_cursor_ = true;
    updatePreview();
}

void DrawTool::doubleClicked(const QPointF& widget_pos)
{
    if (shape_ == Shape::Point) return;  // its first press already placed the point
    pressed(widget_pos);  // adds the vertex unless its press already did
    finish();
}

bool DrawTool::keyPressed(int key)
{
    switch (key) {
        case Qt::Key_Return:
        case Qt::Key_Enter: finish(); return true;
        case Qt::Key_Escape: cancel(); return true;
        case Qt::Key_Backspace:
            if (points_.empty()) return false;
            points_.pop_back();
            updatePreview();
            return true;
        default: return false;
    }
}

bool DrawTool::finish()
{
    std::vector<Point2> shape = points_;
    if (shape.size() > 1 && same(shape.front(), shape.back()) && shape_ == Shape::Polygon) shape.pop_back();
    if (shape.size() < needed()) return false;
    if (shape_ == Shape::Polygon && signed_area(shape) < 0.0) std::reverse(shape.begin(), shape.end());
    cancel();
    emit finished(shape);
    return true;
}

void DrawTool::cancel()
{
    points_.clear();
    has_cursor_ = false;
    view_->clearPreview();
}

void DrawTool::updatePreview()
{
    std::vector<Point2> line = points_;
    if (has_cursor_ && (line.empty() || !same(line.back(), cursor_))) line.push_back(cursor_);
    view_->setPreview(line, shape_ == Shape::Polygon, emphasised_);
}

}  // namespace mcdda::gui
