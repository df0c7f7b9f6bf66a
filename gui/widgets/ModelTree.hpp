#pragma once
/// \file ModelTree.hpp
/// The Model dock's tree: regions, blocks (from the last pre-processing), joints by set,
/// materials, supports, loads and measurement points. Rows of drawn items carry an ItemRef, so
/// choosing a row selects the item in the view and the Select tool's choice selects the row.

#include "Preprocess.hpp"
#include "document/ModelItems.hpp"

#include <QTreeWidget>

namespace mcdda::gui {

class ModelTree : public QTreeWidget {
    Q_OBJECT

public:
    explicit ModelTree(QWidget* parent = nullptr);

    /// Lists `model`; `preprocessed` (may be null or of an older version of the model) gives the
    /// blocks and their meshes. The selected item stays selected when it still exists.
    void refresh(const Model& model, const Preprocessed* preprocessed);
    /// Selects the row of `ref` (the whole item for a vertex) without emitting itemChosen();
    /// an invalid reference clears the selection.
    void selectItem(const ItemRef& ref);
    /// The drawn item of the selected row (invalid when none, or a row of something else).
    ItemRef selectedItem() const;
    /// The number of rows under the Blocks group.
    int blockCount() const;

signals:
    /// The user chose a row of a drawn item (or a row of something else: an invalid ref).
    void itemChosen(const mcdda::gui::ItemRef& ref);

private:
    bool quiet_ = false;  ///< selection changes made by the program are not reported
    bool blocks_expanded_ = false;
    QTreeWidgetItem* blocks_ = nullptr;
};

}  // namespace mcdda::gui
