#pragma once
/// \file JointSetDialog.hpp
/// Edit ▸ Add Joint Set: a named family of parallel joints given by its trace angle (apparent
/// dip: ° from the horizontal, counter-clockwise, as the dialog says), spacing (m), a point one
/// trace passes through (default: the middle of the model), an optional extent (default: the
/// model's box), its joint material and its persistence (%): below 100 % each trace is cut into
/// segments of the trace length (m), the pattern shifted from trace to trace by the stagger (% of
/// the period). A preview beside the fields shows the traces where they cut rock, and how many
/// there are. jointSet() gives the entered set.

#include "model/Model.hpp"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace mcdda::gui {

class JointSetPreview;

class JointSetDialog : public QDialog {
    Q_OBJECT

public:
    /// `model` supplies the joint materials to choose from.
    explicit JointSetDialog(const Model& model, QWidget* parent = nullptr);

    /// The set entered (angle in radians, fractions instead of %, as Model stores it). At 100 %
    /// persistence the disabled trace length and stagger are left at their defaults.
    JointSet jointSet() const;
    /// Fills the fields from `set`.
    void setJointSet(const JointSet& set);
    /// Why the entered values are unusable; empty when they are fine.
    QString validationError() const;

public slots:
    /// Closes the dialog with Accepted when the values are usable, else shows why.
    void accept() override;

    /// The picture of the set (traces where they cut rock).
    JointSetPreview* preview() const { return preview_; }

private:
    void updatePreview();

    QLineEdit* name_ = nullptr;
    JointSetPreview* preview_ = nullptr;
    QLabel* count_ = nullptr;
    QDoubleSpinBox* angle_ = nullptr;
    QDoubleSpinBox* spacing_ = nullptr;
    QDoubleSpinBox* origin_x_ = nullptr;
    QDoubleSpinBox* origin_y_ = nullptr;
    QCheckBox* use_extent_ = nullptr;
    QDoubleSpinBox* extent_[4] = {};
    QComboBox* material_ = nullptr;
    QDoubleSpinBox* persistence_ = nullptr;
    QDoubleSpinBox* trace_length_ = nullptr;
    QDoubleSpinBox* stagger_ = nullptr;
    QLabel* error_ = nullptr;
};

}  // namespace mcdda::gui
