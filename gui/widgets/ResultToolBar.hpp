#pragma once
/// \file ResultToolBar.hpp
/// The Results toolbar: which field colours the picture, in which stress sign convention (the
/// geotechnical one, compression positive, unless chosen otherwise), total or effective stresses
/// (runs with ground water, which also offer the pore pressure), how the displacements are
/// drawn (off, an automatic scale or a factor), the colour scale (map, bands, range), and
/// whether saved steps show their contacts. Its choices make the view::ResultOptions of the
/// picture shown while and after a run; showInfo() reports what was drawn.

#include "view/ResultScene.hpp"

#include <QToolBar>

class QActionGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace mcdda::gui {

class ResultToolBar : public QToolBar {
    Q_OBJECT

public:
    explicit ResultToolBar(QWidget* parent = nullptr);

    /// The field chosen in the chooser: one of view::result_field_names() other than the
    /// effective stresses (the Total/Effective choice makes those of the stress fields).
    QString field() const;
    /// Chooses a field; an effective stress ("effective_stress_1") chooses its stress field and
    /// Effective (when the results have ground water).
    void setField(const QString& field);
    /// The field drawn: field() with the stress fields made effective when Effective is chosen
    /// (τxy is the same in both).
    QString shownField() const;
    /// Whether the results carry ground water (pore pressure and effective stress): the chooser
    /// then offers the pore pressure and the Total/Effective choice is enabled; otherwise the
    /// pore pressure is not offered (a choice of it falls back to the displacement) and the
    /// choice is Total, disabled. Emits nothing: the caller draws next.
    void setWaterResults(bool water);
    bool waterResults() const;
    /// Effective (true) or total (false) stresses for the stress fields.
    bool effectiveStress() const;
    void setEffectiveStress(bool effective);
    /// Scale factor of the drawn displacements (0 = undeformed; the automatic scale reads 0).
    double deformFactor() const;
    /// A factor > 0 draws deformed by it, 0 undeformed.
    void setDeformFactor(double factor);
    /// The automatic scale: the largest displacement drawn as 5 % of the model's size.
    bool deformAuto() const;
    void setDeformAuto(bool on);
    /// The units of stresses and displacements in legend, read-out and query lines, and of
    /// stresses in the forms and the tree: the program's one choice (DisplayUnits).
    void setUnits(view::StressUnit stress, view::LengthUnit length);
    view::StressUnit stressUnit() const;
    view::LengthUnit lengthUnit() const;
    view::StressSign stressSign() const;
    void setStressSign(view::StressSign sign);
    /// The colour scale: map, number of bands (0 = smooth) and ends (NaN = automatic).
    void setColourScale(view::ColourMap map, int bands, double min, double max);
    /// Whether saved steps are drawn with their contacts file (contact forces, joint slip and
    /// opening, bolts); the live picture of a run has none.
    bool showContacts() const;
    void setShowContacts(bool show);
    /// The options of the picture the toolbar describes.
    view::ResultOptions options() const;
    /// Says what the picture drew: the scale used, and a warning when elements are drawn inside
    /// out (the scale is too large to read the picture).
    void showInfo(const view::ResultInfo& info);
    /// The text beside the deformation scale (e.g. "×1.2e+03 (auto)").
    QString infoText() const;

signals:
    /// A choice changed: the picture is to be drawn again.
    void optionsChanged();

private:
    QComboBox* field_box_ = nullptr;
    QComboBox* sign_box_ = nullptr;
    QComboBox* basis_box_ = nullptr;  ///< total or effective stresses
    QDoubleSpinBox* deform_box_ = nullptr;
    QLabel* info_ = nullptr;
    QComboBox* map_box_ = nullptr;
    QSpinBox* bands_box_ = nullptr;
    QLineEdit* min_edit_ = nullptr;
    QLineEdit* max_edit_ = nullptr;
    QAction* contacts_ = nullptr;
    QActionGroup* stress_units_ = nullptr;
    QActionGroup* length_units_ = nullptr;
};

}  // namespace mcdda::gui
