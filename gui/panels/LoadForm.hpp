#pragma once
/// \file LoadForm.hpp
/// The Loads tab of the Properties dock: the load tables (name, variable, hold or extrapolate,
/// the (abscissa, factor) rows), the reference magnitude and table of each point load and edge
/// pressure, and gravity. Forces in kN/m, pressures in kPa (positive pushing into the material),
/// gravity in m/s². Like the other forms, Apply checks the changed model with validate_model()
/// and either refuses with the validator's reason (the model unchanged) or applies the change as
/// one undoable command. A table that a load refers to cannot be deleted.

#include <QString>
#include <QWidget>

#include <array>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace mcdda::gui {

class ModelDocument;

class LoadForm : public QWidget {
    Q_OBJECT

public:
    explicit LoadForm(ModelDocument* document, QWidget* parent = nullptr);

    /// The load table the form shows (an index into Model::load_tables; −1 when there is none).
    int tableIndex() const;
    void setTableIndex(int index);
    /// The load the form shows: an entry of the loads list, point loads first, then edge
    /// pressures (entry point_loads.size() + k is edge pressure k).
    int loadIndex() const;
    void setLoadIndex(int index);
    /// The (abscissa, factor) rows of the shown table, as edited.
    QTableWidget* tablePoints() const { return tbl_points_; }

    /// The status lines: the reason of a refusal, or what was applied.
    QString tableStatus() const;
    QString loadStatus() const;
    QString gravityStatus() const;

public slots:
    /// Apply the load table form: true when applied (or nothing changed).
    bool applyTable();
    /// Adds a table ("table N", a ramp from 0 to 1 over the first step) and shows it.
    bool newTable();
    /// Deletes the shown table; refused while a point load or edge pressure refers to it.
    bool deleteTable();
    /// Appends a row one abscissa unit after the last one, with the last factor.
    void addTableRow();
    /// Removes the selected row (the last one when none is selected).
    void removeTableRow();
    /// Apply the shown load's magnitude and table.
    bool applyLoad();
    bool applyGravity();
    /// Sets gravity to (0, −9.81) m/s² and applies it.
    bool setStandardGravity();
    /// Shows the document's model in the form again (after an edit, undo, open).
    void refresh();

private:
    QWidget* createTableGroup();
    QWidget* createLoadGroup();
    QWidget* createGravityGroup();
    void loadTable();
    void loadLoad();
    void loadGravity();
    void updateTableHeaders();
    void showRows(const std::vector<std::array<double, 2>>& points);

    ModelDocument* document_;
    bool loading_ = false;

    QComboBox* table_box_ = nullptr;
    QPushButton* table_delete_ = nullptr;
    QLineEdit* tbl_name_ = nullptr;
    QComboBox* tbl_variable_ = nullptr;
    QCheckBox* tbl_extrapolate_ = nullptr;
    QTableWidget* tbl_points_ = nullptr;
    QLabel* tbl_status_ = nullptr;
    std::vector<QWidget*> table_fields_;  ///< disabled while there is no table

    QComboBox* load_box_ = nullptr;
    QDoubleSpinBox* ld_fx_ = nullptr;
    QDoubleSpinBox* ld_fy_ = nullptr;
    QDoubleSpinBox* ld_pressure_ = nullptr;
    QComboBox* ld_table_ = nullptr;
    QPushButton* ld_apply_ = nullptr;
    QLabel* ld_status_ = nullptr;

    QDoubleSpinBox* grav_x_ = nullptr;
    QDoubleSpinBox* grav_y_ = nullptr;
    QLabel* grav_status_ = nullptr;
};

}  // namespace mcdda::gui
