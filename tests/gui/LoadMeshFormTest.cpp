// The Loads and Mesh tabs of the Properties dock on a (virtual) X server: load tables edited,
// refused and undone, a point load's force and table, deleting a table in use, gravity, and
// mesh controls that re-mesh the model.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "Preprocess.hpp"
#include "document/ModelDocument.hpp"
#include "panels/LoadForm.hpp"
#include "panels/MeshForm.hpp"
#include "panels/PropertyEditor.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

using namespace mcdda;
using mcdda::gui::LoadForm;
using mcdda::gui::MainWindow;
using mcdda::gui::MeshForm;
using namespace mcdda::guitest;

namespace {

constexpr double pi = 3.14159265358979323846;

void set_cell(QTableWidget* table, int row, int column, const QString& text)
{
    QTableWidgetItem* item = table->item(row, column);
    QVERIFY(item);
    item->setText(text);
}

/// A point load "P" at the top and a pressure "top" on the top edge.
void add_loads(gui::ModelDocument* doc)
{
    PointLoad p;
    p.name = "P";
    p.point = {5, 10};
    p.force = {0.0, -1e3};
    doc->addPointLoad(p);
    EdgePressure e;
    e.name = "top";
    e.from = {0, 10};
    e.to = {10, 10};
    e.pressure = 1e5;
    doc->addEdgePressure(e);
}

}  // namespace

class LoadMeshFormTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void editsLoadTableWithUndo();
    void refusesInvalidTables();
    void changesPointLoadAndPressure();
    void deletingTableInUseIsRefused();
    void appliesGravity();
    void meshSizeRemeshes();
    void regionSizeRemeshesThatRegion();
    void minimumAngleStoredInRadians();
    void editsLocalRefinement();
};

void LoadMeshFormTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

void LoadMeshFormTest::editsLoadTableWithUndo()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    LoadForm* form = window->propertyEditor()->loadForm();
    QVERIFY(form);
    QVERIFY(!form->findChild<QLineEdit*>(QStringLiteral("loadTableName"))->isEnabled());  // no table yet

    form->findChild<QPushButton*>(QStringLiteral("loadTableNew"))->click();
    QCOMPARE(doc->model().load_tables.size(), std::size_t(1));
    QCOMPARE(doc->model().load_tables[0].name, std::string("table 1"));
    QCOMPARE(form->tableIndex(), 0);
    QTableWidget* rows = form->tablePoints();
    QCOMPARE(rows->rowCount(), 2);
    QCOMPARE(rows->item(1, 1)->text(), QStringLiteral("1"));
    const int commands = doc->undoStack()->count();

    form->findChild<QLineEdit*>(QStringLiteral("loadTableName"))->setText(QStringLiteral("ramp"));
    auto* variable = form->findChild<QComboBox*>(QStringLiteral("loadTableVariable"));
    variable->setCurrentIndex(variable->findData(static_cast<int>(LoadTable::Variable::Time)));
    QVERIFY(rows->horizontalHeaderItem(0)->text().contains(QStringLiteral("[s]")));
    form->findChild<QCheckBox*>(QStringLiteral("loadTableExtrapolate"))->setChecked(true);
    set_cell(rows, 1, 1, QStringLiteral("2"));
    form->findChild<QPushButton*>(QStringLiteral("loadTableAddRow"))->click();
    QCOMPARE(rows->rowCount(), 3);
    QCOMPARE(rows->item(2, 0)->text(), QStringLiteral("2"));  // one after the last abscissa
    set_cell(rows, 2, 0, QStringLiteral("2.5"));
    set_cell(rows, 2, 1, QStringLiteral("3"));
    form->findChild<QPushButton*>(QStringLiteral("loadTableApply"))->click();
    QVERIFY2(form->tableStatus().contains(QStringLiteral("Applied")), qPrintable(form->tableStatus()));

    const LoadTable& t = doc->model().load_tables[0];
    QCOMPARE(t.name, std::string("ramp"));
    QCOMPARE(t.variable, LoadTable::Variable::Time);
    QVERIFY(t.extrapolate);
    const std::vector<std::array<double, 2>> expected{{0.0, 0.0}, {1.0, 2.0}, {2.5, 3.0}};
    QVERIFY(t.points == expected);
    QCOMPARE(doc->undoStack()->count(), commands + 1);
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("load table")));

    doc->undoStack()->undo();
    const LoadTable& back = doc->model().load_tables[0];
    QCOMPARE(back.name, std::string("table 1"));
    QCOMPARE(back.variable, LoadTable::Variable::Step);
    QVERIFY(!back.extrapolate);
    QCOMPARE(back.points.size(), std::size_t(2));
    QCOMPARE(back.points[1][1], 1.0);
    QCOMPARE(rows->rowCount(), 2);  // the form follows the undo
    QCOMPARE(rows->item(1, 1)->text(), QStringLiteral("1"));
    doc->undoStack()->undo();
    QVERIFY(doc->model().load_tables.empty());
    QTRY_VERIFY(settled(*window));
}

void LoadMeshFormTest::refusesInvalidTables()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    LoadForm* form = window->propertyEditor()->loadForm();
    QVERIFY(form->newTable());
    QVERIFY(form->newTable());
    QCOMPARE(doc->model().load_tables[1].name, std::string("table 2"));
    QCOMPARE(form->tableIndex(), 1);
    const std::vector<LoadTable> before = doc->model().load_tables;
    const int commands = doc->undoStack()->count();
    const auto unchanged = [&] {
        const auto& now = doc->model().load_tables;
        return now.size() == before.size() && now[1].name == before[1].name && now[1].points == before[1].points;
    };
    QTableWidget* rows = form->tablePoints();

    set_cell(rows, 1, 0, QStringLiteral("0"));  // abscissas 0, 0
    QVERIFY(!form->applyTable());
    QVERIFY2(form->tableStatus().contains(QStringLiteral("increase strictly")), qPrintable(form->tableStatus()));
    // The point named in words (its table and number), not by a JSON pointer.
    QVERIFY2(form->tableStatus().contains(QStringLiteral("load table \"table 2\", point 2")), qPrintable(form->tableStatus()));
    QVERIFY(!form->tableStatus().contains(QStringLiteral("/load_tables")));
    QVERIFY(unchanged());
    QCOMPARE(doc->undoStack()->count(), commands);

    set_cell(rows, 1, 0, QStringLiteral("abc"));
    QVERIFY(!form->applyTable());
    QVERIFY2(form->tableStatus().contains(QStringLiteral("not a number")), qPrintable(form->tableStatus()));
    QVERIFY(unchanged());

    set_cell(rows, 1, 0, QStringLiteral("4"));
    form->findChild<QLineEdit*>(QStringLiteral("loadTableName"))->setText(QStringLiteral("table 1"));
    QVERIFY(!form->applyTable());
    QVERIFY2(form->tableStatus().contains(QStringLiteral("another load table")), qPrintable(form->tableStatus()));
    QVERIFY(unchanged());

    form->findChild<QLineEdit*>(QStringLiteral("loadTableName"))->setText(QStringLiteral("table 2"));
    auto* remove = form->findChild<QPushButton*>(QStringLiteral("loadTableRemoveRow"));
    remove->click();
    remove->click();
    QCOMPARE(rows->rowCount(), 0);
    QVERIFY(!form->applyTable());
    QVERIFY2(form->tableStatus().contains(QStringLiteral("at least one")), qPrintable(form->tableStatus()));
    QVERIFY(unchanged());
    QCOMPARE(doc->undoStack()->count(), commands);
    QTRY_VERIFY(settled(*window));
}

void LoadMeshFormTest::changesPointLoadAndPressure()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    add_loads(doc);
    LoadForm* form = window->propertyEditor()->loadForm();
    QVERIFY(form->newTable());
    auto* box = form->findChild<QComboBox*>(QStringLiteral("loadBox"));
    QCOMPARE(box->count(), 2);
    QVERIFY(box->itemText(0).contains(QStringLiteral("P")));
    QVERIFY(box->itemText(1).contains(QStringLiteral("top")));

    form->setLoadIndex(0);
    auto* fx = form->findChild<QDoubleSpinBox*>(QStringLiteral("loadFx"));
    auto* fy = form->findChild<QDoubleSpinBox*>(QStringLiteral("loadFy"));
    auto* pressure = form->findChild<QDoubleSpinBox*>(QStringLiteral("loadPressure"));
    auto* table = form->findChild<QComboBox*>(QStringLiteral("loadTableChoice"));
    QVERIFY(fy->suffix().contains(QStringLiteral("kN/m")));
    QVERIFY(pressure->suffix().contains(QStringLiteral("kPa")));
    QVERIFY(fx->isEnabled() && !pressure->isEnabled());
    QCOMPARE(fy->value(), -1.0);
    QCOMPARE(table->currentData().toInt(), -1);  // constant
    QCOMPARE(table->itemText(0), QStringLiteral("constant"));

    fy->setValue(-5.0);
    table->setCurrentIndex(table->findData(0));
    form->findChild<QPushButton*>(QStringLiteral("loadApply"))->click();
    QVERIFY2(form->loadStatus().contains(QStringLiteral("Applied")), qPrintable(form->loadStatus()));
    QCOMPARE(doc->model().point_loads[0].force.y, -5e3);
    QCOMPARE(doc->model().point_loads[0].force.x, 0.0);
    QCOMPARE(doc->model().point_loads[0].table, 0);
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("point load")));

    form->setLoadIndex(1);
    QVERIFY(pressure->isEnabled() && !fx->isEnabled());
    QCOMPARE(pressure->value(), 100.0);
    pressure->setValue(250.0);
    QVERIFY(form->applyLoad());
    QCOMPARE(doc->model().edge_pressures[0].pressure, 2.5e5);
    QCOMPARE(doc->model().edge_pressures[0].table, -1);

    doc->undoStack()->undo();
    QCOMPARE(doc->model().edge_pressures[0].pressure, 1e5);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().point_loads[0].force.y, -1e3);
    QCOMPARE(doc->model().point_loads[0].table, -1);
    form->setLoadIndex(0);
    QCOMPARE(fy->value(), -1.0);
    QCOMPARE(table->currentData().toInt(), -1);
    QTRY_VERIFY(settled(*window));
}

void LoadMeshFormTest::deletingTableInUseIsRefused()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    add_loads(doc);
    LoadForm* form = window->propertyEditor()->loadForm();
    QVERIFY(form->newTable());
    QVERIFY(form->newTable());
    // The point load uses table 2 (index 1), the pressure table 1 (index 0).
    form->setLoadIndex(0);
    auto* table = form->findChild<QComboBox*>(QStringLiteral("loadTableChoice"));
    table->setCurrentIndex(table->findData(1));
    QVERIFY(form->applyLoad());
    form->setLoadIndex(1);
    table->setCurrentIndex(table->findData(0));
    QVERIFY(form->applyLoad());
    const int commands = doc->undoStack()->count();

    form->setTableIndex(1);
    form->findChild<QPushButton*>(QStringLiteral("loadTableDelete"))->click();
    QVERIFY2(form->tableStatus().contains(QStringLiteral("point load \"P\"")), qPrintable(form->tableStatus()));
    QCOMPARE(doc->model().load_tables.size(), std::size_t(2));
    form->setTableIndex(0);
    QVERIFY(!form->deleteTable());
    QVERIFY2(form->tableStatus().contains(QStringLiteral("edge pressure \"top\"")), qPrintable(form->tableStatus()));
    QCOMPARE(doc->model().load_tables.size(), std::size_t(2));
    QCOMPARE(doc->undoStack()->count(), commands);

    // Once unused, table 1 goes and the point load still refers to "table 2".
    form->setLoadIndex(1);
    table->setCurrentIndex(table->findData(-1));
    QVERIFY(form->applyLoad());
    form->setTableIndex(0);
    QVERIFY(form->deleteTable());
    QCOMPARE(doc->model().load_tables.size(), std::size_t(1));
    QCOMPARE(doc->model().load_tables[0].name, std::string("table 2"));
    QCOMPARE(doc->model().point_loads[0].table, 0);
    QCOMPARE(doc->model().edge_pressures[0].table, -1);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().load_tables.size(), std::size_t(2));
    QCOMPARE(doc->model().load_tables[0].name, std::string("table 1"));
    QCOMPARE(doc->model().point_loads[0].table, 1);
    QTRY_VERIFY(settled(*window));
}

void LoadMeshFormTest::appliesGravity()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    LoadForm* form = window->propertyEditor()->loadForm();
    auto* gx = form->findChild<QDoubleSpinBox*>(QStringLiteral("gravityX"));
    auto* gy = form->findChild<QDoubleSpinBox*>(QStringLiteral("gravityY"));
    QVERIFY(gy->suffix().contains(QStringLiteral("m/s²")));
    const Point2 before = doc->model().gravity;  // File ▸ New: standard gravity
    const int commands = doc->undoStack()->count();

    gx->setValue(1.5);
    gy->setValue(-5.0);
    QVERIFY(form->applyGravity());
    QCOMPARE(doc->model().gravity.x, 1.5);
    QCOMPARE(doc->model().gravity.y, -5.0);
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("gravity")));
    gx->setValue(0.5);
    QVERIFY(form->applyGravity());
    QCOMPARE(doc->model().gravity.x, 0.5);
    QCOMPARE(doc->model().gravity.y, -5.0);  // the untouched field stays exact

    form->findChild<QPushButton*>(QStringLiteral("gravityStandard"))->click();
    QCOMPARE(doc->model().gravity.x, 0.0);
    QCOMPARE(doc->model().gravity.y, -9.81);
    QCOMPARE(gy->value(), -9.81);
    QCOMPARE(doc->undoStack()->count(), commands + 3);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().gravity.x, 0.5);
    QCOMPARE(gx->value(), 0.5);  // the form follows the undo
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    QCOMPARE(doc->model().gravity.x, before.x);
    QCOMPARE(doc->model().gravity.y, before.y);
    QTRY_VERIFY(settled(*window));
}

void LoadMeshFormTest::meshSizeRemeshes()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    gui::ModelDocument* doc = window->document();
    MeshForm* form = window->propertyEditor()->meshForm();
    QVERIFY(form);
    auto* size = form->findChild<QDoubleSpinBox*>(QStringLiteral("meshSize"));
    QCOMPARE(doc->model().mesh.size, 0.0);
    QCOMPARE(size->text(), QStringLiteral("automatic"));
    QVERIFY(size->suffix().contains(QStringLiteral("m")));
    const int automatic = window->modelView()->scene()->statistics.elements;
    QVERIFY(automatic > 0);

    size->setValue(2.5);
    form->findChild<QPushButton*>(QStringLiteral("meshApply"))->click();
    QVERIFY2(form->meshStatus().contains(QStringLiteral("Applied")), qPrintable(form->meshStatus()));
    QCOMPARE(doc->model().mesh.size, 2.5);
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("mesh")));
    QTRY_VERIFY2(settled(*window) && window->modelView()->scene()->model.mesh.size == 2.5,
                 qPrintable(window->messages()));
    const int coarse = window->modelView()->scene()->statistics.elements;
    QVERIFY2(coarse < automatic, qPrintable(QStringLiteral("%1 vs %2").arg(coarse).arg(automatic)));

    doc->undoStack()->undo();
    QCOMPARE(doc->model().mesh.size, 0.0);
    QCOMPARE(size->text(), QStringLiteral("automatic"));
    QTRY_VERIFY(settled(*window) && window->modelView()->scene()->model.mesh.size == 0.0);
    QCOMPARE(window->modelView()->scene()->statistics.elements, automatic);
}

// A region's own element size, typed in the Mesh tab's region table: applied as one undoable
// command, the view meshes the region coarser; a negative size or a word is refused with the
// reason, and nothing changes.
void LoadMeshFormTest::regionSizeRemeshesThatRegion()
{
    auto window = square_window();
    QVERIFY(window);
    QTRY_VERIFY2(settled(*window), qPrintable(window->messages()));
    gui::ModelDocument* doc = window->document();
    MeshForm* form = window->propertyEditor()->meshForm();
    QTableWidget* regions = form->regionSizes();
    QCOMPARE(regions->rowCount(), static_cast<int>(doc->model().regions.size()));
    QCOMPARE(regions->item(0, 0)->text(), QString::fromStdString(doc->model().regions[0].name));
    QVERIFY(regions->item(0, 1)->text().isEmpty());  // the model's size field
    const int automatic = window->modelView()->scene()->statistics.elements;
    const int commands = doc->undoStack()->count();

    regions->item(0, 1)->setText(QStringLiteral("-1"));
    QVERIFY(!form->applyMesh());
    QVERIFY2(form->meshStatus().contains(QStringLiteral("mesh size must be positive")), qPrintable(form->meshStatus()));
    regions->item(0, 1)->setText(QStringLiteral("coarse"));
    QVERIFY(!form->applyMesh());
    QVERIFY2(form->meshStatus().contains(QStringLiteral("is not a number")), qPrintable(form->meshStatus()));
    QCOMPARE(doc->model().regions[0].mesh_size, 0.0);
    QCOMPARE(doc->undoStack()->count(), commands);

    regions->item(0, 1)->setText(QStringLiteral("2.5"));
    QVERIFY2(form->applyMesh(), qPrintable(form->meshStatus()));
    QCOMPARE(doc->model().regions[0].mesh_size, 2.5);
    QCOMPARE(doc->undoStack()->count(), commands + 1);
    QTRY_VERIFY2(settled(*window) && window->modelView()->scene()->model.regions[0].mesh_size == 2.5,
                 qPrintable(window->messages()));
    const int coarse = window->modelView()->scene()->statistics.elements;
    QVERIFY2(coarse < automatic, qPrintable(QStringLiteral("%1 vs %2").arg(coarse).arg(automatic)));

    doc->undoStack()->undo();
    QCOMPARE(doc->model().regions[0].mesh_size, 0.0);
    QVERIFY(regions->item(0, 1)->text().isEmpty());
    QTRY_VERIFY(settled(*window) && window->modelView()->scene()->model.regions[0].mesh_size == 0.0);
    QCOMPARE(window->modelView()->scene()->statistics.elements, automatic);
}

void LoadMeshFormTest::minimumAngleStoredInRadians()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    MeshForm* form = window->propertyEditor()->meshForm();
    auto* angle = form->findChild<QDoubleSpinBox*>(QStringLiteral("meshMinAngle"));
    QVERIFY(angle->suffix().contains(QStringLiteral("°")));
    const MeshControls before = doc->model().mesh;
    QCOMPARE(angle->value(), 25.0);
    const int commands = doc->undoStack()->count();

    angle->setValue(40.0);
    QVERIFY(!form->applyMesh());
    QVERIFY2(form->meshStatus().contains(QStringLiteral("34")), qPrintable(form->meshStatus()));
    QCOMPARE(doc->model().mesh.min_angle, before.min_angle);
    QCOMPARE(doc->undoStack()->count(), commands);

    angle->setValue(30.0);
    auto* grading = form->findChild<QDoubleSpinBox*>(QStringLiteral("meshGrading"));
    grading->setValue(0.5);
    QVERIFY(form->applyMesh());
    QVERIFY(std::abs(doc->model().mesh.min_angle - 30.0 * pi / 180.0) < 1e-12);
    QCOMPARE(doc->model().mesh.grading, 0.5);
    QCOMPARE(doc->model().mesh.max_elements, before.max_elements);
    QCOMPARE(doc->undoStack()->count(), commands + 1);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().mesh.min_angle, before.min_angle);
    QCOMPARE(doc->model().mesh.grading, before.grading);
    QTRY_VERIFY(settled(*window));
}

void LoadMeshFormTest::editsLocalRefinement()
{
    auto window = square_window();
    QVERIFY(window);
    gui::ModelDocument* doc = window->document();
    Model model = doc->model();
    model.mesh.local.push_back(LocalSize{{5, 5}, {5, 5}, 0.2, 1.0});
    doc->setModel(model);
    MeshForm* form = window->propertyEditor()->meshForm();
    QTableWidget* local = form->localRefinements();
    QCOMPARE(local->rowCount(), 1);
    QVERIFY(!(local->item(0, 0)->flags() & Qt::ItemIsEditable));
    QCOMPARE(local->item(0, 1)->text(), QStringLiteral("0.2"));
    QVERIFY(local->horizontalHeaderItem(2)->text().contains(QStringLiteral("[m]")));

    set_cell(local, 0, 1, QStringLiteral("-1"));
    QVERIFY(!form->applyMesh());
    QVERIFY2(form->meshStatus().contains(QStringLiteral("local size must be positive")), qPrintable(form->meshStatus()));
    QCOMPARE(doc->model().mesh.local[0].size, 0.2);

    set_cell(local, 0, 1, QStringLiteral("0.3"));
    set_cell(local, 0, 2, QStringLiteral("2"));
    QVERIFY(form->applyMesh());
    QCOMPARE(doc->model().mesh.local[0].size, 0.3);
    QCOMPARE(doc->model().mesh.local[0].radius, 2.0);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().mesh.local[0].size, 0.2);
    QCOMPARE(local->item(0, 1)->text(), QStringLiteral("0.2"));
    QTRY_VERIFY(settled(*window));
}

QTEST_MAIN(LoadMeshFormTest)
#include "LoadMeshFormTest.moc"
