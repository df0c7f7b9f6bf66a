#pragma once
/// \file SelectTool.hpp
/// The Select tool: a click picks the item or vertex under the cursor (drawn highlighted), a
/// drag moves it (snapped like drawing), Delete removes it, Escape drops the selection. A
/// click on empty space leaves the left button to the view, which pans. The tool only asks:
/// the window turns moveRequested/deleteRequested into undoable document edits.

#include "document/ModelItems.hpp"
#include "model/Model.hpp"
#include "tools/Snap.hpp"
#include "tools/ViewTool.hpp"

#include <QObject>

#include <functional>

namespace mcdda::gui {

class ModelView;

class SelectTool : public QObject, public ViewTool {
    Q_OBJECT

public:
    SelectTool(ModelView* view, std::function<const Model&()> model, QObject* parent = nullptr);

    ItemRef selection() const { return selection_; }
    /// Selects (and highlights) `ref`; an invalid reference clears the selection.
    void select(const ItemRef& ref);
    /// The model changed: drops a selection that no longer exists, else redraws its highlight.
    void refresh();

    void setSnapOptions(const SnapOptions& options) { snap_ = options; }
    /// Pixels within which a vertex or line is picked.
    void setTolerancePixels(double pixels) { tolerance_px_ = pixels; }

    bool pressed(const QPointF& widget_pos) override;
    void moved(const QPointF& widget_pos) override;
    void released(const QPointF& widget_pos) override;
    bool keyPressed(int key) override;
    void cancel() override;
    Qt::CursorShape cursorShape() const override { return Qt::ArrowCursor; }

signals:
    void selectionChanged(const mcdda::gui::ItemRef& ref);
    /// A drag ended: move `ref` by `delta` (m).
    void moveRequested(const mcdda::gui::ItemRef& ref, const mcdda::Point2& delta);
    /// Delete was pressed with `ref` selected.
    void deleteRequested(const mcdda::gui::ItemRef& ref);

private:
    /// The drag's offset for the cursor at `widget_pos`: the gripped point lands snapped.
    Point2 dragDelta(const QPointF& widget_pos) const;
    void highlight(const Point2& delta);

    ModelView* view_;
    std::function<const Model&()> model_;
    SnapOptions snap_;
    double tolerance_px_ = 6.0;
    ItemRef selection_;
    bool pressing_ = false;   ///< the left button went down on the selection
    bool dragging_ = false;   ///< ... and the cursor has since moved beyond a few pixels
    QPointF press_pos_;
    Point2 press_model_;
    Point2 delta_;
};

}  // namespace mcdda::gui
