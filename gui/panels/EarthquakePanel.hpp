#pragma once
/// \file EarthquakePanel.hpp
/// The Earthquake dock (docs/model-format.md, "Earthquakes"): the model's ground motions —
/// imported from a two-column CSV or a PEER .AT2 file, named, read in g or m/s², scaled,
/// baseline-corrected — with the one chosen plotted against time (its peak and duration) before
/// any run; the base it shakes (none, a rigid base moving every support, or a compliant base
/// along a segment, typed here or drawn in the picture) with its horizontal and vertical
/// record; and the pseudo-static seismic coefficient kh, kv. Every change is one undoable edit
/// of the document; a file that cannot be read is refused with the reader's words.

#include <QString>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace mcdda::gui {

class ModelDocument;
class RecordPlot;

class EarthquakePanel : public QWidget {
    Q_OBJECT

public:
    explicit EarthquakePanel(ModelDocument* document, QWidget* parent = nullptr);

    /// Reads the record at `path` (CSV or .AT2) and adds it to the model as a new ground motion
    /// (undoable), chosen and plotted. Its file is kept relative to the model file's folder once
    /// the model has one. False, with the reader's message in the status line and the log, when
    /// the file cannot be read.
    bool importRecord(const QString& path);
    /// Asks for a file and imports it.
    void importDialog();
    /// The ground motion chosen in the list (-1: none).
    int currentRecord() const;
    void setCurrentRecord(int index);
    RecordPlot* recordPlot() const { return plot_; }
    /// The status lines: of the records (an import refused, an edit applied) and of the base.
    QString recordStatus() const;
    QString baseStatus() const;

signals:
    /// A line for the window's log.
    void message(const QString& text);
    /// Draw was pressed: the window's compliant-base tool takes two clicks in the picture.
    void drawBaseRequested();

private:
    void refresh();
    void showRecord();
    void applyRecord();
    void removeRecord();
    void applyBase();
    void applySeismic();

    ModelDocument* document_;
    bool loading_ = false;
    QListWidget* list_ = nullptr;
    QPushButton* remove_ = nullptr;
    QLineEdit* name_ = nullptr;
    QComboBox* units_ = nullptr;
    QDoubleSpinBox* scale_ = nullptr;
    QCheckBox* baseline_ = nullptr;
    QLabel* file_ = nullptr;
    QLabel* record_status_ = nullptr;
    RecordPlot* plot_ = nullptr;
    QComboBox* base_kind_ = nullptr;
    QComboBox* base_x_ = nullptr;
    QComboBox* base_y_ = nullptr;
    QDoubleSpinBox* base_from_[2] = {nullptr, nullptr};
    QDoubleSpinBox* base_to_[2] = {nullptr, nullptr};
    QPushButton* base_draw_ = nullptr;
    QLabel* base_status_ = nullptr;
    QDoubleSpinBox* kh_ = nullptr;
    QDoubleSpinBox* kv_ = nullptr;
};

}  // namespace mcdda::gui
