#pragma once
/// \file ModelDocument.hpp
/// The model being edited in the desktop program: the Model, its file, the undo history and
/// whether it differs from the file (the undo stack's clean state). Qt Core/Gui only — no
/// widgets, no VTK — so it is tested without a display.
///
/// Every edit goes through a QUndoCommand (Commands.hpp) pushed onto undoStack(); the commands
/// change the model through DocumentCommand, which emits changed().

#include "document/ModelItems.hpp"
#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <optional>
#include <vector>

namespace mcdda::gui {

class ModelDocument : public QObject {
    Q_OBJECT

public:
    explicit ModelDocument(QObject* parent = nullptr);
    ~ModelDocument() override;

    const Model& model() const { return model_; }
    /// The model file; empty for a document never saved.
    QString path() const { return path_; }
    /// What the window title calls the model: "file.json (model name)", the file or the
    /// model's name alone, or "Untitled".
    QString displayName() const;
    QUndoStack* undoStack() { return &undo_; }
    /// True when the model differs from its file (or from the state when it was set).
    bool isModified() const { return !undo_.isClean(); }

    /// Replaces the model (a new document): the undo history is cleared, the document is clean.
    void setModel(const Model& model, const QString& path = QString());

    /// Reads the model file at `path` into the document. Returns the reader's messages; when
    /// they contain errors the document is unchanged.
    std::vector<Diagnostic> open(const QString& path);

    /// Writes the model to its file (atomically: a failure leaves the old file as it was).
    /// Returns false with a message in `error` when the document has no file or writing failed.
    bool save(QString* error = nullptr);
    /// Writes the model to `path` and makes that the document's file on success. Record files
    /// named relative to the old file's folder are named from the new one's; when that changes
    /// any, the undo history is cleared (its edits name them from the old folder).
    bool saveAs(const QString& path, QString* error = nullptr);

    // Undoable edits (each pushes one command; see Commands.hpp).
    /// Adds a region of material `material` (an index into Model::materials); an empty name
    /// becomes "region N".
    void addRegion(const Ring& boundary, int material, const QString& name = QString());
    /// Adds an explicit joint along the polyline; an empty name becomes "joint N".
    void addJoint(const std::vector<Point2>& points, int jointMaterial = -1, const QString& name = QString());
    /// Adds a roller support (an empty name becomes "roller N").
    void addRoller(const Roller& roller);
    /// Replaces material `index`.
    void setMaterial(int index, const Material& material);
    void setAnalysisSettings(const AnalysisSettings& settings);
    /// Replaces joint material `index`.
    void setJointMaterial(int index, const JointMaterial& material);
    void setInitialStress(const InitialStress& stress);
    /// Adds a fixed point, point load, edge pressure or measurement point; an empty name becomes
    /// "fixed point N", "load N", "pressure N" or "point N" (a name not used yet).
    void addFixedPoint(const FixedPoint& point);
    void addPointLoad(const PointLoad& load);
    void addEdgePressure(const EdgePressure& pressure);
    void addMeasurementPoint(const MeasurementPoint& point);

    /// Adds `hole` as an opening of region `region` (an index into Model::regions).
    void addHole(int region, const Ring& hole);
    /// The region whose area holds every vertex of `ring` (inside its boundary, outside its
    /// holes); −1 when there is none.
    int regionContaining(const std::vector<Point2>& ring) const;
    /// Adds a joint set; an empty name becomes "joint set N".
    void addJointSet(const JointSet& set);
    /// Adds a material / joint material (an empty name becomes "material N" / "joint material
    /// N"); returns its index.
    int addMaterial(const Material& material);
    int addJointMaterial(const JointMaterial& material);
    /// Region `region` is made of material `material`.
    void setRegionMaterial(int region, int material);
    /// Explicit joint `joint` gets joint material `jointMaterial` (−1 = the default one).
    void setJointMaterialOfJoint(int joint, int jointMaterial);

    /// Sets the ground water as one undoable edit: the model's (`stage` -1; no water = dry) or,
    /// from stage `stage` on, that stage's (no water: as the stage before; an empty line: dry).
    /// False when there is no such stage.
    bool setWater(int stage, const std::optional<Water>& water);

    // Earthquakes (docs/model-format.md, "Earthquakes"); each one undoable edit.
    /// Adds a ground motion (an empty name becomes "record N"); returns its index.
    int addGroundMotion(const GroundMotion& motion);
    /// Replaces ground motion `index` (its name, units, scale, correction).
    void setGroundMotion(int index, const GroundMotion& motion);
    /// Removes ground motion `index`; a base motion using it loses that component (and is
    /// switched off when it has none left), later indices move down.
    void removeGroundMotion(int index);
    void setBaseMotion(const BaseMotion& base);
    /// Adds an absorbing boundary (an empty name becomes "absorbing boundary N").
    void addAbsorbingBoundary(const AbsorbingBoundary& boundary);
    /// The seismic coefficient of the model (`stage` -1) or, from stage `stage` on, that stage's
    /// (none: as the stage before). False when there is no such stage.
    bool setSeismicCoefficient(int stage, const std::optional<SeismicCoefficient>& k);

    /// Replaces the whole model as one undoable edit named `text`: for edits that touch several
    /// lists at once (a deletion that renumbers references, a move of a region with its holes).
    void replaceModel(Model model, const QString& text);
    /// Moves an item, a hole or a vertex by `delta` (m); false when `ref` does not exist.
    bool moveItem(const ItemRef& ref, const Point2& delta);
    /// Deletes an item, a hole or a vertex (see delete_item()); false when it cannot go.
    bool deleteItem(const ItemRef& ref);
    /// How the item is called in menus and messages: its name, or its kind and number, and
    /// "vertex N of ..." for a vertex.
    QString itemName(const ItemRef& ref) const;

signals:
    /// The model changed (an edit, undo, redo, open or setModel).
    void changed();
    /// The file path changed (open, setModel, saveAs).
    void pathChanged();
    /// isModified() changed.
    void modifiedChanged(bool modified);

private:
    friend class DocumentCommand;
    void setPath(const QString& path);

    Model model_;
    QString path_;
    QUndoStack undo_;
};

}  // namespace mcdda::gui
