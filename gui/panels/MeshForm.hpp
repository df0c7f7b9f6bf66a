#pragma once
/// \file MeshForm.hpp
/// The Mesh tab of the Properties dock: the global element size (m; 0 = automatic, 1/20 of the
/// model's diagonal), the minimum angle (shown in degrees, stored in radians), the grading, the
/// element limit, the size and radius of each local refinement, and each region's own element
/// size (blank: the model's size field). Apply checks the changed
/// model with validate_model() and either refuses with the validator's reason or applies all
/// the mesh controls as one undoable command (the model is then meshed again).

#include <QString>
#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QTableWidget;

namespace mcdda::gui {

class ModelDocument;

class MeshForm : public QWidget {
    Q_OBJECT

public:
    explicit MeshForm(ModelDocument* document, QWidget* parent = nullptr);

    /// One row per local refinement: where (read-only), size (m), radius (m).
    QTableWidget* localRefinements() const { return local_; }
    /// One row per region: its name (read-only) and its own element size (m; blank = the model's
    /// size field, Region::mesh_size).
    QTableWidget* regionSizes() const { return regions_; }
    /// The status line: the reason of a refusal, or what was applied.
    QString meshStatus() const;

public slots:
    /// Apply the form: true when the change was applied (or there was nothing to change).
    bool applyMesh();
    /// Shows the document's model in the form again (after an edit, undo, open).
    void refresh();

private:
    ModelDocument* document_;
    bool loading_ = false;

    QDoubleSpinBox* size_ = nullptr;
    QDoubleSpinBox* min_angle_ = nullptr;
    QDoubleSpinBox* grading_ = nullptr;
    QDoubleSpinBox* max_elements_ = nullptr;
    QTableWidget* local_ = nullptr;
    QTableWidget* regions_ = nullptr;
    QLabel* status_ = nullptr;
};

}  // namespace mcdda::gui
