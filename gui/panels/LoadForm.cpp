#include "panels/LoadForm.hpp"

#include "document/EditCommands.hpp"
#include "document/ModelDocument.hpp"
#include "panels/FormFields.hpp"
#include "panels/PropertyEditor.hpp"
#include "session/DisplayUnits.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <string>

namespace mcdda::gui {

namespace {

using form::display;
using form::explain;
using form::number;
using form::set_status;
using form::si;
using form::status_label;
using form::to_qt;


bool same(const LoadTable& a, const LoadTable& b)
{
    return a.name == b.name && a.variable == b.variable && a.points == b.points && a.extrapolate == b.extrapolate;
}

bool same(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }

}  // namespace

LoadForm::LoadForm(ModelDocument* document, QWidget* parent) : QWidget(parent), document_(document)
{
    // Three groups and a table are taller than the dock: the tab scrolls.
    auto* content = new QWidget(this);
    auto* column = new QVBoxLayout(content);
    column->addWidget(createTableGroup());
    column->addWidget(createLoadGroup());
    column->addWidget(createGravityGroup());
    column->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // the fields follow the dock's width
    scroll->setWidget(content);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
    connect(document_, &ModelDocument::changed, this, &LoadForm::refresh);
    connect(DisplayUnits::instance(), &DisplayUnits::changed, this, &LoadForm::refresh);
    refresh();
}

// --- groups ------------------------------------------------------------------------------

QWidget* LoadForm::createTableGroup()
{
    auto* group = new QGroupBox(tr("Load tables"), this);
    auto* form = new QFormLayout(group);
    table_box_ = new QComboBox(group);
    explain(table_box_, tr("The load table shown below: a factor against time (or step) that loads may follow"));
    table_box_->setObjectName(QStringLiteral("loadTableBox"));
    table_box_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    table_box_->setMinimumContentsLength(8);
    connect(table_box_, &QComboBox::currentIndexChanged, this, [this] {
        if (!loading_) loadTable();
    });
    auto* add = new QPushButton(tr("New"), group);
    add->setObjectName(QStringLiteral("loadTableNew"));
    connect(add, &QPushButton::clicked, this, &LoadForm::newTable);
    table_delete_ = new QPushButton(tr("Delete"), group);
    table_delete_->setObjectName(QStringLiteral("loadTableDelete"));
    connect(table_delete_, &QPushButton::clicked, this, &LoadForm::deleteTable);
    auto* choose = new QHBoxLayout;
    choose->addWidget(table_box_, 1);
    choose->addWidget(add);
    choose->addWidget(table_delete_);
    form->addRow(tr("Table"), choose);

    tbl_name_ = new QLineEdit(group);
    explain(tbl_name_, tr("Name of the load table, as loads refer to it"));
    tbl_name_->setObjectName(QStringLiteral("loadTableName"));
    connect(tbl_name_, &QLineEdit::returnPressed, this, &LoadForm::applyTable);
    form->addRow(tr("Name"), tbl_name_);
    tbl_variable_ = new QComboBox(group);
    explain(tbl_variable_, tr("Whether the table's abscissa is the time (s) or the step number"));
    tbl_variable_->setObjectName(QStringLiteral("loadTableVariable"));
    tbl_variable_->addItem(tr("Step number"), static_cast<int>(LoadTable::Variable::Step));
    tbl_variable_->addItem(tr("Time"), static_cast<int>(LoadTable::Variable::Time));
    connect(tbl_variable_, &QComboBox::currentIndexChanged, this, [this] { updateTableHeaders(); });
    form->addRow(tr("Variable"), tbl_variable_);
    tbl_extrapolate_ = new QCheckBox(tr("Extrapolate (else hold the last factor)"), group);
    tbl_extrapolate_->setObjectName(QStringLiteral("loadTableExtrapolate"));
    explain(tbl_extrapolate_, tr("Beyond the last point, continue the last segment's slope"));
    form->addRow(QString(), tbl_extrapolate_);

    tbl_points_ = new QTableWidget(0, 2, group);
    tbl_points_->setObjectName(QStringLiteral("loadTablePoints"));
    tbl_points_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    tbl_points_->setSelectionBehavior(QAbstractItemView::SelectRows);
    tbl_points_->setMinimumHeight(120);
    tbl_points_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    form->addRow(tbl_points_);
    auto* add_row = new QPushButton(tr("Add Row"), group);
    add_row->setObjectName(QStringLiteral("loadTableAddRow"));
    connect(add_row, &QPushButton::clicked, this, &LoadForm::addTableRow);
    auto* remove_row = new QPushButton(tr("Remove Row"), group);
    remove_row->setObjectName(QStringLiteral("loadTableRemoveRow"));
    connect(remove_row, &QPushButton::clicked, this, &LoadForm::removeTableRow);
    auto* rows = new QHBoxLayout;
    rows->addWidget(add_row);
    rows->addWidget(remove_row);
    rows->addStretch(1);
    form->addRow(rows);

    auto* apply = new QPushButton(tr("Apply"), group);
    apply->setObjectName(QStringLiteral("loadTableApply"));
    connect(apply, &QPushButton::clicked, this, &LoadForm::applyTable);
    form->addRow(QString(), apply);
    tbl_status_ = status_label(QStringLiteral("loadTableStatus"), group);
    form->addRow(tbl_status_);
    table_fields_ = {table_delete_, tbl_name_, tbl_variable_, tbl_extrapolate_, tbl_points_, add_row, remove_row, apply};
    updateTableHeaders();
    return group;
}

QWidget* LoadForm::createLoadGroup()
{
    auto* group = new QGroupBox(tr("Point loads and edge pressures"), this);
    auto* form = new QFormLayout(group);
    load_box_ = new QComboBox(group);
    explain(load_box_, tr("The point load or edge pressure shown below"));
    load_box_->setObjectName(QStringLiteral("loadBox"));
    load_box_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    load_box_->setMinimumContentsLength(8);
    connect(load_box_, &QComboBox::currentIndexChanged, this, [this] {
        if (!loading_) loadLoad();
    });
    form->addRow(tr("Load"), load_box_);
    ld_fx_ = number(QStringLiteral("loadFx"), tr("kN/m"), -1e9, 1e9, 3, group);
    explain(ld_fx_, tr("x component of the point load, per metre out of plane"));
    form->addRow(tr("Force fx"), ld_fx_);
    ld_fy_ = number(QStringLiteral("loadFy"), tr("kN/m"), -1e9, 1e9, 3, group);
    explain(ld_fy_, tr("y component of the point load, per metre out of plane (negative = downwards)"));
    form->addRow(tr("Force fy"), ld_fy_);
    ld_pressure_ = number(QStringLiteral("loadPressure"), tr("kPa"), -1e9, 1e9, 3, group);
    explain(ld_pressure_, tr("Normal pressure; positive pushes into the material"));
    form->addRow(tr("Pressure"), ld_pressure_);
    ld_table_ = new QComboBox(group);
    ld_table_->setObjectName(QStringLiteral("loadTableChoice"));
    ld_table_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    ld_table_->setMinimumContentsLength(8);
    explain(ld_table_, tr("The table whose factor multiplies the load; constant = factor 1"));
    form->addRow(tr("Load table"), ld_table_);
    ld_apply_ = new QPushButton(tr("Apply"), group);
    ld_apply_->setObjectName(QStringLiteral("loadApply"));
    connect(ld_apply_, &QPushButton::clicked, this, &LoadForm::applyLoad);
    form->addRow(QString(), ld_apply_);
    ld_status_ = status_label(QStringLiteral("loadStatus"), group);
    form->addRow(ld_status_);
    for (QDoubleSpinBox* box : {ld_fx_, ld_fy_, ld_pressure_})
        form::apply_on_enter(box, [this] { if (!loading_) applyLoad(); });
    return group;
}

QWidget* LoadForm::createGravityGroup()
{
    auto* group = new QGroupBox(tr("Gravity"), this);
    auto* form = new QFormLayout(group);
    grav_x_ = number(QStringLiteral("gravityX"), tr("m/s²"), -1e3, 1e3, 4, group);
    explain(grav_x_, tr("x component of the acceleration of gravity"));
    form->addRow(tr("gx"), grav_x_);
    grav_y_ = number(QStringLiteral("gravityY"), tr("m/s²"), -1e3, 1e3, 4, group);
    explain(grav_y_, tr("y component of the acceleration of gravity (−9.81 m/s²: standard)"));
    form->addRow(tr("gy"), grav_y_);
    auto* standard = new QPushButton(tr("Standard (0, −9.81)"), group);
    standard->setObjectName(QStringLiteral("gravityStandard"));
    connect(standard, &QPushButton::clicked, this, &LoadForm::setStandardGravity);
    auto* apply = new QPushButton(tr("Apply"), group);
    apply->setObjectName(QStringLiteral("gravityApply"));
    connect(apply, &QPushButton::clicked, this, &LoadForm::applyGravity);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(standard);
    buttons->addWidget(apply);
    buttons->addStretch(1);
    form->addRow(buttons);
    grav_status_ = status_label(QStringLiteral("gravityStatus"), group);
    form->addRow(grav_status_);
    for (QDoubleSpinBox* box : {grav_x_, grav_y_})
        form::apply_on_enter(box, [this] { if (!loading_) applyGravity(); });
    return group;
}

void LoadForm::updateTableHeaders()
{
    const auto variable = static_cast<LoadTable::Variable>(tbl_variable_->currentData().toInt());
    tbl_points_->setHorizontalHeaderLabels(
        {variable == LoadTable::Variable::Time ? tr("Time [s]") : tr("Step [–]"), tr("Factor [–]")});
}

// --- loading -----------------------------------------------------------------------------

void LoadForm::refresh()
{
    const Model& m = document_->model();
    loading_ = true;
    const int table = table_box_->currentIndex();
    table_box_->clear();
    ld_table_->clear();
    ld_table_->addItem(tr("constant"), -1);
    for (std::size_t i = 0; i < m.load_tables.size(); ++i) {
        const QString text = tr("%1: %2").arg(i).arg(to_qt(m.load_tables[i].name));
        table_box_->addItem(text);
        ld_table_->addItem(text, static_cast<int>(i));
    }
    if (table_box_->count() > 0) table_box_->setCurrentIndex(std::clamp(table, 0, table_box_->count() - 1));
    const int load = load_box_->currentIndex();
    load_box_->clear();
    for (const PointLoad& l : m.point_loads) load_box_->addItem(tr("Point load \"%1\"").arg(to_qt(l.name)));
    for (const EdgePressure& e : m.edge_pressures) load_box_->addItem(tr("Edge pressure \"%1\"").arg(to_qt(e.name)));
    if (load_box_->count() > 0) load_box_->setCurrentIndex(std::clamp(load, 0, load_box_->count() - 1));
    loading_ = false;
    loadTable();
    loadLoad();
    loadGravity();
}

void LoadForm::showRows(const std::vector<std::array<double, 2>>& points)
{
    tbl_points_->setRowCount(static_cast<int>(points.size()));
    for (std::size_t r = 0; r < points.size(); ++r)
        for (int c = 0; c < 2; ++c)
            tbl_points_->setItem(static_cast<int>(r), c, new QTableWidgetItem(form::cell_text(points[r][c])));
}

void LoadForm::loadTable()
{
    const Model& m = document_->model();
    const int i = table_box_->currentIndex();
    const bool valid = i >= 0 && static_cast<std::size_t>(i) < m.load_tables.size();
    for (QWidget* w : table_fields_) w->setEnabled(valid);
    loading_ = true;
    if (valid) {
        const LoadTable& t = m.load_tables[static_cast<std::size_t>(i)];
        tbl_name_->setText(to_qt(t.name));
        tbl_variable_->setCurrentIndex(tbl_variable_->findData(static_cast<int>(t.variable)));
        tbl_extrapolate_->setChecked(t.extrapolate);
        showRows(t.points);
    } else {
        tbl_name_->clear();
        showRows({});
    }
    updateTableHeaders();
    loading_ = false;
}

void LoadForm::loadLoad()
{
    const Model& m = document_->model();
    const int e = load_box_->currentIndex();
    const int points = static_cast<int>(m.point_loads.size());
    const int total = points + static_cast<int>(m.edge_pressures.size());
    const bool point = e >= 0 && e < points;
    const bool pressure = e >= points && e < total;
    ld_fx_->setEnabled(point);
    ld_fy_->setEnabled(point);
    ld_pressure_->setEnabled(pressure);
    ld_table_->setEnabled(point || pressure);
    ld_apply_->setEnabled(point || pressure);
    load_box_->setEnabled(total > 0);
    loading_ = true;
    int table = -1;
    if (point) {
        const PointLoad& l = m.point_loads[static_cast<std::size_t>(e)];
        display(ld_fx_, l.force.x / 1e3);
        display(ld_fy_, l.force.y / 1e3);
        display(ld_pressure_, 0.0);
        table = l.table;
    } else if (pressure) {
        const EdgePressure& p = m.edge_pressures[static_cast<std::size_t>(e - points)];
        display(ld_fx_, 0.0);
        display(ld_fy_, 0.0);
        form::display_stress(ld_pressure_, p.pressure);
        table = p.table;
    }
    ld_table_->setCurrentIndex(ld_table_->findData(table));
    loading_ = false;
}

void LoadForm::loadGravity()
{
    const Point2& g = document_->model().gravity;
    loading_ = true;
    display(grav_x_, g.x);
    display(grav_y_, g.y);
    loading_ = false;
}

// --- load tables -------------------------------------------------------------------------

int LoadForm::tableIndex() const { return table_box_->currentIndex(); }
void LoadForm::setTableIndex(int index) { table_box_->setCurrentIndex(index); }
int LoadForm::loadIndex() const { return load_box_->currentIndex(); }
void LoadForm::setLoadIndex(int index) { load_box_->setCurrentIndex(index); }
QString LoadForm::tableStatus() const { return tbl_status_->text(); }
QString LoadForm::loadStatus() const { return ld_status_->text(); }
QString LoadForm::gravityStatus() const { return grav_status_->text(); }

void LoadForm::addTableRow()
{
    const int rows = tbl_points_->rowCount();
    double abscissa = 0.0;
    double factor = 0.0;
    if (rows > 0) {
        const QTableWidgetItem* a = tbl_points_->item(rows - 1, 0);
        const QTableWidgetItem* f = tbl_points_->item(rows - 1, 1);
        // An unreadable last row gives a row that Apply refuses anyway; start from 0 then.
        if (a && form::cell_value(a->text(), &abscissa)) abscissa += 1.0;
        if (!f || !form::cell_value(f->text(), &factor)) factor = 0.0;
    }
    tbl_points_->insertRow(rows);
    tbl_points_->setItem(rows, 0, new QTableWidgetItem(form::cell_text(abscissa)));
    tbl_points_->setItem(rows, 1, new QTableWidgetItem(form::cell_text(factor)));
    tbl_points_->setCurrentCell(rows, 0);
}

void LoadForm::removeTableRow()
{
    const int rows = tbl_points_->rowCount();
    if (rows == 0) return;
    const int row = tbl_points_->currentRow();
    tbl_points_->removeRow(row >= 0 && row < rows ? row : rows - 1);
}

bool LoadForm::applyTable()
{
    const Model& m = document_->model();
    const int i = table_box_->currentIndex();
    if (i < 0 || static_cast<std::size_t>(i) >= m.load_tables.size()) return false;
    const LoadTable& old = m.load_tables[static_cast<std::size_t>(i)];
    LoadTable t = old;
    t.name = tbl_name_->text().toStdString();
    t.variable = static_cast<LoadTable::Variable>(tbl_variable_->currentData().toInt());
    t.extrapolate = tbl_extrapolate_->isChecked();
    t.points.clear();
    for (int r = 0; r < tbl_points_->rowCount(); ++r) {
        std::array<double, 2> point{};
        for (int c = 0; c < 2; ++c) {
            const QTableWidgetItem* item = tbl_points_->item(r, c);
            const QString text = item ? item->text() : QString();
            if (!form::cell_value(text, &point[static_cast<std::size_t>(c)])) {
                set_status(tbl_status_,
                           tr("Not applied: row %1: %2 \"%3\" is not a number")
                               .arg(r + 1)
                               .arg(c == 0 ? tr("abscissa") : tr("factor"), text),
                           true);
                return false;
            }
        }
        t.points.push_back(point);
    }
    if (same(t, old)) return true;
    Model candidate = m;
    candidate.load_tables[static_cast<std::size_t>(i)] = t;
    const QString reason = PropertyEditor::refusal(candidate, "/load_tables/" + std::to_string(i));
    if (!reason.isEmpty()) {
        set_status(tbl_status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    const auto index = static_cast<std::size_t>(i);
    document_->undoStack()->push(new SetValueCommand<LoadTable>(
        document_, [index](Model& model) -> LoadTable& { return model.load_tables[index]; }, t,
        tr("Change load table \"%1\"").arg(to_qt(old.name))));  // → changed() → refresh()
    set_status(tbl_status_, tr("Applied."), false);
    return true;
}

bool LoadForm::newTable()
{
    const Model& m = document_->model();
    LoadTable t;
    // A name not used yet: the model file refers to tables by name.
    for (std::size_t n = m.load_tables.size() + 1;; ++n) {
        t.name = "table " + std::to_string(n);
        if (std::none_of(m.load_tables.begin(), m.load_tables.end(),
                         [&t](const LoadTable& x) { return x.name == t.name; }))
            break;
    }
    t.points = {{0.0, 0.0}, {1.0, 1.0}};
    Model candidate = m;
    candidate.load_tables.push_back(t);
    const QString reason = PropertyEditor::refusal(candidate, "/load_tables/" + std::to_string(m.load_tables.size()));
    if (!reason.isEmpty()) {
        set_status(tbl_status_, tr("Not added: %1").arg(reason), true);
        return false;
    }
    const QString name = to_qt(t.name);
    document_->undoStack()->push(new AddItemCommand<LoadTable>(document_, &Model::load_tables, t,
                                                               tr("Add load table \"%1\"").arg(name)));
    setTableIndex(table_box_->count() - 1);
    set_status(tbl_status_, tr("Added \"%1\".").arg(name), false);
    return true;
}

bool LoadForm::deleteTable()
{
    const Model& m = document_->model();
    const int i = table_box_->currentIndex();
    if (i < 0 || static_cast<std::size_t>(i) >= m.load_tables.size()) return false;
    const QString name = to_qt(m.load_tables[static_cast<std::size_t>(i)].name);
    // Refused rather than turning the loads constant behind the user's back.
    for (const PointLoad& l : m.point_loads)
        if (l.table == i) {
            set_status(tbl_status_, tr("Not deleted: load table \"%1\" is used by point load \"%2\"").arg(name, to_qt(l.name)),
                       true);
            return false;
        }
    for (const EdgePressure& e : m.edge_pressures)
        if (e.table == i) {
            set_status(tbl_status_,
                       tr("Not deleted: load table \"%1\" is used by edge pressure \"%2\"").arg(name, to_qt(e.name)), true);
            return false;
        }
    // Loads refer to the tables after it by index: one whole-model replacement keeps the
    // references and the list consistent in every state the document passes through.
    Model candidate = m;
    candidate.load_tables.erase(candidate.load_tables.begin() + i);
    for (PointLoad& l : candidate.point_loads)
        if (l.table > i) --l.table;
    for (EdgePressure& e : candidate.edge_pressures)
        if (e.table > i) --e.table;
    document_->replaceModel(std::move(candidate), tr("Delete load table \"%1\"").arg(name));
    set_status(tbl_status_, tr("Deleted \"%1\".").arg(name), false);
    return true;
}

// --- loads and gravity -------------------------------------------------------------------

bool LoadForm::applyLoad()
{
    const Model& m = document_->model();
    const int e = load_box_->currentIndex();
    const int points = static_cast<int>(m.point_loads.size());
    if (e < 0 || e >= points + static_cast<int>(m.edge_pressures.size())) return false;
    const QVariant chosen = ld_table_->currentData();
    Model candidate = m;
    QString reason;
    if (e < points) {
        const auto k = static_cast<std::size_t>(e);
        const PointLoad& old = m.point_loads[k];
        PointLoad x = old;
        x.force = {si(ld_fx_, old.force.x, 1e3), si(ld_fy_, old.force.y, 1e3)};
        if (chosen.isValid()) x.table = chosen.toInt();  // none shown: a reference the list lacks stays
        if (same(x.force, old.force) && x.table == old.table) return true;
        candidate.point_loads[k] = x;
        reason = PropertyEditor::refusal(candidate, "/point_loads/" + std::to_string(k));
        if (reason.isEmpty())
            document_->undoStack()->push(new SetValueCommand<PointLoad>(
                document_, [k](Model& model) -> PointLoad& { return model.point_loads[k]; }, x,
                tr("Change point load \"%1\"").arg(to_qt(old.name))));
    } else {
        const auto k = static_cast<std::size_t>(e - points);
        const EdgePressure& old = m.edge_pressures[k];
        EdgePressure x = old;
        x.pressure = form::stress_value(ld_pressure_, old.pressure);
        if (chosen.isValid()) x.table = chosen.toInt();
        if (x.pressure == old.pressure && x.table == old.table) return true;
        candidate.edge_pressures[k] = x;
        reason = PropertyEditor::refusal(candidate, "/edge_pressures/" + std::to_string(k));
        if (reason.isEmpty())
            document_->undoStack()->push(new SetValueCommand<EdgePressure>(
                document_, [k](Model& model) -> EdgePressure& { return model.edge_pressures[k]; }, x,
                tr("Change edge pressure \"%1\"").arg(to_qt(old.name))));
    }
    if (!reason.isEmpty()) {
        set_status(ld_status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    set_status(ld_status_, tr("Applied."), false);
    return true;
}

bool LoadForm::applyGravity()
{
    const Model& m = document_->model();
    const Point2 g{si(grav_x_, m.gravity.x, 1.0), si(grav_y_, m.gravity.y, 1.0)};
    if (same(g, m.gravity)) return true;
    Model candidate = m;
    candidate.gravity = g;
    const QString reason = PropertyEditor::refusal(candidate, "/gravity");
    if (!reason.isEmpty()) {
        set_status(grav_status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    document_->undoStack()->push(new SetValueCommand<Point2>(
        document_, [](Model& model) -> Point2& { return model.gravity; }, g, tr("Change gravity")));
    set_status(grav_status_, tr("Applied."), false);
    return true;
}

bool LoadForm::setStandardGravity()
{
    grav_x_->setValue(0.0);
    grav_y_->setValue(-standard_gravity);
    return applyGravity();
}

}  // namespace mcdda::gui
