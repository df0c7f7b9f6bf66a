#include "dialogs/JointSetDialog.hpp"

#include "dialogs/JointSetPreview.hpp"
#include "model/Defaults.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>

namespace mcdda::gui {

namespace {

/// The regions' box (xmin, ymin, xmax, ymax); a 10 m square at the origin without regions.
std::array<double, 4> model_box(const Model& model)
{
    std::array<double, 4> box{1e300, 1e300, -1e300, -1e300};
    for (const Region& r : model.regions)
        for (const Point2& p : r.boundary)
            box = {std::min(box[0], p.x), std::min(box[1], p.y), std::max(box[2], p.x), std::max(box[3], p.y)};
    if (!(box[0] < box[2] && box[1] < box[3])) return {0.0, 0.0, 10.0, 10.0};
    return box;
}

/// `v` rounded to millimetres: defaults that read well.
double to_mm(double v) { return std::round(v * 1e3) / 1e3; }

}  // namespace

JointSetDialog::JointSetDialog(const Model& model, QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Add Joint Set"));
    const std::array<double, 4> box = model_box(model);
    auto spin = [this](const QString& name, double min, double max, double value, const QString& suffix) {
        auto* box = new QDoubleSpinBox(this);
        box->setObjectName(name);
        box->setRange(min, max);
        box->setDecimals(3);
        box->setValue(value);
        box->setSuffix(suffix);
        return box;
    };
    angle_ = spin(QStringLiteral("angleBox"), -180.0, 180.0, 45.0, QStringLiteral(" °"));
    angle_->setToolTip(tr("Direction of the traces, counter-clockwise from the x axis"));
    name_ = new QLineEdit(tr("set %1").arg(model.joint_sets.size() + 1), this);
    name_->setObjectName(QStringLiteral("nameEdit"));
    name_->setToolTip(tr("Name of the set (tree, messages, results)"));
    // The convention stated where it is typed: engineers think in apparent dip.
    auto* convention = new QLabel(tr("Apparent dip in the section: the angle of the traces from the horizontal, "
                                     "counter-clockwise. 0° is horizontal, 90° vertical, 30° rises to the "
                                     "right, 150° (or −30°) dips 30° to the right."),
                                  this);
    convention->setObjectName(QStringLiteral("angleConvention"));
    convention->setWordWrap(true);
    spacing_ = spin(QStringLiteral("spacingBox"), 0.0, 1e6, 1.0, QStringLiteral(" m"));
    spacing_->setToolTip(tr("Normal distance between neighbouring traces"));
    // The box's centre: through a model corner a trace would cut a sliver of a block (a sliver too thin to mesh).
    origin_x_ = spin(QStringLiteral("originXBox"), -1e9, 1e9, to_mm((box[0] + box[2]) / 2), QStringLiteral(" m"));
    origin_y_ = spin(QStringLiteral("originYBox"), -1e9, 1e9, to_mm((box[1] + box[3]) / 2), QStringLiteral(" m"));
    use_extent_ = new QCheckBox(tr("Limit to a box"), this);
    use_extent_->setObjectName(QStringLiteral("extentCheck"));
    use_extent_->setToolTip(tr("Without a box the traces cross the whole model"));
    const char* const names[4] = {"xminBox", "yminBox", "xmaxBox", "ymaxBox"};
    auto* extent_row = new QHBoxLayout;
    for (int i = 0; i < 4; ++i) {
        extent_[i] = spin(QString::fromLatin1(names[i]), -1e9, 1e9, to_mm(box[static_cast<std::size_t>(i)]),
                          QStringLiteral(" m"));
        extent_[i]->setEnabled(false);
        extent_row->addWidget(extent_[i]);
        connect(use_extent_, &QCheckBox::toggled, extent_[i], &QWidget::setEnabled);
    }
    extent_[0]->setToolTip(tr("Smallest x of the box"));
    extent_[1]->setToolTip(tr("Smallest y of the box"));
    extent_[2]->setToolTip(tr("Largest x of the box"));
    extent_[3]->setToolTip(tr("Largest y of the box"));
    material_ = new QComboBox(this);
    material_->setObjectName(QStringLiteral("jointMaterialBox"));
    material_->addItem(tr("(default)"), -1);
    for (std::size_t i = 0; i < model.joint_materials.size(); ++i) {
        const QString name = QString::fromStdString(model.joint_materials[i].name);
        material_->addItem(name.isEmpty() ? tr("Joint material %1").arg(i + 1) : name, static_cast<int>(i));
    }
    if (!model.joint_materials.empty()) material_->setCurrentIndex(1);
    persistence_ = spin(QStringLiteral("persistenceBox"), 0.0, 100.0, 100.0, QStringLiteral(" %"));
    persistence_->setToolTip(tr("Share of each trace that is joint; below 100 % the traces are cut "
                                "into segments separated by rock bridges"));
    trace_length_ = spin(QStringLiteral("traceLengthBox"), 0.0, 1e6, 1.0, QStringLiteral(" m"));
    trace_length_->setToolTip(tr("Length of each joint segment along a trace"));
    // Stagger 100 % would be the same pattern as 0 %, so the range stops short of it.
    stagger_ = spin(QStringLiteral("staggerBox"), 0.0, 99.999, 50.0, QStringLiteral(" %"));
    stagger_->setToolTip(tr("Shift of the segment pattern from one trace to the next, in % of the "
                            "period (segment plus bridge), so that the bridges do not line up"));
    // Fully persistent traces have no segments: trace length and stagger mean nothing then.
    auto enable_segment_fields = [this](double persistence) {
        trace_length_->setEnabled(persistence < 100.0);
        stagger_->setEnabled(persistence < 100.0);
    };
    connect(persistence_, &QDoubleSpinBox::valueChanged, this, enable_segment_fields);
    enable_segment_fields(persistence_->value());

    auto* form = new QFormLayout;
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Angle from horizontal"), angle_);
    form->addRow(convention);
    form->addRow(tr("Spacing"), spacing_);
    form->addRow(tr("Origin x"), origin_x_);
    form->addRow(tr("Origin y"), origin_y_);
    form->addRow(use_extent_);
    form->addRow(tr("x min, y min, x max, y max"), extent_row);
    form->addRow(tr("Joint material"), material_);
    form->addRow(tr("Persistence"), persistence_);
    form->addRow(tr("Trace length"), trace_length_);
    form->addRow(tr("Stagger"), stagger_);
    error_ = new QLabel(this);
    error_->setObjectName(QStringLiteral("errorLabel"));
    error_->setStyleSheet(QStringLiteral("color: #b00020"));
    error_->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &JointSetDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &JointSetDialog::reject);
    preview_ = new JointSetPreview(model, this);
    count_ = new QLabel(this);
    count_->setObjectName(QStringLiteral("traceCount"));
    auto* columns = new QHBoxLayout;
    columns->addLayout(form);
    auto* picture = new QVBoxLayout;
    picture->addWidget(preview_, 1);
    picture->addWidget(count_);
    columns->addLayout(picture, 1);
    // The preview follows every field.
    for (QDoubleSpinBox* field : findChildren<QDoubleSpinBox*>())
        connect(field, &QDoubleSpinBox::valueChanged, this, &JointSetDialog::updatePreview);
    connect(use_extent_, &QCheckBox::toggled, this, &JointSetDialog::updatePreview);
    updatePreview();
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns);
    layout->addWidget(error_);
    layout->addWidget(buttons);
}

JointSet JointSetDialog::jointSet() const
{
    JointSet set;
    set.name = name_->text().trimmed().toStdString();
    set.angle = angle_->value() * pi / 180.0;
    set.spacing = spacing_->value();
    set.origin = {origin_x_->value(), origin_y_->value()};
    if (use_extent_->isChecked())
        set.extent = std::array<double, 4>{extent_[0]->value(), extent_[1]->value(), extent_[2]->value(),
                                           extent_[3]->value()};
    set.joint_material = material_->currentData().toInt();
    if (persistence_->value() < 100.0) {
        set.persistence = persistence_->value() / 100.0;
        set.trace_length = trace_length_->value();
        set.stagger = stagger_->value() / 100.0;
    }
    return set;
}

void JointSetDialog::setJointSet(const JointSet& set)
{
    name_->setText(QString::fromStdString(set.name));
    angle_->setValue(set.angle * 180.0 / pi);
    spacing_->setValue(set.spacing);
    origin_x_->setValue(set.origin.x);
    origin_y_->setValue(set.origin.y);
    use_extent_->setChecked(set.extent.has_value());
    if (set.extent)
        for (int i = 0; i < 4; ++i) extent_[i]->setValue((*set.extent)[static_cast<std::size_t>(i)]);
    const int index = material_->findData(set.joint_material);
    if (index >= 0) material_->setCurrentIndex(index);
    persistence_->setValue(set.persistence * 100.0);
    trace_length_->setValue(set.trace_length);
    stagger_->setValue(set.stagger * 100.0);
}

QString JointSetDialog::validationError() const
{
    if (!(spacing_->value() > 0.0)) return tr("The spacing must be positive.");
    if (use_extent_->isChecked() &&
        (extent_[0]->value() >= extent_[2]->value() || extent_[1]->value() >= extent_[3]->value()))
        return tr("The box needs x min < x max and y min < y max.");
    if (!(persistence_->value() > 0.0)) return tr("The persistence must be above 0 %.");
    if (persistence_->value() < 100.0 && !(trace_length_->value() > 0.0))
        return tr("A persistence below 100 % needs a positive trace length.");
    return {};
}

void JointSetDialog::updatePreview()
{
    const bool usable = validationError().isEmpty();
    preview_->setJointSet(usable ? jointSet() : JointSet{});
    count_->setText(usable ? tr("%n trace(s) cut rock", "", preview_->traceCount()) : validationError());
}

void JointSetDialog::accept()
{
    const QString error = validationError();
    error_->setText(error);
    if (error.isEmpty()) QDialog::accept();
}

}  // namespace mcdda::gui
