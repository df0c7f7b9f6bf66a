#pragma once
/// \file EditingTools.hpp
/// The editing side of the main window: the Select tool and the drawing tools (regions and
/// holes, joints, fixed points, rollers, point loads, edge pressures, measurement points, the
/// water table), their
/// entries in Edit and the Tools toolbar, the Tool Options toolbar (roller directions, values of
/// new loads, the unit weight of water, Hole, typed coordinates), grid snapping, Edit ▸ Delete and Edit ▸ Add Joint Set.
/// Finished shapes, drags and deletions become undoable edits of the document.

#include "document/ModelItems.hpp"
#include "model/Model.hpp"

#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>
#include <utility>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QMainWindow;
class QMenu;

namespace mcdda::gui {

class DrawTool;
class ModelDocument;
class ModelView;
class SelectTool;

class EditingTools : public QObject {
    Q_OBJECT

public:
    /// Tools for `view` that edit `document`; toolbars and messages go to `window`.
    EditingTools(QMainWindow* window, ModelView* view, ModelDocument* document);

    /// Adds Undo, Redo, the tool, Delete and Add Joint Set entries to `edit` and the Tools and Tool Options
    /// toolbars to the window.
    void createActions(QMenu* edit);

    /// The active drawing tool (null while Select is active).
    DrawTool* activeTool() const;
    SelectTool* selectTool() const { return select_tool_; }
    /// The selected item or vertex (invalid when none).
    ItemRef selection() const;
    /// Edit ▸ Delete (enabled while something is selected).
    QAction* deleteAction() const { return delete_action_; }

    /// The object names of the Tool Options widgets shown now: only the active tool's (none for
    /// Select), e.g. "rollerFixBox" and "coordinateEdit" with the Roller tool.
    QStringList visibleToolOptions() const;

    /// Grid snapping on or off, and the grid's spacing (m); drawing tools show the grid.
    void setSnapping(bool grid, double spacing);

public slots:
    /// Makes Select the active tool / a drawing tool.
    void useSelect();
    void useRegion();
    void useJoint();
    void useFixedPoint();
    void useRoller();
    void usePointLoad();
    void useEdgePressure();
    void useMeasurementPoint();
    /// Edit ▸ Bolt: two clicks add a rock bolt between them (undoable).
    void useBolt();
    /// Edit ▸ Draw Water Table: a polyline drawn left to right becomes the piezometric line of
    /// the stage the picture shows (the Stages dock's choice), or of the model as drawn.
    void useWaterTable();
    /// Edit ▸ Absorbing Boundary: two clicks give a boundary of dashpots that lets waves out.
    void useAbsorbingBoundary();
    /// Two clicks give the compliant base, where the earthquake enters (the Earthquake dock's
    /// Draw button); refused with a message while the model has no ground motion.
    void useCompliantBase();
    /// Edit ▸ Query Line: two clicks on the result picture give queryLineDrawn().
    void useQueryLine();
    /// Makes Select the tool and selects `ref` (highlighted in the view).
    void selectItem(const ItemRef& ref);
    /// Deletes `ref` (undoable); false with a message when it cannot go.
    bool deleteItem(const ItemRef& ref);
    /// "x, y" (m; also "x; y" or "x y" with decimal commas) places a vertex as a click does;
    /// empty text finishes the shape. False when no drawing tool is active or the text is not
    /// two numbers.
    bool enterCoordinates(const QString& text);
    /// Asks for a joint set and adds it.
    void addJointSetDialog();
    /// The document changed: the selection follows (or goes when its item went).
    void documentChanged();

signals:
    void selectionChanged(const mcdda::gui::ItemRef& ref);
    /// A line for the window's log.
    void message(const QString& text);
    /// A query line was drawn from `from` to `to` (m).
    void queryLineDrawn(const mcdda::Point2& from, const mcdda::Point2& to);

protected:
    /// Ctrl+Z / Ctrl+Shift+Z in the coordinate field undo the model's last edit when the field
    /// itself has nothing to undo (a QLineEdit would swallow the keys and do nothing).
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    DrawTool* makeTool(int shape, std::function<void(const std::vector<Point2>&)> apply);
    void setTool(DrawTool* tool);
    void createToolOptions();
    /// Shows the Tool Options of `tool` (null: Select) and hides the others.
    void showToolOptions(DrawTool* tool);
    /// A drawn polygon: a new region, or a hole of the region holding it (Hole / Shift).
    void applyRegion(const std::vector<Point2>& points);
    /// A drawn polyline as the water table of the stage shown; refused (the tool stays for a
    /// new try) unless it runs left to right.
    void applyWaterTable(const std::vector<Point2>& points);
    void tell(const QString& text);

    QMainWindow* window_;
    ModelView* view_;
    ModelDocument* document_;
    SelectTool* select_tool_ = nullptr;
    DrawTool* region_tool_ = nullptr;
    DrawTool* joint_tool_ = nullptr;
    DrawTool* fixed_tool_ = nullptr;
    DrawTool* roller_tool_ = nullptr;
    DrawTool* load_tool_ = nullptr;
    DrawTool* pressure_tool_ = nullptr;
    DrawTool* point_tool_ = nullptr;
    DrawTool* query_tool_ = nullptr;
    DrawTool* bolt_tool_ = nullptr;
    DrawTool* water_tool_ = nullptr;
    DrawTool* absorbing_tool_ = nullptr;
    DrawTool* base_tool_ = nullptr;
    QAction* select_action_ = nullptr;
    QAction* delete_action_ = nullptr;
    std::vector<std::pair<DrawTool*, QAction*>> tool_actions_;
    QComboBox* roller_fix_box_ = nullptr;
    QDoubleSpinBox* load_fx_ = nullptr;
    QDoubleSpinBox* load_fy_ = nullptr;
    QDoubleSpinBox* pressure_box_ = nullptr;
    QDoubleSpinBox* water_weight_box_ = nullptr;  ///< γw of a new water table (kN/m³)
    QLineEdit* coordinate_edit_ = nullptr;
    QCheckBox* hole_box_ = nullptr;
    QLabel* tool_name_ = nullptr;  ///< the active tool, first in Tool Options
    /// Tool Options widgets and the tool each belongs to (null: every drawing tool).
    std::vector<std::pair<DrawTool*, QAction*>> option_actions_;
    bool hole_shift_ = false;  ///< Shift was held at the first click of the region being drawn
    bool snap_grid_ = true;
    double grid_spacing_ = 0.5;
};

}  // namespace mcdda::gui
