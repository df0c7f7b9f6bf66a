#pragma once
/// \file StagesPanel.hpp
/// The Stages dock: the model's construction stages in order, the picture showing the model as it
/// stands in the stage chosen (regions excavated by then, or built only later, left out), and
/// editing: add, remove, rename and reorder stages, choose the regions each excavates or builds,
/// the supports, loads and bolts it installs or removes, its number of steps, how fast it
/// releases the out-of-balance forces and its other number settings (time step, tolerances …),
/// and its ground water: as the stage before, a water table of its own (drawn with the Water
/// Table tool) or dry; and its pseudo-static seismic coefficient kh, kv (or the stage before's). Every change is one undoable edit of the document; the model checker reports stages
/// that do not make sense (excavating what is already gone) in the Messages dock.

#include "panels/DeclaredFields.hpp"

#include <QWidget>

#include <memory>
#include <optional>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QComboBox;
class QSpinBox;
class QPushButton;

namespace mcdda::gui {

class ModelDocument;
class ModelView;

class StagesPanel : public QWidget {
    Q_OBJECT

public:
    StagesPanel(ModelDocument* document, ModelView* view, QWidget* parent = nullptr);
    ~StagesPanel() override;

    /// The stage shown: -1 = the model as drawn (every region).
    int currentStage() const;
    void setCurrentStage(int stage);
    /// The water of the stage shown, in words: "as the stage before (...)", "line with N
    /// points", "dry".
    QString waterText() const;

signals:
    /// Draw Water Table was pressed: the window activates the tool, which draws the water of
    /// the stage shown.
    void drawWaterRequested();

private:
    void setStageWater(const std::optional<Water>& water);
    /// The seismic coefficient fields applied: the model's, or the stage's own (or none).
    void applySeismicCoefficient();
    void refresh();
    void showStage();
    void applyStage();
    void addStage();
    void removeStage();
    void moveStage(int by);

    ModelDocument* document_ = nullptr;
    ModelView* view_ = nullptr;
    QListWidget* list_ = nullptr;
    QLineEdit* name_ = nullptr;
    QListWidget* excavate_ = nullptr;
    QListWidget* activate_ = nullptr;
    QListWidget* install_ = nullptr;
    QListWidget* remove_items_ = nullptr;
    QSpinBox* steps_ = nullptr;
    QSpinBox* release_ = nullptr;
    QComboBox* type_ = nullptr;  ///< static, dynamic, strength reduction (a safety stage)
    std::unique_ptr<form::DeclaredFields<AnalysisSettings>> analysis_;  ///< the stage's everyday number settings
    std::unique_ptr<form::DeclaredFields<AnalysisSettings>> advanced_;  ///< its numerical ones (Advanced)
    QCheckBox* reset_ = nullptr;  ///< displacements reported from the stage's start
    QPushButton* apply_ = nullptr;
    QPushButton* remove_ = nullptr;
    QPushButton* up_ = nullptr;
    QPushButton* down_ = nullptr;
    QLabel* note_ = nullptr;
    QLabel* water_ = nullptr;               ///< the stage's water in words
    QPushButton* water_draw_ = nullptr;     ///< activates the Water Table tool
    QPushButton* water_dry_ = nullptr;      ///< no water from this stage on
    QPushButton* water_inherit_ = nullptr;  ///< the water of the stage before
    QCheckBox* seismic_own_ = nullptr;      ///< the stage sets kh, kv (else as the stage before)
    QDoubleSpinBox* seismic_kh_ = nullptr;
    QDoubleSpinBox* seismic_kv_ = nullptr;
};

}  // namespace mcdda::gui
