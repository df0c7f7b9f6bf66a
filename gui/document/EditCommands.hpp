#pragma once
/// \file EditCommands.hpp
/// Undoable edits of a ModelDocument. Each command stores what it needs to restore the model
/// exactly; redo() and undo() emit the document's changed().

#include "model/Model.hpp"

#include <QCoreApplication>
#include <QUndoCommand>

#include <QString>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

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

/// Adds a hole (opening) to one region (by index); undo removes it again.
class AddHoleCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::AddHoleCommand)
public:
    AddHoleCommand(ModelDocument* document, int region, Ring hole, QUndoCommand* parent = nullptr);
    void redo() override;
    void undo() override;

private:
    std::size_t region_;
    Ring hole_;
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

/// Appends one item to a list of the model (fixed points, loads, measurement points, ...) and
/// removes it again on undo: one template instead of a near-copy per list.
template <typename T>
class AddItemCommand : public DocumentCommand {
public:
    AddItemCommand(ModelDocument* document, std::vector<T> Model::*list, T item, const QString& text,
                   QUndoCommand* parent = nullptr)
        : DocumentCommand(document, parent), list_(list), item_(std::move(item)) {
        setText(text);
    }
    void redo() override {
        (model().*list_).push_back(item_);
        notify();
    }
    void undo() override {
        (model().*list_).pop_back();
        notify();
    }
    const T& item() const { return item_; }

private:
    std::vector<T> Model::*list_;
    T item_;
};

/// Replaces one value of the model (found by `access`), restoring the old one on undo.
template <typename T>
class SetValueCommand : public DocumentCommand {
public:
    using Access = std::function<T&(Model&)>;
    SetValueCommand(ModelDocument* document, Access access, T value, const QString& text,
                    QUndoCommand* parent = nullptr)
        : DocumentCommand(document, parent), access_(std::move(access)), new_(std::move(value)) {
        setText(text);
    }
    void redo() override {
        if (!saved_) {
            old_ = access_(model());
            saved_ = true;
        }
        access_(model()) = new_;
        notify();
    }
    void undo() override {
        access_(model()) = old_;
        notify();
    }

private:
    Access access_;
    T new_;
    T old_{};
    bool saved_ = false;
};

/// Replaces one joint material (by index).
class SetJointMaterialCommand : public SetValueCommand<JointMaterial> {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::SetJointMaterialCommand)
public:
    SetJointMaterialCommand(ModelDocument* document, int index, JointMaterial material,
                            QUndoCommand* parent = nullptr);
};

/// Replaces the initial (in-situ) stress.
class SetInitialStressCommand : public SetValueCommand<InitialStress> {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::SetInitialStressCommand)
public:
    SetInitialStressCommand(ModelDocument* document, const InitialStress& stress, QUndoCommand* parent = nullptr);
};

}  // namespace mcdda::gui
