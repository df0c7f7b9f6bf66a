#include "tools/EditingTools.hpp"

#include "dialogs/JointSetDialog.hpp"
#include "document/ModelDocument.hpp"
#include "tools/DrawTool.hpp"
#include "tools/SelectTool.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QKeyEvent>
#include <QActionGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGuiApplication>
#include <QIcon>
#include <QKeySequence>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QPainter>
#include <QPixmap>
#include <QRegularExpression>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>
#include <QWidgetAction>

#include <algorithm>
#include <cmath>

namespace mcdda::gui {

namespace {

/// A number typed with a decimal point or a decimal comma ("2.5" or "2,5").
bool parse_number(QString text, double* value)
{
    text.replace(QLatin1Char(','), QLatin1Char('.'));
    bool ok = false;
    *value = text.toDouble(&ok);
    return ok && std::isfinite(*value);
}

/// "x, y", "x y" or "x; y" — the last two also with decimal commas ("2,5; -1" or "2,5 -1").
bool parse_point(QString text, Point2* p)
{
    // "x, y" with a space after the comma would split on the space: the comma is a separator.
    text.replace(QRegularExpression(QStringLiteral("\\s*,\\s+")), QStringLiteral(";"));
    QStringList parts = text.split(QLatin1Char(';'));
    if (parts.size() != 2) parts = text.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts);
    if (parts.size() != 2) parts = text.split(QLatin1Char(','));
    if (parts.size() != 2) return false;
    return parse_number(parts[0].trimmed(), &p->x) && parse_number(parts[1].trimmed(), &p->y);
}

/// The Absorbing Boundary tool's icon, a dashpot under a dashed line, painted here (the
/// SVG icons under resources/ are the drawn tools' of before earthquakes).
QIcon dashpot_icon()
{
    QIcon icon;
    for (int size : {24, 48}) {
        QPixmap pixmap(size, size);
        pixmap.fill(Qt::transparent);
        QPainter p(&pixmap);
        p.setRenderHint(QPainter::Antialiasing);
        p.scale(size / 24.0, size / 24.0);
        QPen pen(QColor(191, 13, 128), 1.6);
        p.setPen(pen);
        for (double x = 2; x < 22; x += 5) p.drawLine(QPointF(x, 4), QPointF(x + 3, 4));  // the dashed boundary
        p.drawLine(QPointF(12, 4), QPointF(12, 11));                                 // rod
        p.drawLine(QPointF(9, 11), QPointF(15, 11));                                 // piston
        p.drawPolyline(QPolygonF({QPointF(8, 9), QPointF(8, 16), QPointF(16, 16), QPointF(16, 9)}));  // cylinder
        p.drawLine(QPointF(12, 16), QPointF(12, 20));
        p.drawLine(QPointF(6, 20), QPointF(18, 20));  // ground
        for (double x = 7; x < 18; x += 3.5) p.drawLine(QPointF(x + 2, 20), QPointF(x, 23));
        p.end();
        icon.addPixmap(pixmap);
    }
    return icon;
}

}  // namespace

EditingTools::EditingTools(QMainWindow* window, ModelView* view, ModelDocument* document)
    : QObject(window), window_(window), view_(view), document_(document)
{
    region_tool_ = makeTool(int(DrawTool::Shape::Polygon),
                            [this](const std::vector<Point2>& points) { applyRegion(points); });
    joint_tool_ = makeTool(int(DrawTool::Shape::Polyline), [this](const std::vector<Point2>& points) {
        document_->addJoint(points);
    });
    fixed_tool_ = makeTool(int(DrawTool::Shape::Point), [this](const std::vector<Point2>& points) {
        FixedPoint f;
        f.point = points.front();
        document_->addFixedPoint(f);
    });
    roller_tool_ = makeTool(int(DrawTool::Shape::Segment), [this](const std::vector<Point2>& points) {
        Roller r;
        r.from = points.front();
        r.to = points.back();
        const QString fix = roller_fix_box_->currentData().toString();
        r.fix_x = fix.contains(QLatin1Char('x'));
        r.fix_y = fix.contains(QLatin1Char('y'));
        document_->addRoller(r);
    });
    load_tool_ = makeTool(int(DrawTool::Shape::Point), [this](const std::vector<Point2>& points) {
        PointLoad l;
        l.point = points.front();
        l.force = {load_fx_->value() * 1e3, load_fy_->value() * 1e3};  // kN/m → N/m
        document_->addPointLoad(l);
    });
    pressure_tool_ = makeTool(int(DrawTool::Shape::Segment), [this](const std::vector<Point2>& points) {
        EdgePressure e;
        e.from = points.front();
        e.to = points.back();
        e.pressure = pressure_box_->value() * 1e3;  // kPa → Pa
        document_->addEdgePressure(e);
    });
    point_tool_ = makeTool(int(DrawTool::Shape::Point), [this](const std::vector<Point2>& points) {
        MeasurementPoint q;
        q.point = points.front();
        document_->addMeasurementPoint(q);
    });
    bolt_tool_ = makeTool(int(DrawTool::Shape::Segment), [this](const std::vector<Point2>& points) {
        Model m = document_->model();
        Bolt b;
        b.name = tr("bolt %1").arg(m.bolts.size() + 1).toStdString();
        b.from = points.front();
        b.to = points.back();
        // A fully grouted 25 mm bar every metre: EA = 200 GPa × 491 mm², yield about 160 kN.
        b.stiffness = 9.8e7;
        b.strength = 1.6e5;
        m.bolts.push_back(b);
        document_->replaceModel(m, tr("Add bolt \"%1\"").arg(QString::fromStdString(b.name)));
    });
    // Two clicks on the result picture; the tool stays for the next line.
    query_tool_ = makeTool(int(DrawTool::Shape::Segment), [this](const std::vector<Point2>& points) {
        emit queryLineDrawn(points.front(), points.back());
    });
    query_tool_->setEmphasisedPreview(true);  // a blue band vanished on the rainbow's blue end
    water_tool_ = makeTool(int(DrawTool::Shape::Polyline),
                           [this](const std::vector<Point2>& points) { applyWaterTable(points); });
    absorbing_tool_ = makeTool(int(DrawTool::Shape::Segment), [this](const std::vector<Point2>& points) {
        AbsorbingBoundary a;
        a.from = points.front();
        a.to = points.back();
        document_->addAbsorbingBoundary(a);
    });
    base_tool_ = makeTool(int(DrawTool::Shape::Segment), [this](const std::vector<Point2>& points) {
        BaseMotion b = document_->model().base_motion;
        if (b.x < 0 && b.y < 0) {  // the panel keeps a base with a record; drawn first, it takes the first one
            if (document_->model().ground_motions.empty()) return;
            b.x = 0;
        }
        b.kind = BaseMotion::Kind::Compliant;
        b.from = points.front();
        b.to = points.back();
        document_->setBaseMotion(b);
        useSelect();  // one base: the tool is done
    });
    connect(region_tool_, &DrawTool::started, this, [this] {
        hole_shift_ = QGuiApplication::keyboardModifiers().testFlag(Qt::ShiftModifier);
    });
    select_tool_ = new SelectTool(view_, [this]() -> const Model& { return document_->model(); }, this);
    connect(select_tool_, &SelectTool::moveRequested, this, [this](const ItemRef& ref, const Point2& delta) {
        if (!document_->moveItem(ref, delta) && ref.kind == ItemRef::Kind::WaterTable)
            tell(tr("The water table must run from left to right: a point cannot be moved past its neighbour."));
    });
    connect(select_tool_, &SelectTool::deleteRequested, this, &EditingTools::deleteItem);
    connect(select_tool_, &SelectTool::selectionChanged, this, [this](const ItemRef& ref) {
        if (delete_action_) delete_action_->setEnabled(ref.valid());
        emit selectionChanged(ref);
    });
    setSnapping(true, grid_spacing_);
    view_->setTool(select_tool_);
}

DrawTool* EditingTools::makeTool(int shape, std::function<void(const std::vector<Point2>&)> apply)
{
    auto* tool = new DrawTool(static_cast<DrawTool::Shape>(shape), view_,
                              [this]() -> const Model& { return document_->model(); }, this);
    connect(tool, &DrawTool::finished, this, std::move(apply));
    return tool;
}

void EditingTools::createActions(QMenu* edit)
{
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(QIcon(QStringLiteral(":/icons/undo.svg")));
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setIcon(QIcon(QStringLiteral(":/icons/redo.svg")));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    // Each tool named under its icon, on a row of its own: icons alone were mistaken for one
    // another (Fixed Point for Roller). Along the top rather than down the side, where it took
    // the picture's width.
    QToolBar* bar = window_->addToolBar(tr("Tools"));
    bar->setObjectName(QStringLiteral("tools"));
    bar->setToolButtonStyle(Qt::ToolButtonTextUnderIcon);
    bar->setIconSize(QSize(20, 20));
    auto* group = new QActionGroup(this);
    auto tool = [&](const QString& text, const QString& name, const QString& icon, const QString& tip,
                    void (EditingTools::*slot)()) {
        QAction* action = edit->addAction(text, this, slot);
        if (!icon.isEmpty()) action->setIcon(QIcon(QStringLiteral(":/icons/") + icon + QStringLiteral(".svg")));
        action->setObjectName(name);
        action->setCheckable(true);
        action->setStatusTip(tip);
        action->setToolTip(QStringLiteral("<b>%1</b><br>%2").arg(QString(text).remove(QLatin1Char('&')), tip));
        group->addAction(action);
        bar->addAction(action);
        return action;
    };
    select_action_ = tool(tr("&Select"), QStringLiteral("selectToolAction"), QStringLiteral("select"),
                          tr("Click an item or a vertex to select it, drag it to move it, Delete removes it; "
                             "drag empty space to pan"),
                          &EditingTools::useSelect);
    QAction* region = tool(tr("Draw &Region"), QStringLiteral("drawRegionAction"), QStringLiteral("draw-region"),
                           tr("Click the corners of a new region; double-click or Enter closes it, Escape cancels"),
                           &EditingTools::useRegion);
    QAction* joint = tool(tr("Draw &Joint"), QStringLiteral("drawJointAction"), QStringLiteral("draw-joint"),
                          tr("Click the points of a new joint; double-click or Enter finishes it, Escape cancels"),
                          &EditingTools::useJoint);
    bar->addSeparator();
    QAction* fixed = tool(tr("&Fixed Point"), QStringLiteral("fixedPointAction"), QStringLiteral("fixed-point"),
                          tr("Click where the mesh is held in both directions"), &EditingTools::useFixedPoint);
    QAction* roller = tool(tr("R&oller"), QStringLiteral("rollerAction"), QStringLiteral("roller"),
                           tr("Click the two ends of a roller; the fixed directions are chosen in Tool Options"),
                           &EditingTools::useRoller);
    QAction* load = tool(tr("Point &Load"), QStringLiteral("pointLoadAction"), QStringLiteral("point-load"),
                         tr("Click where a point load acts; its force is set in Tool Options"),
                         &EditingTools::usePointLoad);
    QAction* pressure = tool(tr("Edge &Pressure"), QStringLiteral("edgePressureAction"), QStringLiteral("edge-pressure"),
                             tr("Click the two ends of a loaded edge; the pressure is set in Tool Options"),
                             &EditingTools::useEdgePressure);
    QAction* point = tool(tr("&Measurement Point"), QStringLiteral("measurementPointAction"),
                          QStringLiteral("measurement-point"), tr("Click where displacements are recorded"),
                          &EditingTools::useMeasurementPoint);
    QAction* bolt = tool(tr("&Bolt"), QStringLiteral("boltAction"), QStringLiteral("bolt"),
                         tr("Click the two anchors of a rock bolt (EA 98 MN/m, breaking at 160 kN/m per metre of "
                            "thickness; other values and the stage that installs it are set in the model file)"),
                         &EditingTools::useBolt);
    QAction* water = tool(tr("Draw &Water Table"), QStringLiteral("waterTableAction"), QStringLiteral("water-table"),
                          tr("Click the points of the water table (piezometric line) from left to right; double-click "
                             "or Enter finishes it. It is the water of the stage chosen in the Stages dock, or of the "
                             "model as drawn"),
                          &EditingTools::useWaterTable);
    QAction* absorbing = tool(tr("&Absorbing Boundary"), QStringLiteral("absorbingBoundaryAction"), QString(),
                              tr("Click the two ends of a boundary whose dashpots let the earthquake's waves out "
                                 "instead of reflecting them (no support may hold it in a dynamic stage)"),
                              &EditingTools::useAbsorbingBoundary);
    absorbing->setIcon(dashpot_icon());
    bar->addSeparator();
    QAction* query = tool(tr("&Query Line"), QStringLiteral("queryLineAction"), QStringLiteral("query-line"),
                          tr("Click the two ends of a line across the result picture: the Query dock plots the "
                             "field shown along it"),
                          &EditingTools::useQueryLine);
    edit->addSeparator();
    delete_action_ = edit->addAction(tr("&Delete"), this, [this] { deleteItem(select_tool_->selection()); });
    delete_action_->setObjectName(QStringLiteral("deleteAction"));
    delete_action_->setShortcut(QKeySequence::Delete);
    // Only where it is added (the view, the Model tree): Delete keeps deleting characters in forms.
    delete_action_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    delete_action_->setStatusTip(tr("Delete the selected item or vertex"));
    delete_action_->setEnabled(false);
    view_->addAction(delete_action_);
    QAction* joint_set = edit->addAction(tr("Add Joint Se&t..."), this, &EditingTools::addJointSetDialog);
    joint_set->setObjectName(QStringLiteral("addJointSetAction"));
    joint_set->setStatusTip(tr("Add a family of parallel joints"));
    // Short names beside the icons, so the palette stays narrow (the menu keeps the long ones).
    region->setIconText(tr("Region"));
    joint->setIconText(tr("Joint"));
    pressure->setIconText(tr("Pressure"));
    point->setIconText(tr("Measurement"));
    water->setIconText(tr("Water Table"));
    absorbing->setIconText(tr("Absorbing"));
    tool_actions_ = {{region_tool_, region}, {joint_tool_, joint}, {fixed_tool_, fixed}, {roller_tool_, roller},
                     {load_tool_, load},     {pressure_tool_, pressure}, {point_tool_, point},
                     {query_tool_, query},   {bolt_tool_, bolt},         {water_tool_, water},
                     {absorbing_tool_, absorbing}};
    select_action_->setChecked(true);
    createToolOptions();
}

void EditingTools::createToolOptions()
{
    window_->addToolBarBreak();  // under the tools, whatever the width of the active tool's options
    QToolBar* bar = window_->addToolBar(tr("Tool Options"));
    bar->setObjectName(QStringLiteral("toolOptions"));
    // Each widget belongs to one tool and shows only while that tool is active (null: every
    // drawing tool); the bar always starts with the active tool's name.
    DrawTool* owner = nullptr;
    auto add = [&](QWidget* widget) { option_actions_.push_back({owner, bar->addWidget(widget)}); };
    auto label = [&](const QString& text) {
        auto* l = new QLabel(text, bar);
        l->setContentsMargins(6, 0, 2, 0);
        add(l);
    };
    tool_name_ = new QLabel(bar);
    tool_name_->setObjectName(QStringLiteral("activeToolName"));
    tool_name_->setContentsMargins(6, 0, 6, 0);
    QFont bold = tool_name_->font();
    bold.setBold(true);
    tool_name_->setFont(bold);
    bar->addWidget(tool_name_);
    owner = roller_tool_;
    label(tr("Roller fixes"));
    roller_fix_box_ = new QComboBox(bar);
    roller_fix_box_->setObjectName(QStringLiteral("rollerFixBox"));
    roller_fix_box_->setToolTip(tr("Directions a new roller holds"));
    roller_fix_box_->addItem(tr("y"), QStringLiteral("y"));
    roller_fix_box_->addItem(tr("x"), QStringLiteral("x"));
    roller_fix_box_->addItem(tr("x and y"), QStringLiteral("xy"));
    add(roller_fix_box_);
    auto spin = [&](const QString& name, const QString& unit, double value, const QString& tip) {
        auto* box = new QDoubleSpinBox(bar);
        box->setObjectName(name);
        box->setRange(-1e9, 1e9);
        box->setDecimals(3);
        box->setValue(value);
        box->setSuffix(QLatin1Char(' ') + unit);
        box->setToolTip(tip);
        add(box);
        return box;
    };
    owner = load_tool_;
    label(tr("Load Fx"));
    load_fx_ = spin(QStringLiteral("loadFxBox"), tr("kN/m"), 0.0, tr("Horizontal force of a new point load"));
    label(tr("Fy"));
    load_fy_ = spin(QStringLiteral("loadFyBox"), tr("kN/m"), -1.0, tr("Vertical force of a new point load"));
    owner = pressure_tool_;
    label(tr("Pressure"));
    pressure_box_ = spin(QStringLiteral("pressureBox"), tr("kPa"), 100.0,
                         tr("Pressure of a new edge load (positive pushes into the material)"));
    owner = water_tool_;
    label(tr("γw"));
    water_weight_box_ = spin(QStringLiteral("waterUnitWeightBox"), tr("kN/m³"), 9.81,
                             tr("Unit weight of water of a new water table (fresh water 9.81 kN/m³)"));
    water_weight_box_->setRange(0.01, 100.0);
    owner = region_tool_;
    hole_box_ = new QCheckBox(tr("Hole"), bar);
    hole_box_->setObjectName(QStringLiteral("holeBox"));
    hole_box_->setToolTip(tr("Draw Region cuts an opening into the region around it (or hold Shift at the first click)"));
    add(hole_box_);
    owner = nullptr;
    label(tr("Point"));
    coordinate_edit_ = new QLineEdit(bar);
    coordinate_edit_->setObjectName(QStringLiteral("coordinateEdit"));
    coordinate_edit_->setPlaceholderText(tr("x, y"));
    coordinate_edit_->setToolTip(tr("Type a point as \"x, y\" (m) and press Enter to place it; Enter on an empty field finishes the shape"));
    coordinate_edit_->setMaximumWidth(140);
    coordinate_edit_->setEnabled(false);
    connect(coordinate_edit_, &QLineEdit::returnPressed, this, [this] {
        // setText, not clear(): the field keeps no undo step of its own for a placed point, so
        // Ctrl+Z there undoes the point (eventFilter).
        if (enterCoordinates(coordinate_edit_->text())) coordinate_edit_->setText(QString());
    });
    add(coordinate_edit_);
    coordinate_edit_->installEventFilter(this);
    // As tall as the tallest option, so the bar (and the picture under it) keeps its height
    // whichever tool's options show.
    int tallest = 0;
    for (const auto& [owner, action] : option_actions_)
        if (auto* widget_action = qobject_cast<QWidgetAction*>(action))
            tallest = std::max(tallest, widget_action->defaultWidget()->sizeHint().height());
    tool_name_->setMinimumHeight(tallest);
    showToolOptions(nullptr);
}

void EditingTools::showToolOptions(DrawTool* tool)
{
    for (const auto& [owner, action] : option_actions_) action->setVisible(tool && (owner == nullptr || owner == tool));
    QString name = tr("Select");
    for (const auto& [t, a] : tool_actions_)
        if (t == tool) name = a->iconText();
    if (tool == base_tool_) name = tr("Compliant Base");
    tool_name_->setText(tool ? name : tr("Select: no options"));
}

QStringList EditingTools::visibleToolOptions() const
{
    QStringList names;
    for (const auto& [owner, action] : option_actions_)
        if (action->isVisible())
            if (auto* widget_action = qobject_cast<QWidgetAction*>(action))
                if (QWidget* w = widget_action->defaultWidget(); w && !w->objectName().isEmpty()) names << w->objectName();
    return names;
}

bool EditingTools::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == coordinate_edit_ && event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        const bool undo = key->matches(QKeySequence::Undo) && !coordinate_edit_->isUndoAvailable();
        const bool redo = key->matches(QKeySequence::Redo) && !coordinate_edit_->isRedoAvailable();
        if (undo || redo) {
            event->ignore();  // not overridden: the window's Undo/Redo shortcut fires
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

void EditingTools::tell(const QString& text)
{
    emit message(text);
    window_->statusBar()->showMessage(text, 5000);
}

void EditingTools::applyRegion(const std::vector<Point2>& points)
{
    const bool hole = hole_shift_ || (hole_box_ && hole_box_->isChecked());
    hole_shift_ = false;
    if (!hole) {
        document_->addRegion(points, document_->model().materials.empty() ? -1 : 0);
        return;
    }
    const int region = document_->regionContaining(points);
    if (region < 0) {
        tell(tr("The hole was not added: no region contains it."));
        return;
    }
    document_->addHole(region, points);
}

void EditingTools::applyWaterTable(const std::vector<Point2>& points)
{
    // One level at each x, as the solver needs: a line that folds back is refused here, in plain
    // words, rather than later by the model checker. The tool stays for the next try.
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (points[i].x > points[i - 1].x) continue;
        tell(points[i].x == points[i - 1].x
                 ? tr("The water table must run from left to right: point %1 is straight above or below point %2. "
                      "Draw it again.").arg(i + 1).arg(i)
                 : tr("The water table must run from left to right: point %1 is left of point %2. Draw it again.")
                       .arg(i + 1)
                       .arg(i));
        return;
    }
    Water water;
    water.piezometric_line = points;
    water.unit_weight = water_weight_box_->value() * 1e3;  // kN/m³ → N/m³
    const int stage = view_->sceneOptions().stage;
    const bool staged = stage >= 0 && stage < static_cast<int>(document_->model().stages.size());
    document_->setWater(staged ? stage : -1, water);
}

bool EditingTools::enterCoordinates(const QString& text)
{
    DrawTool* tool = activeTool();
    if (!tool) return false;
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty()) return tool->finish();
    Point2 p;
    if (!parse_point(trimmed, &p)) {
        window_->statusBar()->showMessage(
            tr("Type a point as \"x, y\" in metres, e.g. \"2.5, -1\" (or \"2,5; -1\")"), 5000);
        return false;
    }
    // The view follows typed points (clicked ones are in sight already): the shape drawn so
    // far, or the item the point finished.
    std::vector<Point2> shape = tool->points();
    tool->addPoint(p);
    shape.push_back(p);
    view_->keepInView(shape);
    return true;
}

void EditingTools::addJointSetDialog()
{
    JointSetDialog dialog(document_->model(), window_);
    if (dialog.exec() == QDialog::Accepted) document_->addJointSet(dialog.jointSet());
}

DrawTool* EditingTools::activeTool() const { return dynamic_cast<DrawTool*>(view_->tool()); }

ItemRef EditingTools::selection() const { return select_tool_->selection(); }

void EditingTools::setTool(DrawTool* tool)
{
    if (view_->tool() == select_tool_ && tool) select_tool_->cancel();
    view_->setTool(tool ? static_cast<ViewTool*>(tool) : select_tool_);
    QAction* action = select_action_;
    for (const auto& [t, a] : tool_actions_)
        if (t == tool) action = a;
    if (action) action->setChecked(true);
    if (coordinate_edit_) coordinate_edit_->setEnabled(tool != nullptr);
    if (tool_name_) showToolOptions(tool);
    hole_shift_ = false;
    setSnapping(snap_grid_, grid_spacing_);  // the grid shows with the drawing tools
    if (tool) {
        if (tool != query_tool_) view_->clearResult();  // drawing edits the model; a query reads the result
        view_->setFocus();
    }
}

void EditingTools::useSelect() { setTool(nullptr); }
void EditingTools::useRegion() { setTool(region_tool_); }
void EditingTools::useJoint() { setTool(joint_tool_); }
void EditingTools::useFixedPoint() { setTool(fixed_tool_); }
void EditingTools::useRoller() { setTool(roller_tool_); }
void EditingTools::usePointLoad() { setTool(load_tool_); }
void EditingTools::useEdgePressure() { setTool(pressure_tool_); }
void EditingTools::useMeasurementPoint() { setTool(point_tool_); }
void EditingTools::useQueryLine() { setTool(query_tool_); }
void EditingTools::useBolt() { setTool(bolt_tool_); }
void EditingTools::useWaterTable() { setTool(water_tool_); }
void EditingTools::useAbsorbingBoundary() { setTool(absorbing_tool_); }

void EditingTools::useCompliantBase()
{
    if (document_->model().ground_motions.empty()) {
        tell(tr("Import a ground motion first (Earthquake dock): the compliant base is where it enters the model."));
        return;
    }
    setTool(base_tool_);
    window_->statusBar()->showMessage(tr("Click the two ends of the compliant base"), 5000);
}

void EditingTools::selectItem(const ItemRef& ref)
{
    if (view_->tool() != select_tool_) useSelect();
    select_tool_->select(ref);
}

bool EditingTools::deleteItem(const ItemRef& ref)
{
    const QString name = document_->itemName(ref);
    if (document_->deleteItem(ref)) return true;
    if (ref.valid()) tell(tr("%1 was not deleted: a region or hole keeps at least three vertices.").arg(name));
    return false;
}

void EditingTools::documentChanged() { select_tool_->refresh(); }

void EditingTools::setSnapping(bool grid, double spacing)
{
    snap_grid_ = grid;
    if (spacing > 0.0) grid_spacing_ = spacing;
    SnapOptions options;
    options.grid = snap_grid_;
    options.spacing = grid_spacing_;
    // Not over a result: the query line reads the picture, a grid across it only hides it.
    view_->setGridSpacing(options.grid && activeTool() && activeTool() != query_tool_ ? grid_spacing_ : 0.0);
    for (DrawTool* tool : {region_tool_, joint_tool_, fixed_tool_, roller_tool_, load_tool_, pressure_tool_, point_tool_,
                           query_tool_, bolt_tool_, water_tool_, absorbing_tool_, base_tool_})
        tool->setSnapOptions(options);
    select_tool_->setSnapOptions(options);
}

}  // namespace mcdda::gui
