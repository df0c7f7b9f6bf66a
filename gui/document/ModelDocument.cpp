#include "document/ModelDocument.hpp"

#include "document/Commands.hpp"
#include "io/ModelReader.hpp"
#include "io/ModelWriter.hpp"

#include <QFile>

#include <exception>

namespace mcdda::gui {

namespace {
std::string local_path(const QString& path) { return QFile::encodeName(path).toStdString(); }
}  // namespace

ModelDocument::ModelDocument(QObject* parent) : QObject(parent) {
    connect(&undo_, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

ModelDocument::~ModelDocument() = default;

void ModelDocument::setModel(const Model& model, const QString& path) {
    undo_.clear();  // clean afterwards (emits cleanChanged → modifiedChanged when it was not)
    model_ = model;
    setPath(path);
    emit changed();
}

std::vector<Diagnostic> ModelDocument::open(const QString& path) {
    ReadResult r = read_model_file(local_path(path));
    if (r.model) setModel(*r.model, path);
    return std::move(r.diagnostics);
}

bool ModelDocument::save(QString* error) {
    if (path_.isEmpty()) {
        if (error) *error = tr("The model has no file yet; choose one with Save As.");
        return false;
    }
    return saveAs(path_, error);
}

bool ModelDocument::saveAs(const QString& path, QString* error) {
    try {
        write_model_file(local_path(path), model_);
    } catch (const std::exception& e) {
        if (error) *error = tr("Cannot save %1: %2").arg(path, QString::fromLocal8Bit(e.what()));
        return false;
    }
    setPath(path);
    undo_.setClean();
    return true;
}

void ModelDocument::addRegion(const Ring& boundary, int material, const QString& name) {
    Region r;
    r.name = name.toStdString();
    r.material = material;
    r.boundary = boundary;
    undo_.push(new AddRegionCommand(this, std::move(r)));
}

void ModelDocument::addJoint(const std::vector<Point2>& points, int jointMaterial, const QString& name) {
    Joint j;
    j.name = name.toStdString();
    j.points = points;
    j.joint_material = jointMaterial;
    undo_.push(new AddJointCommand(this, std::move(j)));
}

void ModelDocument::addRoller(const Roller& roller) {
    undo_.push(new AddRollerCommand(this, roller));
}

void ModelDocument::setMaterial(int index, const Material& material) {
    undo_.push(new SetMaterialCommand(this, index, material));
}

void ModelDocument::setAnalysisSettings(const AnalysisSettings& settings) {
    undo_.push(new SetAnalysisSettingsCommand(this, settings));
}

void ModelDocument::setPath(const QString& path) {
    if (path == path_) return;
    path_ = path;
    emit pathChanged();
}

}  // namespace mcdda::gui
