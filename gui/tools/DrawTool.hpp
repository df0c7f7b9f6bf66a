#pragma once
/// \file DrawTool.hpp
/// Draws a polygon (a new region) or a polyline (a new joint) in a ModelView: left clicks add
/// snapped vertices, a double-click or Enter finishes, Escape cancels. A rubber band follows
/// the cursor. When finished it emits the points; the window turns them into a command.
/// Shape::Point finishes at the first click (fixed points, point loads, measurement points),
/// Shape::Segment at the second (rollers, edge pressures).

#include "model/Model.hpp"
#include "tools/Snap.hpp"
#include "tools/ViewTool.hpp"

#include <QObject>

#include <functional>
#include <vector>

namespace mcdda::gui {

class ModelView;

class DrawTool : public QObject, public ViewTool {
    Q_OBJECT

public:
    enum class Shape { Polygon, Polyline, Point, Segment };

    /// `model` gives the model whose vertices attract the cursor.
    DrawTool(Shape shape, ModelView* view, std::function<const Model&()> model, QObject* parent = nullptr);

    Shape shape() const { return shape_; }
    void setSnapOptions(const SnapOptions& options) { snap_ = options; }
    SnapOptions snapOptions() const { return snap_; }
    /// Draws the rubber band as a query line (dark, white halo, end markers) rather than blue.
    void setEmphasisedPreview(bool on) { emphasised_ = on; }
    /// Pixels within which an existing vertex attracts the cursor.
    void setVertexTolerancePixels(double pixels) { tolerance_px_ = pixels; }
    /// The vertices placed so far.
    const std::vector<Point2>& points() const { return points_; }
    /// Where a click at `widget_pos` would put a vertex.
    Point2 snapped(const QPointF& widget_pos) const;

    /// Places a vertex at `p` (model coordinates, not snapped) as a click there does: a typed
    /// point. A click goes through here after snapping.
    void addPoint(const Point2& p);

    /// Finishes the shape (as a double-click or Enter); false when it has too few vertices.
    bool finish();

    bool pressed(const QPointF& widget_pos) override;
    void moved(const QPointF& widget_pos) override;
    void doubleClicked(const QPointF& widget_pos) override;
    bool keyPressed(int key) override;
    void cancel() override;

signals:
    /// The first vertex of a new shape was placed.
    void started();
    /// A polygon was closed (counter-clockwise, ≥ 3 vertices), a polyline finished (≥ 2), a
    /// point placed (1) or a segment drawn (2).
    void finished(const std::vector<mcdda::Point2>& points);

private:
    void updatePreview();
    std::size_t needed() const;

    Shape shape_;
    ModelView* view_;
    std::function<const Model&()> model_;
    SnapOptions snap_;
    double tolerance_px_ = 6.0;
    std::vector<Point2> points_;
    Point2 cursor_;
    bool has_cursor_ = false;
    bool emphasised_ = false;
};

}  // namespace mcdda::gui
