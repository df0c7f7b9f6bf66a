// The Select tool on a (virtual) X server: clicking picks items and vertices, dragging moves
// them (snapped to the grid), Delete removes them, all undoable; the Model tree follows the
// selection and selects in the view; empty space still pans. Also Shift-drawn holes and typed
// coordinates with decimal commas.

#include "MainWindow.hpp"
#include "WindowProbe.hpp"
#include "document/ModelDocument.hpp"
#include "panels/PropertyEditor.hpp"
#include "tools/DrawTool.hpp"
#include "tools/SelectTool.hpp"
#include "view/Palette.hpp"
#include "widgets/ModelTree.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QMenuBar>
#include <QStandardPaths>
#include <QTreeWidgetItemIterator>
#include <QtTest>

#include <cmath>

using namespace mcdda;
using mcdda::gui::ItemRef;
using mcdda::gui::MainWindow;
using mcdda::gui::ModelView;
using Kind = mcdda::gui::ItemRef::Kind;
using namespace mcdda::guitest;

namespace {

/// Share of the 9 × 9 device pixels around the model point (x, y) that have `colour`.
double share_around(ModelView& view, double x, double y, const view::Rgb& colour)
{
    return count_around(view, x, y, colour) / 81.0;
}

/// Presses at model point `from`, moves there in a few steps and releases at `to`.
void drag(ModelView* view, Point2 from, Point2 to)
{
    QTest::mousePress(view, Qt::LeftButton, {}, pixel_of(*view, from.x, from.y));
    for (int k = 1; k <= 4; ++k) {
        const double t = k / 4.0;
        QTest::mouseMove(view, pixel_of(*view, from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)));
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, pixel_of(*view, to.x, to.y));
}

}  // namespace

class SelectTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void selectMoveDelete();
    void treeSelectsAndListsBlocks();
    void shiftDrawsAHoleAndCommasAreDecimal();
    void selectionAssignsMaterials();

private:
    /// A new model: a 10 m square on rollers with a measurement point at (5, 8).
    void squareModel(MainWindow& window);
};

void SelectTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        QSKIP("the VTK view needs the xcb platform (run under xvfb-run)");
}

void SelectTest::squareModel(MainWindow& window)
{
    QVERIFY(show_square(window));
    gui::ModelDocument* doc = window.document();
    MeasurementPoint q;
    q.point = {5, 8};
    doc->addMeasurementPoint(q);
    doc->undoStack()->clear();
    QTRY_VERIFY2(settled(window), qPrintable(window.messages()));
    window.modelView()->showBox(-5, -5, 20, 15);
}

void SelectTest::selectMoveDelete()
{
    MainWindow window;
    squareModel(window);
    gui::ModelDocument* doc = window.document();
    ModelView* view = window.modelView();
    QVERIFY(window.activeTool() == nullptr);  // Select is the tool at start
    QVERIFY(!window.selection().valid());

    // A click near a corner picks that vertex; the highlight is the vertex.
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 10.03, 9.97));
    QVERIFY(window.selection() == (ItemRef{Kind::Region, 0, 0, 2}));
    QCOMPARE(view->preview().size(), std::size_t(1));
    QVERIFY(!doc->isModified());  // a click does not move anything

    // Dragging it lands on the grid node nearest to where it was let go.
    drag(view, {10, 10}, {12.1, 10.9});
    QCOMPARE(doc->model().regions[0].boundary[2].x, 12.0);
    QCOMPARE(doc->model().regions[0].boundary[2].y, 11.0);
    QCOMPARE(doc->model().regions[0].boundary[1].x, 10.0);
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("vertex 3")));
    QTRY_VERIFY(settled(window));
    const view::Rgb rock = view::material_color(0);
    QVERIFY2(share_around(*view, 10.6, 9.4, rock) > 0.5,
             qPrintable(QStringLiteral("the stretched corner is drawn: %1").arg(share_around(*view, 10.6, 9.4, rock))));
    doc->undoStack()->undo();
    QCOMPARE(doc->model().regions[0].boundary[2].x, 10.0);
    QTRY_VERIFY(settled(window));
    QVERIFY(share_around(*view, 10.6, 9.4, view::palette::background) > 0.9);

    // A click inside picks the region; dragging it moves the whole region by whole grid steps.
    drag(view, {3, 3}, {5.1, 2.95});
    QVERIFY(window.selection() == (ItemRef{Kind::Region, 0}));
    const Ring& ring = doc->model().regions[0].boundary;
    QCOMPARE(ring[0].x, 2.0);
    QCOMPARE(ring[0].y, 0.0);
    QCOMPARE(ring[2].x, 12.0);
    QTRY_VERIFY(settled(window));
    QVERIFY(share_around(*view, 11.5, 5, rock) > 0.5);
    QVERIFY(share_around(*view, 1.0, 5, view::palette::background) > 0.9);
    doc->undoStack()->undo();
    QCOMPARE(doc->model().regions[0].boundary[0].x, 0.0);

    // The measurement point: picked before the region under it, deleted with Delete, restored.
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 5.05, 8.0));
    QVERIFY(window.selection() == (ItemRef{Kind::MeasurementPoint, 0}));
    QTest::keyClick(view, Qt::Key_Delete);
    QVERIFY(doc->model().measurement_points.empty());
    QVERIFY(!window.selection().valid());  // it no longer exists
    QVERIFY(view->preview().empty());
    doc->undoStack()->undo();
    QCOMPARE(doc->model().measurement_points.size(), std::size_t(1));

    // Vertices go until a triangle is left; its vertices are refused with a message.
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 0, 10));
    QVERIFY(window.selection() == (ItemRef{Kind::Region, 0, 0, 3}));
    QTest::keyClick(view, Qt::Key_Delete);
    QCOMPARE(doc->model().regions[0].boundary.size(), std::size_t(3));
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 10, 10));
    QVERIFY(window.selection() == (ItemRef{Kind::Region, 0, 0, 2}));
    QTest::keyClick(view, Qt::Key_Delete);
    QCOMPARE(doc->model().regions[0].boundary.size(), std::size_t(3));
    QVERIFY(window.messages().contains(QStringLiteral("three vertices")));
    doc->undoStack()->undo();
    QCOMPARE(doc->model().regions[0].boundary.size(), std::size_t(4));

    // Empty space: the selection goes and a drag pans the picture.
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 5, 8));
    QVERIFY(window.selection().valid());
    const QPointF before = view->toModel(QPointF(100, 100));
    drag(view, {-3, 12}, {-1, 12});
    QVERIFY(!window.selection().valid());
    const QPointF after = view->toModel(QPointF(100, 100));
    QVERIFY2(after.x() < before.x() - 1.5, "dragging empty space pans");
    QCOMPARE(doc->model().regions[0].boundary[0].x, 0.0);

    // Escape drops the selection; drawing tools take over the left button.
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 5, 5));
    QVERIFY(window.selection().valid());
    QTest::keyClick(view, Qt::Key_Escape);
    QVERIFY(!window.selection().valid());
}

void SelectTest::treeSelectsAndListsBlocks()
{
    MainWindow window;
    squareModel(window);
    gui::ModelDocument* doc = window.document();
    gui::ModelTree* tree = window.modelTree();
    QCOMPARE(tree->blockCount(), 1);
    doc->addJoint({{-1, 4}, {11, 4}});
    QTRY_VERIFY(settled(window));
    QTRY_COMPARE(tree->blockCount(), 2);  // the joint cuts the square in two
    // The Blocks group (row 1) starts folded and keeps what the user chose across refreshes.
    QTreeWidgetItem* blocks = tree->topLevelItem(1);
    QVERIFY(!blocks->isExpanded());
    blocks->setExpanded(true);
    doc->undoStack()->undo();
    doc->undoStack()->redo();
    QTRY_VERIFY(settled(window));
    QVERIFY(tree->topLevelItem(1)->isExpanded());
    QCOMPARE(tree->blockCount(), 2);
    // Help is the last menu.
    QCOMPARE(window.menuBar()->actions().last()->text(), QStringLiteral("&Help"));

    // Choosing the roller's row selects it in the view (its two ends highlighted).
    QTreeWidgetItem* roller_row = nullptr;
    for (QTreeWidgetItemIterator it(tree); *it; ++it)
        if ((*it)->text(1).startsWith(QStringLiteral("roller"))) roller_row = *it;
    QVERIFY(roller_row);
    tree->setCurrentItem(roller_row);
    QVERIFY(window.selection() == (ItemRef{Kind::Roller, 0}));
    QCOMPARE(window.modelView()->preview().size(), std::size_t(2));

    // Clicking the joint in the view selects its row.
    ModelView* view = window.modelView();
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 5, 4.02));
    QVERIFY(window.selection() == (ItemRef{Kind::Joint, 0}));
    QVERIFY(tree->selectedItem() == (ItemRef{Kind::Joint, 0}));
    QCOMPARE(tree->selectedItems().size(), 1);

    // Edit ▸ Delete works on the tree's choice too.
    QAction* del = window.findChild<QAction*>(QStringLiteral("deleteAction"));
    QVERIFY(del && del->isEnabled());
    del->trigger();
    QVERIFY(doc->model().joints.empty());
    QVERIFY(!del->isEnabled());
    QTRY_COMPARE(tree->blockCount(), 1);
}

void SelectTest::shiftDrawsAHoleAndCommasAreDecimal()
{
    MainWindow window;
    squareModel(window);
    gui::ModelDocument* doc = window.document();
    ModelView* view = window.modelView();
    window.drawRegionTool();
    QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, pixel_of(*view, 4, 4));
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 6, 4));
    QTest::mouseClick(view, Qt::LeftButton, {}, pixel_of(*view, 6, 6));
    QTest::mouseDClick(view, Qt::LeftButton, {}, pixel_of(*view, 4, 6));
    QCOMPARE(doc->model().regions.size(), std::size_t(1));
    QCOMPARE(doc->model().regions[0].holes.size(), std::size_t(1));
    QTRY_VERIFY(settled(window));
    QVERIFY(share_around(*view, 5.25, 5.25, view::palette::background) > 0.9);  // between grid lines

    // Typed points with decimal commas (as German users type them) next to the usual forms.
    auto* edit = window.findChild<QLineEdit*>(QStringLiteral("coordinateEdit"));
    QVERIFY(edit && edit->isEnabled());
    QVERIFY(window.enterCoordinates(QStringLiteral("12,5; 0,25")));
    QVERIFY(window.enterCoordinates(QStringLiteral("14,5 0,25")));
    QVERIFY(window.enterCoordinates(QStringLiteral("14.5, 2")));
    QVERIFY(!window.enterCoordinates(QStringLiteral("1,5,2")));  // ambiguous: refused
    const std::vector<Point2> typed = window.activeTool()->points();
    QCOMPARE(typed.size(), std::size_t(3));
    QCOMPARE(typed[0].x, 12.5);
    QCOMPARE(typed[0].y, 0.25);
    QCOMPARE(typed[1].x, 14.5);
    QCOMPARE(typed[2].y, 2.0);
}

// A second material for a selected region and a second joint material for a selected joint:
// New copies the one shown, Assign gives it to the selection; both undoable.
void SelectTest::selectionAssignsMaterials()
{
    MainWindow window;
    squareModel(window);
    gui::ModelDocument* doc = window.document();
    doc->addJoint({{-1, 4}, {11, 4}});
    QTRY_VERIFY(settled(window));
    gui::PropertyEditor* editor = window.propertyEditor();
    auto* assign = editor->findChild<QPushButton*>(QStringLiteral("materialAssign"));
    QVERIFY(assign);
    QVERIFY(!assign->isEnabled());  // nothing selected

    window.selectItem({Kind::Region, 0});
    QVERIFY(assign->isEnabled());
    QVERIFY(editor->newMaterial());
    QCOMPARE(doc->model().materials.size(), std::size_t(2));
    QCOMPARE(doc->model().materials[1].young_modulus, doc->model().materials[0].young_modulus);  // a copy
    QCOMPARE(editor->materialIndex(), 1);
    QVERIFY(editor->assignMaterial());
    QCOMPARE(doc->model().regions[0].material, 1);
    QTRY_VERIFY(settled(window));
    QVERIFY2(share_around(*window.modelView(), 5, 7, view::material_color(1)) > 0.5, "drawn in the new colour");
    doc->undoStack()->undo();
    QCOMPARE(doc->model().regions[0].material, 0);

    window.selectItem({Kind::Joint, 0});
    QVERIFY(!assign->isEnabled());  // a joint has no rock material
    QVERIFY(editor->newJointMaterial());
    QVERIFY(editor->assignJointMaterial());
    QCOMPARE(doc->model().joints[0].joint_material, 1);
    QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("joint material")));
    window.selectItem({});
    QVERIFY(!editor->assignJointMaterial());
}

QTEST_MAIN(SelectTest)
#include "SelectTest.moc"
