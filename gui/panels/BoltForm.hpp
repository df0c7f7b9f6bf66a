#pragma once
/// \file BoltForm.hpp
/// The Bolts tab of the Properties dock: the rock bolts of the model (drawn with Edit ▸ Bolt),
/// one at a time, with its name and the fields declared for bolts (axial stiffness EA, strength,
/// pretension; model/ModelFields.hpp). Apply checks the changed model like the other forms and
/// makes the change one undoable edit.

#include "panels/DeclaredFields.hpp"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace mcdda::gui {

class ModelDocument;

class BoltForm : public QWidget {
    Q_OBJECT

public:
    explicit BoltForm(ModelDocument* document, QWidget* parent = nullptr);
    ~BoltForm() override;

    int boltIndex() const;
    void setBoltIndex(int index);
    QString status() const;

public slots:
    /// True when the change was applied (or there was nothing to change).
    bool apply();
    void refresh();

private:
    void loadBolt();

    ModelDocument* document_ = nullptr;
    bool loading_ = false;
    QComboBox* bolt_box_ = nullptr;
    QLineEdit* name_ = nullptr;
    std::unique_ptr<form::DeclaredFields<Bolt>> fields_;
    QPushButton* apply_ = nullptr;
    QLabel* status_ = nullptr;
};

}  // namespace mcdda::gui
