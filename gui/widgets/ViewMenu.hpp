#pragma once
/// \file ViewMenu.hpp
/// View: fit, what the picture shows (mesh, joints, supports, loads, measurement points,
/// legend), snapping to the grid, and the docks. The show toggles are applied to the view
/// directly.

#include <QMenu>

#include <initializer_list>

class QDockWidget;

namespace mcdda::gui {

class ModelView;

class ViewMenu : public QMenu {
    Q_OBJECT

public:
    ViewMenu(ModelView* view, QWidget* parent);

    /// Adds the docks' show/hide actions at the end.
    void addDocks(std::initializer_list<QDockWidget*> docks);
    /// Shows the element edges (Run ▸ Mesh: what was asked for is seen).
    void showMesh();
    /// Whether drawing snaps to the grid.
    bool snapping() const;

signals:
    void snappingChanged(bool snap);

private:
    void apply();

    ModelView* view_ = nullptr;
    QAction* show_mesh_ = nullptr;
    QAction* show_joints_ = nullptr;
    QAction* show_supports_ = nullptr;
    QAction* show_loads_ = nullptr;
    QAction* show_points_ = nullptr;
    QAction* show_legend_ = nullptr;
    QAction* snap_ = nullptr;
};

}  // namespace mcdda::gui
