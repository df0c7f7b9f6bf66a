#pragma once
/// \file ResultToolBar.hpp
/// The Results toolbar: which field colours the picture and how the displacements are drawn.
/// Its choices make the view::ResultOptions of the picture shown while and after a run.

#include "view/ResultScene.hpp"

#include <QToolBar>

class QComboBox;
class QDoubleSpinBox;

namespace mcdda::gui {

class ResultToolBar : public QToolBar {
    Q_OBJECT

public:
    explicit ResultToolBar(QWidget* parent = nullptr);

    /// The field shown: one of view::result_field_names().
    QString field() const;
    void setField(const QString& field);
    /// Scale factor of the drawn displacements (0 = undeformed).
    double deformFactor() const;
    void setDeformFactor(double factor);
    /// Whether saved steps are drawn with their contacts file (contact forces, joint slip and
    /// opening, bolts); the live picture of a run has none.
    bool showContacts() const;
    void setShowContacts(bool show);
    /// The options of the picture the toolbar describes.
    view::ResultOptions options() const;

signals:
    /// A choice changed: the picture is to be drawn again.
    void optionsChanged();

private:
    QComboBox* field_box_ = nullptr;
    QDoubleSpinBox* deform_box_ = nullptr;
    QAction* contacts_ = nullptr;
};

}  // namespace mcdda::gui
