#pragma once
/// \file ViewTool.hpp
/// What a ModelView hands its left-button clicks, cursor moves and keys to while an editing
/// tool is active (the middle button and the wheel keep navigating). Positions are in widget
/// (logical) pixels; the tool converts them with ModelView::toModel().

#include <QPointF>
#include <Qt>

namespace mcdda::gui {

class ViewTool {
public:
    virtual ~ViewTool() = default;
    /// The left button went down; false leaves it to the view (which pans).
    virtual bool pressed(const QPointF& widget_pos) = 0;
    /// The left button went up.
    virtual void released(const QPointF& /*widget_pos*/) {}
    /// The cursor moved (with or without a button).
    virtual void moved(const QPointF& /*widget_pos*/) {}
    /// A left double-click (its first press came through pressed()).
    virtual void doubleClicked(const QPointF& /*widget_pos*/) {}
    /// A key; true when the tool used it.
    virtual bool keyPressed(int /*key*/) { return false; }
    /// Drop whatever is half done (e.g. when another tool is chosen).
    virtual void cancel() {}
    /// The cursor over the view while the tool is active.
    virtual Qt::CursorShape cursorShape() const { return Qt::CrossCursor; }
};

}  // namespace mcdda::gui
