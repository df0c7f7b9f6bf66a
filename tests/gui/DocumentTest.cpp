// The model document: undoable edits, the modified flag, save and reopen. No display needed.

#include "ModelCompare.hpp"
#include "document/EditCommands.hpp"
#include "document/ModelDocument.hpp"
#include "document/ModelItems.hpp"
#include "io/ModelReader.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

using namespace mcdda;
using mcdda::gui::ModelDocument;
using mcdda::test::model_differences;

namespace {

QString example(const char* name) {
    return QDir(QStringLiteral(MCDDA_EXAMPLES_DIR)).filePath(QString::fromLatin1(name));
}

QString messages(const std::vector<Diagnostic>& diagnostics) {
    QString text;
    for (const Diagnostic& d : diagnostics) text += QString::fromStdString(format_diagnostic(d)) + QLatin1Char('\n');
    return text;
}

/// Fails the test with the differences when the models differ.
#define COMPARE_MODELS(a, b)                                                   \
    do {                                                                       \
        const std::string differences = model_differences((a), (b));           \
        QVERIFY2(differences.empty(), differences.c_str());                    \
    } while (false)

/// A 10 m square with a 2 m hole, an explicit joint at y = 2, a generated one at y = 8 and a
/// fixed point on a corner.
Model picking_model() {
    Model m;
    m.materials.push_back({});
    Region r;
    r.material = 0;
    r.boundary = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    r.holes = {{{4, 4}, {6, 4}, {6, 6}, {4, 6}}};
    m.regions.push_back(r);
    Joint j;
    j.points = {{-1, 2}, {11, 2}};
    m.joints.push_back(j);
    Joint g;
    g.points = {{-1, 8}, {11, 8}};
    g.joint_set = 0;
    m.joints.push_back(g);
    FixedPoint f;
    f.point = {0, 0};
    m.fixed_points.push_back(f);
    return m;
}

}  // namespace

class DocumentTest : public QObject {
    Q_OBJECT

private:
    /// Opens an example; fails the test when it cannot be read.
    bool openExample(ModelDocument& document) {
        const auto diagnostics = document.open(example("kirsch.json"));
        if (has_errors(diagnostics)) qWarning("%s", qPrintable(messages(diagnostics)));
        return !has_errors(diagnostics);
    }

    /// Adds a square region of the first material and a joint across it.
    static void edit(ModelDocument& document) {
        document.addRegion({{100, 100}, {110, 100}, {110, 110}, {100, 110}}, 0, QStringLiteral("added block"));
        document.addJoint({{100, 105}, {105, 106}, {110, 105}});
    }

private slots:
    void picksVerticesLinesAndAreas() {
        using Kind = gui::ItemRef::Kind;
        const Model m = picking_model();
        // A vertex wins over the region around it; the nearest one within the tolerance.
        gui::ItemRef r = gui::pick_item(m, {10.05, 9.98}, 0.1);
        QCOMPARE(int(r.kind), int(Kind::Region));
        QCOMPARE(r.index, 0);
        QCOMPARE(r.ring, 0);
        QCOMPARE(r.vertex, 2);
        // A hole's vertex names the hole ring.
        r = gui::pick_item(m, {6.0, 6.0}, 0.1);
        QCOMPARE(r.ring, 1);
        QCOMPARE(r.vertex, 2);
        // A point item on a region corner wins at equal distance.
        r = gui::pick_item(m, {0.0, 0.0}, 0.1);
        QCOMPARE(int(r.kind), int(Kind::FixedPoint));
        // The middle of a joint picks the joint as a whole; a set's joint is not picked.
        r = gui::pick_item(m, {5.0, 2.04}, 0.1);
        QCOMPARE(int(r.kind), int(Kind::Joint));
        QCOMPARE(r.index, 0);
        QCOMPARE(r.vertex, -1);
        r = gui::pick_item(m, {5.0, 8.0}, 0.1);
        QCOMPARE(int(r.kind), int(Kind::Region));  // the area under the generated joint
        QCOMPARE(r.vertex, -1);
        // A hole's edge names the hole; the area of the hole is nothing.
        r = gui::pick_item(m, {5.0, 4.03}, 0.1);
        QCOMPARE(r.ring, 1);
        QCOMPARE(r.vertex, -1);
        QVERIFY(!gui::pick_item(m, {5.0, 5.0}, 0.1).valid());
        QVERIFY(!gui::pick_item(m, {20.0, 20.0}, 0.1).valid());
    }

    void movesAndDeletesItemsUndoably() {
        using Kind = gui::ItemRef::Kind;
        ModelDocument document;
        document.setModel(picking_model());
        const Model original = document.model();
        // A whole region moves with its hole.
        QVERIFY(document.moveItem({Kind::Region, 0}, {2.0, -1.0}));
        QCOMPARE(document.model().regions[0].boundary[2].x, 12.0);
        QCOMPARE(document.model().regions[0].holes[0][0].y, 3.0);
        QVERIFY(document.undoStack()->undoText().contains(QStringLiteral("region")));
        document.undoStack()->undo();
        COMPARE_MODELS(document.model(), original);
        // One vertex; one hole alone.
        QVERIFY(document.moveItem({Kind::Region, 0, 0, 2}, {1.5, 0.5}));
        QCOMPARE(document.model().regions[0].boundary[2].x, 11.5);
        QCOMPARE(document.model().regions[0].boundary[1].x, 10.0);
        QVERIFY(document.undoStack()->undoText().contains(QStringLiteral("vertex 3")));
        QVERIFY(document.moveItem({Kind::Region, 0, 1, -1}, {0.5, 0.0}));
        QCOMPARE(document.model().regions[0].holes[0][0].x, 4.5);
        QCOMPARE(document.model().regions[0].boundary[0].x, 0.0);
        document.undoStack()->undo();
        document.undoStack()->undo();
        COMPARE_MODELS(document.model(), original);
        // Deleting: a vertex of the square leaves a triangle, whose vertices then stay.
        QVERIFY(document.deleteItem({Kind::Region, 0, 0, 3}));
        QCOMPARE(document.model().regions[0].boundary.size(), std::size_t(3));
        QVERIFY(!document.deleteItem({Kind::Region, 0, 0, 0}));
        // A hole, a joint, a point; a missing item is refused.
        QVERIFY(document.deleteItem({Kind::Region, 0, 1, -1}));
        QVERIFY(document.model().regions[0].holes.empty());
        QVERIFY(document.deleteItem({Kind::FixedPoint, 0}));
        QVERIFY(document.model().fixed_points.empty());
        QVERIFY(!document.deleteItem({Kind::FixedPoint, 0}));
        QVERIFY(document.deleteItem({Kind::Joint, 0, 0, 1}));  // a two-point joint goes whole
        QCOMPARE(document.model().joints.size(), std::size_t(1));
        QCOMPARE(document.model().joints[0].joint_set, 0);
        for (int i = 0; i < 4; ++i) document.undoStack()->undo();
        COMPARE_MODELS(document.model(), original);
        QVERIFY(!document.isModified());
        QVERIFY(!document.moveItem({Kind::Roller, 3}, {1.0, 0.0}));
    }

    void waterTablesArePickedMovedAndDeletedPerStage() {
        using Kind = gui::ItemRef::Kind;
        ModelDocument document;
        Model m = picking_model();
        m.water.piezometric_line = {{2, 7}, {8, 7}};
        m.stages.resize(3);
        Water low;
        low.piezometric_line = {{0, 3}, {5, 2}, {10, 3}};
        m.stages[1].water = low;  // stage 2 lowers it; stage 3 keeps that
        document.setModel(m);
        const Model original = document.model();
        QCOMPARE(gui::water_table_in(m, -1).index, 0);
        QCOMPARE(gui::water_table_in(m, 0).index, 0);
        QCOMPARE(gui::water_table_in(m, 2).index, 2);
        // The line of the stage shown, held level to the model's sides: the model's in stage 1.
        gui::ItemRef r = gui::pick_item(m, {9.5, 7.03}, 0.1, 0);
        QCOMPARE(int(r.kind), int(Kind::WaterTable));
        QCOMPARE(r.index, 0);
        QCOMPARE(r.vertex, -1);
        QCOMPARE(int(gui::pick_item(m, {9.5, 3.0}, 0.1, 0).kind), int(Kind::Region));  // a later stage's line
        r = gui::pick_item(m, {5.02, 2.0}, 0.1, 2);  // stage 3 shows stage 2's water
        QCOMPARE(int(r.kind), int(Kind::WaterTable));
        QCOMPARE(r.index, 2);
        QCOMPARE(r.vertex, 1);
        QVERIFY(document.itemName(r).contains(QStringLiteral("water table")));
        // A vertex moves, but not past its neighbour.
        QVERIFY(document.moveItem(r, {1.0, 0.5}));
        QCOMPARE(document.model().stages[1].water->piezometric_line[1].x, 6.0);
        QVERIFY(!document.moveItem(r, {4.0, 0.0}));
        // Deleting the stage's line makes that stage dry, not "as before"; the model's stays.
        QVERIFY(document.deleteItem({Kind::WaterTable, 2}));
        QVERIFY(document.model().stages[1].water.has_value());
        QVERIFY(!document.model().stages[1].water->present());
        QVERIFY(document.model().water.present());
        QVERIFY(!gui::water_table_in(document.model(), 1).valid());
        // A vertex of a two-point line deletes the line.
        QVERIFY(document.deleteItem({Kind::WaterTable, 0, 0, 1}));
        QVERIFY(!document.model().water.present());
        QVERIFY(!has_water(document.model()));
        for (int i = 0; i < 3; ++i) document.undoStack()->undo();
        COMPARE_MODELS(document.model(), original);
        // Set per stage: none = as the stage before.
        QVERIFY(document.setWater(2, Water{}));
        QVERIFY(document.model().stages[2].water && !document.model().stages[2].water->present());
        QVERIFY(document.setWater(1, std::nullopt));
        QVERIFY(!document.model().stages[1].water.has_value());
        QVERIFY(!document.setWater(3, Water{}));
        document.undoStack()->undo();
        document.undoStack()->undo();
        COMPARE_MODELS(document.model(), original);
    }

    void opensAFileClean() {
        ModelDocument document;
        QSignalSpy path_spy(&document, &ModelDocument::pathChanged);
        QSignalSpy changed_spy(&document, &ModelDocument::changed);
        QVERIFY(openExample(document));
        QCOMPARE(document.path(), example("kirsch.json"));
        QCOMPARE(path_spy.count(), 1);
        QVERIFY(changed_spy.count() >= 1);
        QVERIFY(!document.isModified());
        const ReadResult direct = read_model_file(example("kirsch.json").toStdString());
        QVERIFY(direct.model);
        COMPARE_MODELS(document.model(), *direct.model);
    }

    void aMissingFileLeavesTheDocumentAlone() {
        ModelDocument document;
        QVERIFY(openExample(document));
        const Model before = document.model();
        const auto diagnostics = document.open(QStringLiteral("/no/such/model.json"));
        QVERIFY(has_errors(diagnostics));
        QCOMPARE(document.path(), example("kirsch.json"));
        COMPARE_MODELS(document.model(), before);
    }

    void editsUndoAndRedo() {
        ModelDocument document;
        QVERIFY(openExample(document));
        const Model original = document.model();
        QSignalSpy changed_spy(&document, &ModelDocument::changed);
        edit(document);
        QCOMPARE(changed_spy.count(), 2);
        const Model edited = document.model();
        QCOMPARE(edited.regions.size(), original.regions.size() + 1);
        QCOMPARE(edited.regions.back().name, std::string("added block"));
        QCOMPARE(edited.regions.back().material, 0);
        QCOMPARE(edited.joints.size(), original.joints.size() + 1);
        QCOMPARE(edited.joints.back().points.size(), std::size_t(3));
        QCOMPARE(edited.joints.back().name, "joint " + std::to_string(original.joints.size() + 1));
        QCOMPARE(document.undoStack()->count(), 2);
        QVERIFY(!document.undoStack()->text(0).isEmpty());
        QVERIFY(!document.undoStack()->text(1).isEmpty());

        document.undoStack()->undo();
        document.undoStack()->undo();
        COMPARE_MODELS(document.model(), original);
        document.undoStack()->redo();
        document.undoStack()->redo();
        COMPARE_MODELS(document.model(), edited);
        QCOMPARE(changed_spy.count(), 6);
    }

    void materialAndAnalysisSettingsAreUndoable() {
        ModelDocument document;
        QVERIFY(openExample(document));
        const Model original = document.model();
        Material m = original.materials[0];
        m.name = "changed";
        m.young_modulus *= 2;
        m.parameters["friction_angle"] = 0.5;
        document.setMaterial(0, m);
        AnalysisSettings a = original.analysis;
        a.steps = 1234;
        a.kind = AnalysisSettings::Kind::Dynamic;
        document.setAnalysisSettings(a);
        QCOMPARE(document.model().materials[0].name, std::string("changed"));
        QCOMPARE(document.model().analysis.steps, 1234);
        const Model edited = document.model();
        document.undoStack()->undo();
        QCOMPARE(document.model().analysis.steps, original.analysis.steps);
        document.undoStack()->undo();
        COMPARE_MODELS(document.model(), original);
        document.undoStack()->redo();
        document.undoStack()->redo();
        COMPARE_MODELS(document.model(), edited);
    }

    void supportsLoadsPointsAndStressAreUndoable() {
        ModelDocument document;
        QVERIFY(openExample(document));
        const Model original = document.model();
        const std::size_t points = original.measurement_points.size();
        FixedPoint f;
        f.point = {1, 2};
        document.addFixedPoint(f);
        PointLoad l;
        l.point = {3, 4};
        l.force = {0, -1e3};
        document.addPointLoad(l);
        EdgePressure e;
        e.from = {0, 0};
        e.to = {1, 0};
        e.pressure = 1e5;
        document.addEdgePressure(e);
        document.addMeasurementPoint(MeasurementPoint{"", {5, 6}});
        document.addMeasurementPoint(MeasurementPoint{"", {7, 8}});
        const auto& added = document.model().measurement_points;
        QCOMPARE(added.size(), points + 2);
        QVERIFY(added[points].name != added[points + 1].name);  // auto names stay unique
        QVERIFY(!document.model().fixed_points.back().name.empty());
        QCOMPARE(document.model().point_loads.back().force.y, -1e3);
        QCOMPARE(document.model().edge_pressures.back().pressure, 1e5);

        InitialStress s;
        s.kind = InitialStress::Kind::Gravity;
        s.surface_y = 20.0;
        s.k0 = 0.5;
        document.setInitialStress(s);
        QCOMPARE(document.model().initial_stress.k0, 0.5);
        if (!document.model().joint_materials.empty()) {
            JointMaterial j = document.model().joint_materials[0];
            j.cohesion = 12345.0;
            document.setJointMaterial(0, j);
            QCOMPARE(document.model().joint_materials[0].cohesion, 12345.0);
        }
        while (document.undoStack()->canUndo()) document.undoStack()->undo();
        COMPARE_MODELS(original, document.model());
        QVERIFY(!document.isModified());
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, gui::SetJointMaterialCommand(&document, 999, JointMaterial{}));
    }

    void modifiedFollowsUndoRedoAndSave() {
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        ModelDocument document;
        QVERIFY(openExample(document));
        QSignalSpy modified_spy(&document, &ModelDocument::modifiedChanged);
        QVERIFY(!document.isModified());
        edit(document);
        QVERIFY(document.isModified());
        QCOMPARE(modified_spy.count(), 1);
        QCOMPARE(modified_spy.last().at(0).toBool(), true);
        document.undoStack()->undo();
        document.undoStack()->undo();
        QVERIFY(!document.isModified());  // back at the file's state
        QCOMPARE(modified_spy.last().at(0).toBool(), false);
        document.undoStack()->redo();
        QVERIFY(document.isModified());

        const QString path = folder.filePath(QStringLiteral("saved.json"));
        QSignalSpy path_spy(&document, &ModelDocument::pathChanged);
        QString error;
        QVERIFY2(document.saveAs(path, &error), qPrintable(error));
        QCOMPARE(document.path(), path);
        QCOMPARE(path_spy.count(), 1);
        QVERIFY(!document.isModified());
        document.undoStack()->redo();
        QVERIFY(document.isModified());
        QVERIFY2(document.save(&error), qPrintable(error));
        QVERIFY(!document.isModified());
        document.undoStack()->undo();  // now differs from the saved file
        QVERIFY(document.isModified());
    }

    void savesAndReopensTheSameModel() {
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        ModelDocument document;
        QVERIFY(openExample(document));
        edit(document);
        const QString path = folder.filePath(QStringLiteral("edited.json"));
        QString error;
        QVERIFY2(document.saveAs(path, &error), qPrintable(error));

        ModelDocument reopened;
        const auto diagnostics = reopened.open(path);
        QVERIFY2(!has_errors(diagnostics), qPrintable(messages(diagnostics)));
        COMPARE_MODELS(reopened.model(), document.model());
        QVERIFY(!reopened.isModified());
        // Only the saved file is in the folder (no temporary left behind).
        QCOMPARE(QDir(folder.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("edited.json")});
    }

    void savingIntoAMissingFolderFails() {
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        ModelDocument document;
        QVERIFY(openExample(document));
        edit(document);
        const QString missing = folder.filePath(QStringLiteral("missing"));
        QString error;
        QVERIFY(!document.saveAs(missing + QStringLiteral("/model.json"), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(error.contains(QStringLiteral("model.json")));
        QCOMPARE(document.path(), example("kirsch.json"));  // unchanged
        QVERIFY(document.isModified());                     // still unsaved
        QVERIFY(!QFileInfo::exists(missing));
        QVERIFY(QDir(folder.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden).isEmpty());
    }

    void savingIntoAReadOnlyFolderFails() {
        if (::geteuid() == 0) QSKIP("root may write into read-only folders");
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        QVERIFY(QFile::setPermissions(folder.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        ModelDocument document;
        QVERIFY(openExample(document));
        QString error;
        const bool saved = document.saveAs(folder.filePath(QStringLiteral("model.json")), &error);
        QFile::setPermissions(folder.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        QVERIFY(!saved);
        QVERIFY(!error.isEmpty());
        QVERIFY(QDir(folder.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden).isEmpty());
    }

    void saveWithoutAFileFails() {
        ModelDocument document;
        Model m;
        m.name = "new";
        document.setModel(m);
        QString error;
        QVERIFY(!document.save(&error));
        QVERIFY(!error.isEmpty());
    }
};

QTEST_GUILESS_MAIN(DocumentTest)
#include "DocumentTest.moc"
