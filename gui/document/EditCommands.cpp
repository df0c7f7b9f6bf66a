#include "document/EditCommands.hpp"

#include "document/ModelDocument.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace mcdda::gui {

Model& DocumentCommand::model() { return document_->model_; }

void DocumentCommand::notify() { emit document_->changed(); }

AddRegionCommand::AddRegionCommand(ModelDocument* document, Region region, QUndoCommand* parent)
    : DocumentCommand(document, parent), region_(std::move(region)) {
    if (region_.name.empty()) region_.name = "region " + std::to_string(document->model().regions.size() + 1);
    setText(tr("Add region \"%1\"").arg(QString::fromStdString(region_.name)));
}

void AddRegionCommand::redo() {
    model().regions.push_back(region_);
    notify();
}

void AddRegionCommand::undo() {
    model().regions.pop_back();
    notify();
}

AddJointCommand::AddJointCommand(ModelDocument* document, Joint joint, QUndoCommand* parent)
    : DocumentCommand(document, parent), joint_(std::move(joint)) {
    joint_.joint_set = -1;
    if (joint_.name.empty()) {
        const auto& joints = document->model().joints;
        const auto explicit_joints = std::count_if(joints.begin(), joints.end(), [](const Joint& j) { return j.joint_set < 0; });
        joint_.name = "joint " + std::to_string(explicit_joints + 1);
    }
    setText(tr("Add joint \"%1\"").arg(QString::fromStdString(joint_.name)));
}

void AddJointCommand::redo() {
    auto& joints = model().joints;
    const auto first_generated = std::find_if(joints.begin(), joints.end(), [](const Joint& j) { return j.joint_set >= 0; });
    index_ = static_cast<std::size_t>(first_generated - joints.begin());
    joints.insert(first_generated, joint_);
    notify();
}

void AddJointCommand::undo() {
    auto& joints = model().joints;
    joints.erase(joints.begin() + static_cast<std::ptrdiff_t>(index_));
    notify();
}

AddRollerCommand::AddRollerCommand(ModelDocument* document, Roller roller, QUndoCommand* parent)
    : DocumentCommand(document, parent), roller_(std::move(roller)) {
    if (roller_.name.empty()) roller_.name = "roller " + std::to_string(document->model().rollers.size() + 1);
    setText(tr("Add roller \"%1\"").arg(QString::fromStdString(roller_.name)));
}

void AddRollerCommand::redo() {
    model().rollers.push_back(roller_);
    notify();
}

void AddRollerCommand::undo() {
    model().rollers.pop_back();
    notify();
}

SetMaterialCommand::SetMaterialCommand(ModelDocument* document, int index, Material material, QUndoCommand* parent)
    : DocumentCommand(document, parent), index_(index), new_(std::move(material)) {
    const auto& materials = document->model().materials;
    if (index < 0 || static_cast<std::size_t>(index) >= materials.size())
        throw std::out_of_range("SetMaterialCommand: no material " + std::to_string(index));
    old_ = materials[static_cast<std::size_t>(index)];
    setText(tr("Change material \"%1\"").arg(QString::fromStdString(old_.name)));
}

void SetMaterialCommand::redo() {
    model().materials[static_cast<std::size_t>(index_)] = new_;
    notify();
}

void SetMaterialCommand::undo() {
    model().materials[static_cast<std::size_t>(index_)] = old_;
    notify();
}

SetAnalysisSettingsCommand::SetAnalysisSettingsCommand(ModelDocument* document, const AnalysisSettings& settings,
                                                       QUndoCommand* parent)
    : DocumentCommand(document, parent), new_(settings), old_(document->model().analysis) {
    setText(tr("Change analysis settings"));
}

void SetAnalysisSettingsCommand::redo() {
    model().analysis = new_;
    notify();
}

void SetAnalysisSettingsCommand::undo() {
    model().analysis = old_;
    notify();
}

namespace {
std::size_t checked_index(std::size_t size, int index, const char* what) {
    if (index < 0 || static_cast<std::size_t>(index) >= size)
        throw std::out_of_range(std::string(what) + ": no item " + std::to_string(index));
    return static_cast<std::size_t>(index);
}
}  // namespace

AddHoleCommand::AddHoleCommand(ModelDocument* document, int region, Ring hole, QUndoCommand* parent)
    : DocumentCommand(document, parent),
      region_(checked_index(document->model().regions.size(), region, "AddHoleCommand")),
      hole_(std::move(hole)) {
    setText(tr("Add hole to region \"%1\"").arg(QString::fromStdString(document->model().regions[region_].name)));
}

void AddHoleCommand::redo() {
    model().regions[region_].holes.push_back(hole_);
    notify();
}

void AddHoleCommand::undo() {
    model().regions[region_].holes.pop_back();
    notify();
}

SetJointMaterialCommand::SetJointMaterialCommand(ModelDocument* document, int index, JointMaterial material,
                                                 QUndoCommand* parent)
    : SetValueCommand<JointMaterial>(
          document,
          [i = checked_index(document->model().joint_materials.size(), index, "SetJointMaterialCommand")](
              Model& m) -> JointMaterial& { return m.joint_materials[i]; },
          std::move(material), QString(), parent) {
    setText(tr("Change joint material \"%1\"")
                .arg(QString::fromStdString(document->model().joint_materials[static_cast<std::size_t>(index)].name)));
}

SetInitialStressCommand::SetInitialStressCommand(ModelDocument* document, const InitialStress& stress,
                                                 QUndoCommand* parent)
    : SetValueCommand<InitialStress>(
          document, [](Model& m) -> InitialStress& { return m.initial_stress; }, stress, QString(), parent) {
    setText(tr("Change in-situ stress"));
}

}  // namespace mcdda::gui
