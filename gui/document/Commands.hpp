#pragma once
/// \file Commands.hpp
/// Undoable edits of a ModelDocument. Each command stores what it needs to restore the model
/// exactly; redo() and undo() emit the document's changed().

#include "model/Model.hpp"

#include <QCoreApplication>
#include <QUndoCommand>

#include <cstddef>

namespace mcdda::gui {

class ModelDocument;

/// Base of the document's commands: access to the model being edited.
class DocumentCommand : public QUndoCommand {
public:
    explicit DocumentCommand(ModelDocument* document, QUndoCommand* parent = nullptr)
        : QUndoCommand(parent), document_(document) {}

protected:
    Model& model();
    /// Emits the document's changed().
    void notify();

private:
    ModelDocument* document_;
};

/// Appends a region.
class AddRegionCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::AddRegionCommand)
public:
    AddRegionCommand(ModelDocument* document, Region region, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Region region_;
};

/// Appends an explicit joint (before any joints generated from joint sets, so those stay last).
class AddJointCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::AddJointCommand)
public:
    AddJointCommand(ModelDocument* document, Joint joint, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Joint joint_;
    std::size_t index_ = 0;  ///< where redo() inserted it
};

/// Appends a roller support.
class AddRollerCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::AddRollerCommand)
public:
    AddRollerCommand(ModelDocument* document, Roller roller, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Roller roller_;
};

/// Replaces one material (by index); regions keep referring to it by index.
class SetMaterialCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::SetMaterialCommand)
public:
    SetMaterialCommand(ModelDocument* document, int index, Material material, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    int index_;
    Material new_;
    Material old_;
};

/// Replaces the analysis settings.
class SetAnalysisSettingsCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::SetAnalysisSettingsCommand)
public:
    SetAnalysisSettingsCommand(ModelDocument* document, const AnalysisSettings& settings,
                               QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    AnalysisSettings new_;
    AnalysisSettings old_;
};

}  // namespace mcdda::gui
