#include "document/ModelDocument.hpp"

#include <QDir>
#include <QFileInfo>

#include "document/EditCommands.hpp"
#include "geometry/PolygonChecks.hpp"
#include "io/ModelReader.hpp"
#include "io/ModelWriter.hpp"

#include <QFile>

#include <algorithm>
#include <exception>
#include <string>

namespace mcdda::gui {

namespace {
std::string local_path(const QString& path) { return QFile::encodeName(path).toStdString(); }

/// `stem` + " N" with the smallest N ≥ size + 1 that no item of `items` is named yet.
template <typename T>
std::string unused_name(const std::vector<T>& items, const std::string& stem) {
    for (std::size_t n = items.size() + 1;; ++n) {
        const std::string name = stem + " " + std::to_string(n);
        if (std::none_of(items.begin(), items.end(), [&](const T& x) { return x.name == name; })) return name;
    }
}
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
    // Record files are named relative to the model's folder: saved into another folder, they
    // are named from there, or the file would point beside the new model (where they are not).
    Model rebased = model_;
    bool moved = false;
    if (!path_.isEmpty()) {
        const QDir from = QFileInfo(path_).absoluteDir(), to = QFileInfo(path).absoluteDir();
        for (GroundMotion& g : rebased.ground_motions) {
            const QString file = QString::fromStdString(g.file);
            if (file.isEmpty() || QFileInfo(file).isAbsolute() || from == to) continue;
            g.file = to.relativeFilePath(from.absoluteFilePath(file)).toStdString();
            moved = true;
        }
    }
    try {
        write_model_file(local_path(path), rebased);
    } catch (const std::exception& e) {
        if (error) *error = tr("Cannot save %1: %2").arg(path, QString::fromLocal8Bit(e.what()));
        return false;
    }
    if (moved) {
        // The edits before name the files from the old folder: their history goes with it.
        undo_.clear();
        model_ = std::move(rebased);
        emit changed();
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

void ModelDocument::setJointMaterial(int index, const JointMaterial& material) {
    undo_.push(new SetJointMaterialCommand(this, index, material));
}

void ModelDocument::setInitialStress(const InitialStress& stress) {
    undo_.push(new SetInitialStressCommand(this, stress));
}

void ModelDocument::addFixedPoint(const FixedPoint& point) {
    FixedPoint p = point;
    if (p.name.empty()) p.name = unused_name(model_.fixed_points, "fixed point");
    const QString text = tr("Add fixed point \"%1\"").arg(QString::fromStdString(p.name));
    undo_.push(new AddItemCommand<FixedPoint>(this, &Model::fixed_points, std::move(p), text));
}

void ModelDocument::addPointLoad(const PointLoad& load) {
    PointLoad l = load;
    if (l.name.empty()) l.name = unused_name(model_.point_loads, "load");
    const QString text = tr("Add point load \"%1\"").arg(QString::fromStdString(l.name));
    undo_.push(new AddItemCommand<PointLoad>(this, &Model::point_loads, std::move(l), text));
}

void ModelDocument::addEdgePressure(const EdgePressure& pressure) {
    EdgePressure e = pressure;
    if (e.name.empty()) e.name = unused_name(model_.edge_pressures, "pressure");
    const QString text = tr("Add edge pressure \"%1\"").arg(QString::fromStdString(e.name));
    undo_.push(new AddItemCommand<EdgePressure>(this, &Model::edge_pressures, std::move(e), text));
}

void ModelDocument::addMeasurementPoint(const MeasurementPoint& point) {
    MeasurementPoint p = point;
    if (p.name.empty()) p.name = unused_name(model_.measurement_points, "point");
    const QString text = tr("Add measurement point \"%1\"").arg(QString::fromStdString(p.name));
    undo_.push(new AddItemCommand<MeasurementPoint>(this, &Model::measurement_points, std::move(p), text));
}

void ModelDocument::addHole(int region, const Ring& hole) {
    undo_.push(new AddHoleCommand(this, region, hole));
}

int ModelDocument::regionContaining(const std::vector<Point2>& ring) const {
    if (ring.empty()) return -1;
    for (std::size_t r = 0; r < model_.regions.size(); ++r) {
        const Region& region = model_.regions[r];
        if (std::all_of(ring.begin(), ring.end(), [&](const Point2& p) { return region_contains(region, p); }))
            return static_cast<int>(r);
    }
    return -1;
}

void ModelDocument::addJointSet(const JointSet& set) {
    JointSet j = set;
    if (j.name.empty()) j.name = unused_name(model_.joint_sets, "joint set");
    const QString text = tr("Add joint set \"%1\"").arg(QString::fromStdString(j.name));
    undo_.push(new AddItemCommand<JointSet>(this, &Model::joint_sets, std::move(j), text));
}

int ModelDocument::addMaterial(const Material& material) {
    Material m = material;
    if (m.name.empty()) m.name = unused_name(model_.materials, "material");
    const QString text = tr("Add material \"%1\"").arg(QString::fromStdString(m.name));
    undo_.push(new AddItemCommand<Material>(this, &Model::materials, std::move(m), text));
    return static_cast<int>(model_.materials.size()) - 1;
}

int ModelDocument::addJointMaterial(const JointMaterial& material) {
    JointMaterial m = material;
    if (m.name.empty()) m.name = unused_name(model_.joint_materials, "joint material");
    const QString text = tr("Add joint material \"%1\"").arg(QString::fromStdString(m.name));
    undo_.push(new AddItemCommand<JointMaterial>(this, &Model::joint_materials, std::move(m), text));
    return static_cast<int>(model_.joint_materials.size()) - 1;
}

void ModelDocument::setRegionMaterial(int region, int material) {
    if (region < 0 || static_cast<std::size_t>(region) >= model_.regions.size()) return;
    const auto r = static_cast<std::size_t>(region);
    undo_.push(new SetValueCommand<int>(this, [r](Model& m) -> int& { return m.regions[r].material; }, material,
                                        tr("Assign a material to %1").arg(itemName({ItemRef::Kind::Region, region}))));
}

void ModelDocument::setJointMaterialOfJoint(int joint, int jointMaterial) {
    if (joint < 0 || static_cast<std::size_t>(joint) >= model_.joints.size()) return;
    const auto j = static_cast<std::size_t>(joint);
    undo_.push(new SetValueCommand<int>(this, [j](Model& m) -> int& { return m.joints[j].joint_material; },
                                        jointMaterial,
                                        tr("Assign a joint material to %1").arg(itemName({ItemRef::Kind::Joint, joint}))));
}

bool ModelDocument::setWater(int stage, const std::optional<Water>& water) {
    if (stage < 0) {
        const Water w = water.value_or(Water{});
        undo_.push(new SetValueCommand<Water>(this, [](Model& m) -> Water& { return m.water; }, w,
                                              w.present() ? tr("Set the water table") : tr("Make the ground dry")));
        return true;
    }
    if (static_cast<std::size_t>(stage) >= model_.stages.size()) return false;
    const auto s = static_cast<std::size_t>(stage);
    const QString name = QString::fromStdString(model_.stages[s].name);
    const QString text = !water               ? tr("Stage \"%1\": water as in the stage before").arg(name)
                         : water->present() ? tr("Stage \"%1\": set the water table").arg(name)
                                            : tr("Stage \"%1\": make the ground dry").arg(name);
    undo_.push(new SetValueCommand<std::optional<Water>>(
        this, [s](Model& m) -> std::optional<Water>& { return m.stages[s].water; }, water, text));
    return true;
}

int ModelDocument::addGroundMotion(const GroundMotion& motion) {
    GroundMotion g = motion;
    if (g.name.empty()) g.name = unused_name(model_.ground_motions, "record");
    const QString text = tr("Add ground motion \"%1\"").arg(QString::fromStdString(g.name));
    undo_.push(new AddItemCommand<GroundMotion>(this, &Model::ground_motions, std::move(g), text));
    return static_cast<int>(model_.ground_motions.size()) - 1;
}

void ModelDocument::setGroundMotion(int index, const GroundMotion& motion) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.ground_motions.size()) return;
    const auto i = static_cast<std::size_t>(index);
    undo_.push(new SetValueCommand<GroundMotion>(
        this, [i](Model& m) -> GroundMotion& { return m.ground_motions[i]; }, motion,
        tr("Change ground motion \"%1\"").arg(QString::fromStdString(motion.name))));
}

void ModelDocument::removeGroundMotion(int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.ground_motions.size()) return;
    Model m = model_;
    const QString name = QString::fromStdString(m.ground_motions[static_cast<std::size_t>(index)].name);
    m.ground_motions.erase(m.ground_motions.begin() + index);
    // The base refers to records by index: the removed one goes, later ones move down.
    for (int* r : {&m.base_motion.x, &m.base_motion.y}) {
        if (*r == index) *r = -1;
        else if (*r > index) --*r;
    }
    if (m.base_motion.x < 0 && m.base_motion.y < 0) m.base_motion.kind = BaseMotion::Kind::None;
    replaceModel(std::move(m), tr("Remove ground motion \"%1\"").arg(name));
}

void ModelDocument::setBaseMotion(const BaseMotion& base) {
    const QString text = base.kind == BaseMotion::Kind::None    ? tr("Remove the base motion")
                         : base.kind == BaseMotion::Kind::Rigid ? tr("Shake a rigid base")
                                                                : tr("Shake a compliant base");
    undo_.push(new SetValueCommand<BaseMotion>(this, [](Model& m) -> BaseMotion& { return m.base_motion; }, base, text));
}

void ModelDocument::addAbsorbingBoundary(const AbsorbingBoundary& boundary) {
    AbsorbingBoundary a = boundary;
    if (a.name.empty()) a.name = unused_name(model_.absorbing_boundaries, "absorbing boundary");
    const QString text = tr("Add absorbing boundary \"%1\"").arg(QString::fromStdString(a.name));
    undo_.push(new AddItemCommand<AbsorbingBoundary>(this, &Model::absorbing_boundaries, std::move(a), text));
}

bool ModelDocument::setSeismicCoefficient(int stage, const std::optional<SeismicCoefficient>& k) {
    if (stage < 0) {
        undo_.push(new SetValueCommand<SeismicCoefficient>(
            this, [](Model& m) -> SeismicCoefficient& { return m.seismic_coefficient; }, k.value_or(SeismicCoefficient{}),
            tr("Set the seismic coefficient")));
        return true;
    }
    if (static_cast<std::size_t>(stage) >= model_.stages.size()) return false;
    const auto s = static_cast<std::size_t>(stage);
    undo_.push(new SetValueCommand<std::optional<SeismicCoefficient>>(
        this, [s](Model& m) -> std::optional<SeismicCoefficient>& { return m.stages[s].seismic_coefficient; }, k,
        tr("Stage \"%1\": set the seismic coefficient").arg(QString::fromStdString(model_.stages[s].name))));
    return true;
}

void ModelDocument::replaceModel(Model model, const QString& text) {
    // The whole model is swapped: exact undo whatever the edit touched.
    undo_.push(new SetValueCommand<Model>(this, [](Model& m) -> Model& { return m; }, std::move(model), text));
}

bool ModelDocument::moveItem(const ItemRef& ref, const Point2& delta) {
    Model moved = model_;
    if (!move_item(moved, ref, delta)) return false;
    replaceModel(std::move(moved), tr("Move %1").arg(itemName(ref)));
    return true;
}

bool ModelDocument::deleteItem(const ItemRef& ref) {
    Model reduced = model_;
    const QString name = itemName(ref);
    if (!delete_item(reduced, ref)) return false;
    replaceModel(std::move(reduced), tr("Delete %1").arg(name));
    return true;
}

QString ModelDocument::itemName(const ItemRef& ref) const {
    if (!item_exists(model_, ref)) return QString();
    using Kind = ItemRef::Kind;
    const auto i = static_cast<std::size_t>(ref.index);
    auto named = [&](const std::string& name, const QString& fallback) {
        return name.empty() ? fallback.arg(ref.index + 1) : QStringLiteral("\"%1\"").arg(QString::fromStdString(name));
    };
    QString item;
    switch (ref.kind) {
    case Kind::Region: item = named(model_.regions[i].name, tr("region %1")); break;
    case Kind::Joint: item = named(model_.joints[i].name, tr("joint %1")); break;
    case Kind::FixedPoint: item = named(model_.fixed_points[i].name, tr("fixed point %1")); break;
    case Kind::Roller: item = named(model_.rollers[i].name, tr("roller %1")); break;
    case Kind::PointLoad: item = named(model_.point_loads[i].name, tr("load %1")); break;
    case Kind::EdgePressure: item = named(model_.edge_pressures[i].name, tr("pressure %1")); break;
    case Kind::MeasurementPoint: item = named(model_.measurement_points[i].name, tr("point %1")); break;
    case Kind::AbsorbingBoundary:
        item = named(model_.absorbing_boundaries[i].name, tr("absorbing boundary %1"));
        break;
    case Kind::CompliantBase: item = tr("the compliant base"); break;
    case Kind::WaterTable:
        item = ref.index == 0 ? tr("the water table")
                              : tr("the water table of stage \"%1\"")
                                    .arg(QString::fromStdString(model_.stages[i - 1].name));
        break;
    case Kind::None: break;
    }
    if (ref.kind == Kind::Region && ref.ring > 0) item = tr("hole %1 of %2").arg(ref.ring).arg(item);
    if (ref.vertex >= 0) item = tr("vertex %1 of %2").arg(ref.vertex + 1).arg(item);
    return item;
}

void ModelDocument::setPath(const QString& path) {
    if (path == path_) return;
    path_ = path;
    emit pathChanged();
}

QString ModelDocument::displayName() const
{
    const QString model_name = QString::fromStdString(model_.name);
    if (path_.isEmpty()) return model_name.isEmpty() ? tr("Untitled") : model_name;
    const QString file = QFileInfo(path_).fileName();
    return model_name.isEmpty() ? file : tr("%1 (%2)").arg(file, model_name);
}

}  // namespace mcdda::gui
