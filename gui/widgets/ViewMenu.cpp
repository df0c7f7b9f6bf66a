#include "widgets/ViewMenu.hpp"

#include "widgets/ModelView.hpp"

#include <QDockWidget>
#include <QIcon>
#include <QKeySequence>

namespace mcdda::gui {

ViewMenu::ViewMenu(ModelView* view, QWidget* parent) : QMenu(tr("&View"), parent), view_(view)
{
    QAction* fit = addAction(tr("&Fit"), view_, &ModelView::fitView);
    fit->setShortcut(QKeySequence(Qt::Key_F));
    fit->setIcon(QIcon(QStringLiteral(":/icons/fit-view.svg")));
    fit->setStatusTip(tr("Show the whole model"));
    addSeparator();
    auto toggle = [&](const QString& text, const QString& tip) {
        QAction* action = addAction(text);
        action->setCheckable(true);
        action->setChecked(true);
        action->setStatusTip(tip);
        connect(action, &QAction::toggled, this, &ViewMenu::apply);
        return action;
    };
    show_mesh_ = toggle(tr("&Mesh"), tr("Show the element edges"));
    show_joints_ = toggle(tr("&Joints"), tr("Show the joint traces"));
    show_supports_ = toggle(tr("&Supports"), tr("Show fixed points and rollers"));
    show_loads_ = toggle(tr("&Loads"), tr("Show point loads and edge pressures"));
    show_points_ = toggle(tr("Measurement &points"), tr("Show the measurement points"));
    show_legend_ = toggle(tr("Le&gend"), tr("Show the legend"));
    addSeparator();
    snap_ = addAction(tr("Snap to &Grid"));
    snap_->setObjectName(QStringLiteral("snapToGridAction"));
    snap_->setCheckable(true);
    snap_->setChecked(true);
    snap_->setStatusTip(tr("Drawn points snap to a grid (0.5 m) and to nearby region vertices"));
    connect(snap_, &QAction::toggled, this, &ViewMenu::snappingChanged);
    addSeparator();
}

void ViewMenu::addDocks(std::initializer_list<QDockWidget*> docks)
{
    for (QDockWidget* dock : docks) addAction(dock->toggleViewAction());
}

void ViewMenu::showMesh() { show_mesh_->setChecked(true); }

bool ViewMenu::snapping() const { return snap_->isChecked(); }

void ViewMenu::apply()
{
    view::SceneOptions options = view_->sceneOptions();
    options.show_mesh = show_mesh_->isChecked();
    options.show_joints = show_joints_->isChecked();
    options.show_supports = show_supports_->isChecked();
    options.show_loads = show_loads_->isChecked();
    options.show_points = show_points_->isChecked();
    options.show_legend = show_legend_->isChecked();
    view_->setSceneOptions(options);
}

}  // namespace mcdda::gui
