#include "tools/SelectTool.hpp"

#include "widgets/ModelView.hpp"

#include <Qt>

#include <cmath>
#include <utility>

namespace mcdda::gui {

namespace {

/// Pixels the cursor must travel before a press becomes a drag (a click must not nudge items).
constexpr double drag_threshold_px = 4.0;

}  // namespace

SelectTool::SelectTool(ModelView* view, std::function<const Model&()> model, QObject* parent)
    : QObject(parent), view_(view), model_(std::move(model))
{
}

void SelectTool::select(const ItemRef& ref)
{
    const ItemRef next = item_exists(model_(), ref) ? ref : ItemRef{};
    const bool changed = next != selection_;
    selection_ = next;
    highlight({0.0, 0.0});
    if (changed) emit selectionChanged(selection_);
}

void SelectTool::refresh()
{
    if (!item_exists(model_(), selection_)) {
        select({});
        return;
    }
    highlight({0.0, 0.0});
}

bool SelectTool::pressed(const QPointF& widget_pos)
{
    const QPointF m = view_->toModel(widget_pos);
    // The water table of the stage the picture shows is the one drawn.
    const ItemRef hit = pick_item(model_(), {m.x(), m.y()}, tolerance_px_ * view_->metresPerPixel(),
                                  view_->sceneOptions().stage);
    select(hit);
    if (!hit.valid()) return false;  // empty space: the view pans
    pressing_ = true;
    dragging_ = false;
    press_pos_ = widget_pos;
    press_model_ = {m.x(), m.y()};
    delta_ = {0.0, 0.0};
    return true;
}

Point2 SelectTool::dragDelta(const QPointF& widget_pos) const
{
    const QPointF m = view_->toModel(widget_pos);
    const Point2 anchor = item_anchor(model_(), selection_);
    const Point2 wanted{anchor.x + m.x() - press_model_.x, anchor.y + m.y() - press_model_.y};
    SnapOptions options = snap_;
    options.vertex_tolerance = tolerance_px_ * view_->metresPerPixel();
    const Point2 landed = snap_point(wanted, model_(), {}, options);
    return {landed.x - anchor.x, landed.y - anchor.y};
}

void SelectTool::moved(const QPointF& widget_pos)
{
    if (!pressing_) return;
    const QPointF d = widget_pos - press_pos_;
    if (!dragging_ && std::hypot(d.x(), d.y()) < drag_threshold_px) return;
    dragging_ = true;
    delta_ = dragDelta(widget_pos);
    highlight(delta_);
}

void SelectTool::released(const QPointF& widget_pos)
{
    if (!pressing_) return;
    const bool was_dragging = dragging_;
    pressing_ = dragging_ = false;
    if (!was_dragging) return;
    const Point2 delta = dragDelta(widget_pos);
    highlight({0.0, 0.0});
    if (delta.x != 0.0 || delta.y != 0.0) emit moveRequested(selection_, delta);
}

bool SelectTool::keyPressed(int key)
{
    if ((key == Qt::Key_Delete || key == Qt::Key_Backspace) && selection_.valid()) {
        emit deleteRequested(selection_);
        return true;
    }
    if (key == Qt::Key_Escape) {
        if (dragging_) {  // drop the drag, keep the selection
            pressing_ = dragging_ = false;
            highlight({0.0, 0.0});
        } else {
            select({});
        }
        return true;
    }
    return false;
}

void SelectTool::cancel()
{
    pressing_ = dragging_ = false;
    select({});
    view_->clearPreview();
}

void SelectTool::highlight(const Point2& delta)
{
    bool closed = false;
    std::vector<Point2> points = item_points(model_(), selection_, &closed);
    // A whole region is highlighted by its boundary, but moves with its holes: the boundary is
    // enough to see where it goes.
    for (Point2& p : points) {
        p.x += delta.x;
        p.y += delta.y;
    }
    if (points.empty()) view_->clearPreview();
    else view_->setPreview(points, closed);
}

}  // namespace mcdda::gui
