#include "panels/MeshForm.hpp"

#include "document/EditCommands.hpp"
#include "document/ModelDocument.hpp"
#include "panels/FormFields.hpp"
#include "panels/PropertyEditor.hpp"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>
#include <string>

namespace mcdda::gui {

namespace {

using form::cell_text;
using form::deg;
using form::display;
using form::explain;
using form::zero_is_automatic;
using form::number;
using form::set_status;
using form::si;

bool same(const MeshControls& a, const MeshControls& b)
{
    if (a.size != b.size || a.min_angle != b.min_angle || a.grading != b.grading ||
        a.max_elements != b.max_elements || a.local.size() != b.local.size())
        return false;
    for (std::size_t i = 0; i < a.local.size(); ++i) {
        const LocalSize& x = a.local[i];
        const LocalSize& y = b.local[i];
        if (x.from.x != y.from.x || x.from.y != y.from.y || x.to.x != y.to.x || x.to.y != y.to.y ||
            x.size != y.size || x.radius != y.radius)
            return false;
    }
    return true;
}

}  // namespace

MeshForm::MeshForm(ModelDocument* document, QWidget* parent) : QWidget(parent), document_(document)
{
    auto* column = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    column->addLayout(form);
    size_ = number(QStringLiteral("meshSize"), tr("m"), 0.0, 1e6, 4, this);
    zero_is_automatic(size_);
    size_->setSpecialValueText(tr("automatic"));  // shown for 0
    explain(size_, tr("Target longest edge of a triangle; 0 = automatic (1/20 of the model's diagonal)"));
    form->addRow(tr("Element size"), size_);
    min_angle_ = number(QStringLiteral("meshMinAngle"), tr("°"), -360.0, 360.0, 2, this);
    explain(min_angle_, tr("Smallest angle a triangle may have, (0°, 34°]"));
    form->addRow(tr("Minimum angle"), min_angle_);
    grading_ = number(QStringLiteral("meshGrading"), QString(), -100.0, 100.0, 3, this);
    grading_->setSingleStep(0.05);
    explain(grading_, tr("Growth of the size away from a local refinement: size = local size + grading × "
                            "(distance − radius)"));
    form->addRow(tr("Grading [–]"), grading_);
    max_elements_ = number(QStringLiteral("meshMaxElements"), tr("elements"), -1.0, 1e12, 0, this);
    max_elements_->setGroupSeparatorShown(true);
    max_elements_->setSingleStep(100000.0);
    explain(max_elements_, tr("The mesher refuses a model whose size field asks for more triangles"));
    form->addRow(tr("Element limit"), max_elements_);

    local_ = new QTableWidget(0, 3, this);
    local_->setObjectName(QStringLiteral("meshLocal"));
    local_->setHorizontalHeaderLabels({tr("At [m]"), tr("Size [m]"), tr("Radius [m]")});
    local_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    local_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    local_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    local_->setMinimumHeight(100);
    local_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);  // the rest goes below
    column->addWidget(new QLabel(tr("Local refinements"), this));
    column->addWidget(local_);

    regions_ = new QTableWidget(0, 2, this);
    regions_->setObjectName(QStringLiteral("meshRegions"));
    regions_->setHorizontalHeaderLabels({tr("Region"), tr("Size [m]")});
    regions_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    regions_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    regions_->setMinimumHeight(80);
    regions_->setToolTip(tr("A region's own element size, uniform inside it: the element size and the local "
                            "refinements above do not reach into it (a stiff footing or lining need not follow "
                            "the refinement of the ground it stands on). Blank: the model's sizes."));
    column->addWidget(new QLabel(tr("Element size per region"), this));
    column->addWidget(regions_);

    auto* apply = new QPushButton(tr("Apply"), this);
    apply->setObjectName(QStringLiteral("meshApply"));
    connect(apply, &QPushButton::clicked, this, &MeshForm::applyMesh);
    column->addWidget(apply, 0, Qt::AlignRight);
    status_ = form::status_label(QStringLiteral("meshStatus"), this);
    column->addWidget(status_);
    column->addStretch(1);
    for (QDoubleSpinBox* box : {size_, min_angle_, grading_, max_elements_})
        form::apply_on_enter(box, [this] { if (!loading_) applyMesh(); });
    connect(document_, &ModelDocument::changed, this, &MeshForm::refresh);
    refresh();
}

QString MeshForm::meshStatus() const { return status_->text(); }

void MeshForm::refresh()
{
    const MeshControls& c = document_->model().mesh;
    loading_ = true;
    display(size_, c.size);
    display(min_angle_, c.min_angle / deg);
    display(grading_, c.grading);
    display(max_elements_, static_cast<double>(c.max_elements));
    local_->setRowCount(static_cast<int>(c.local.size()));
    for (std::size_t i = 0; i < c.local.size(); ++i) {
        const LocalSize& l = c.local[i];
        const bool point = l.from.x == l.to.x && l.from.y == l.to.y;
        const QString at = point ? tr("(%1, %2)").arg(cell_text(l.from.x), cell_text(l.from.y))
                                 : tr("(%1, %2) – (%3, %4)")
                                       .arg(cell_text(l.from.x), cell_text(l.from.y), cell_text(l.to.x),
                                            cell_text(l.to.y));
        auto* where = new QTableWidgetItem(at);
        where->setFlags(where->flags() & ~Qt::ItemIsEditable);  // placed in the model file, not here
        const int row = static_cast<int>(i);
        local_->setItem(row, 0, where);
        local_->setItem(row, 1, new QTableWidgetItem(cell_text(l.size)));
        local_->setItem(row, 2, new QTableWidgetItem(cell_text(l.radius)));
    }
    const std::vector<Region>& regions = document_->model().regions;
    regions_->setRowCount(static_cast<int>(regions.size()));
    for (std::size_t i = 0; i < regions.size(); ++i) {
        auto* name = new QTableWidgetItem(QString::fromStdString(regions[i].name));
        name->setFlags(name->flags() & ~Qt::ItemIsEditable);  // named in the Model tree
        regions_->setItem(static_cast<int>(i), 0, name);
        regions_->setItem(static_cast<int>(i), 1,
                          new QTableWidgetItem(regions[i].mesh_size > 0.0 ? cell_text(regions[i].mesh_size) : QString()));
    }
    loading_ = false;
}

bool MeshForm::applyMesh()
{
    const Model& m = document_->model();
    const MeshControls& old = m.mesh;
    MeshControls c = old;
    c.size = si(size_, old.size, 1.0);
    c.min_angle = si(min_angle_, old.min_angle, deg);
    c.grading = si(grading_, old.grading, 1.0);
    c.max_elements = static_cast<long>(std::llround(si(max_elements_, static_cast<double>(old.max_elements), 1.0)));
    for (int r = 0; r < local_->rowCount() && static_cast<std::size_t>(r) < c.local.size(); ++r) {
        LocalSize& l = c.local[static_cast<std::size_t>(r)];
        for (int col : {1, 2}) {
            const QTableWidgetItem* item = local_->item(r, col);
            const QString text = item ? item->text() : QString();
            if (!form::cell_value(text, col == 1 ? &l.size : &l.radius)) {
                set_status(status_,
                           tr("Not applied: local refinement %1: %2 \"%3\" is not a number")
                               .arg(r + 1)
                               .arg(col == 1 ? tr("size") : tr("radius"), text),
                           true);
                return false;
            }
        }
    }
    std::vector<double> region_sizes;
    for (int r = 0; r < regions_->rowCount() && static_cast<std::size_t>(r) < m.regions.size(); ++r) {
        const QTableWidgetItem* item = regions_->item(r, 1);
        const QString text = item ? item->text().trimmed() : QString();
        double size = 0.0;  // blank: the model's size field
        if (!text.isEmpty() && !form::cell_value(text, &size)) {
            set_status(status_,
                       tr("Not applied: the element size of %1: \"%2\" is not a number")
                           .arg(QString::fromStdString(m.regions[static_cast<std::size_t>(r)].name), text),
                       true);
            return false;
        }
        region_sizes.push_back(size);
    }
    std::vector<std::size_t> changed_regions;
    for (std::size_t r = 0; r < region_sizes.size(); ++r)
        if (region_sizes[r] != m.regions[r].mesh_size) changed_regions.push_back(r);
    if (same(c, old) && changed_regions.empty()) return true;
    Model candidate = m;
    candidate.mesh = c;
    for (std::size_t r : changed_regions) candidate.regions[r].mesh_size = region_sizes[r];
    QString reason = PropertyEditor::refusal(candidate, "/mesh");
    for (std::size_t r = 0; reason.isEmpty() && r < changed_regions.size(); ++r)
        reason = PropertyEditor::refusal(candidate, "/regions/" + std::to_string(changed_regions[r]) + "/mesh_size");
    if (!reason.isEmpty()) {
        set_status(status_, tr("Not applied: %1").arg(reason), true);
        return false;
    }
    // One undoable change, however many of the controls it touches.
    auto* change = new QUndoCommand(tr("Change mesh controls"));
    if (!same(c, old))
        new SetValueCommand<MeshControls>(document_, [](Model& model) -> MeshControls& { return model.mesh; }, c,
                                          tr("Change mesh controls"), change);
    for (std::size_t r : changed_regions)
        new SetValueCommand<double>(document_, [r](Model& model) -> double& { return model.regions[r].mesh_size; },
                                    region_sizes[r], tr("Change the element size of a region"), change);
    document_->undoStack()->push(change);
    set_status(status_, tr("Applied."), false);
    return true;
}

}  // namespace mcdda::gui
