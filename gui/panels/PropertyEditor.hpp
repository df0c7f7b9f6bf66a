#pragma once
/// \file PropertyEditor.hpp
/// The Properties dock: forms for the materials, the joint materials, the analysis settings
/// and the in-situ stress of the document's model, plus the Loads (LoadForm.hpp), Bolts
/// (BoltForm.hpp) and Mesh (MeshForm.hpp) tabs, which follow the same rules. The material, joint
/// material and bolt fields are built from their declarations (model/ModelFields.hpp). Values are
/// shown in engineering units (MPa, kPa, kN/m³, MN/m, kN/m, degrees; in-situ stress compression
/// positive) with the unit next to every field. Apply (or Enter in a field) converts them to SI, checks the changed model with
/// validate_model() and either refuses — the first error about the edited item is shown in the
/// form's status line and the model stays as it was — or applies the change as one undoable
/// command.

#include "document/ModelItems.hpp"
#include "model/Model.hpp"
#include "panels/DeclaredFields.hpp"
#include "panels/LawFields.hpp"

#include <QString>
#include <QWidget>

#include <memory>
#include <string>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace mcdda::gui {

class BoltForm;
class LoadForm;
class MeshForm;
class ModelDocument;

class PropertyEditor : public QWidget {
    Q_OBJECT

public:
    explicit PropertyEditor(ModelDocument* document, QWidget* parent = nullptr);

    /// The first error that validate_model() reports for `candidate` at `prefix` (a JSON
    /// pointer such as "/materials/0") or below it, in words and display units
    /// (session/DiagnosticText.hpp); empty when there is none.
    static QString refusal(const Model& candidate, const std::string& prefix);

    /// The material / joint material the forms show (an index into the model's lists).
    int materialIndex() const;
    void setMaterialIndex(int index);
    int jointMaterialIndex() const;
    void setJointMaterialIndex(int index);

    /// The status lines under the forms: the reason of a refusal, or what was applied.
    QString materialStatus() const;
    QString jointMaterialStatus() const;
    QString analysisStatus() const;
    QString initialStressStatus() const;

    /// The item selected in the view or the tree: the forms turn to what it uses (a region's
    /// material, a joint's joint material, a load), and Assign gives it the material shown.
    void setSelection(const ItemRef& ref);

    /// The Loads, Bolts and Mesh tabs.
    LoadForm* loadForm() const { return load_form_; }
    BoltForm* boltForm() const { return bolt_form_; }
    MeshForm* meshForm() const { return mesh_form_; }

public slots:
    /// Apply the form: true when the change was applied (or there was nothing to change).
    bool applyMaterial();
    bool applyJointMaterial();
    bool applyAnalysis();
    bool applyInitialStress();
    /// New: adds a material (a copy of the one shown, or defaults) and shows it.
    bool newMaterial();
    bool newJointMaterial();
    /// Assign: the selected region gets the material shown / the selected explicit joint the
    /// joint material shown. False without such a selection.
    bool assignMaterial();
    bool assignJointMaterial();
    /// Shows the document's model in the forms again (after an edit, undo, open).
    void refresh();

private:
    QWidget* createMaterialForm();
    QWidget* createJointMaterialForm();
    QWidget* createAnalysisForm();
    QWidget* createInitialStressForm();
    void loadMaterial();
    void loadJointMaterial();
    void loadAnalysis();
    void loadInitialStress();
    void updateStressFields();
    /// Enables and labels the Assign buttons after the selection.
    void updateAssignButtons();

    ModelDocument* document_;
    bool loading_ = false;
    QTabWidget* tabs_ = nullptr;
    LoadForm* load_form_ = nullptr;
    BoltForm* bolt_form_ = nullptr;
    MeshForm* mesh_form_ = nullptr;

    QComboBox* material_box_ = nullptr;
    QLineEdit* mat_name_ = nullptr;
    std::unique_ptr<form::DeclaredFields<Material>> mat_fields_;
    std::unique_ptr<form::LawFields> mat_law_;  ///< the law and its own fields
    QCheckBox* mat_reduce_ = nullptr;  ///< divided by a strength reduction
    QCheckBox* jm_reduce_ = nullptr;
    QPushButton* mat_new_ = nullptr;
    QPushButton* mat_assign_ = nullptr;
    QPushButton* jm_new_ = nullptr;
    QPushButton* jm_assign_ = nullptr;
    ItemRef selection_;
    QLabel* mat_status_ = nullptr;

    QComboBox* joint_box_ = nullptr;
    QLineEdit* jm_name_ = nullptr;
    std::unique_ptr<form::DeclaredFields<JointMaterial>> jm_fields_;
    QLabel* jm_status_ = nullptr;

    QComboBox* an_kind_ = nullptr;
    QSpinBox* an_steps_ = nullptr;
    std::unique_ptr<form::DeclaredFields<AnalysisSettings>> an_fields_;    ///< the everyday ones
    std::unique_ptr<form::DeclaredFields<AnalysisSettings>> an_advanced_;  ///< DDA's numerical ones, collapsed
    QSpinBox* an_output_ = nullptr;
    QCheckBox* an_plasticity_ = nullptr;
    QComboBox* an_flow_ = nullptr;  ///< strength reduction of non-associated materials: Davis or direct
    QLabel* an_status_ = nullptr;

    QComboBox* is_kind_ = nullptr;
    QDoubleSpinBox* is_sxx_ = nullptr;
    QDoubleSpinBox* is_syy_ = nullptr;
    QDoubleSpinBox* is_sxy_ = nullptr;
    QCheckBox* is_szz_given_ = nullptr;
    QDoubleSpinBox* is_szz_ = nullptr;
    QDoubleSpinBox* is_surface_ = nullptr;
    QDoubleSpinBox* is_k0_ = nullptr;
    QLabel* is_status_ = nullptr;
};

}  // namespace mcdda::gui
