#include "panels/EarthquakePanel.hpp"

#include "document/ModelDocument.hpp"
#include "io/AccelerationRecord.hpp"
#include "model/Defaults.hpp"
#include "panels/FormFields.hpp"
#include "results/RecordPlot.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>

namespace mcdda::gui {

namespace {

using form::explain;
using form::to_qt;

/// A record whose peak exceeds this in the file's numbers is taken to be in m/s², not g (no
/// earthquake reaches 5 g).
constexpr double largest_peak_in_g = 5.0;

QString record_label(const GroundMotion& g)
{
    return QStringLiteral("%1 (%2)").arg(to_qt(g.name),
                                         g.units == GroundMotion::Units::G ? EarthquakePanel::tr("g") : EarthquakePanel::tr("m/s²"));
}

}  // namespace

EarthquakePanel::EarthquakePanel(ModelDocument* document, QWidget* parent) : QWidget(parent), document_(document)
{
    setObjectName(QStringLiteral("earthquakePanel"));
    auto* inner = new QWidget;
    auto* column = new QVBoxLayout(inner);

    // Records.
    auto* records = new QGroupBox(tr("Ground motions (acceleration records)"), inner);
    auto* records_layout = new QVBoxLayout(records);
    list_ = new QListWidget(records);
    list_->setObjectName(QStringLiteral("groundMotionList"));
    list_->setMaximumHeight(90);
    explain(list_, tr("The model's earthquake records; the one chosen is plotted and edited below"));
    records_layout->addWidget(list_);
    auto* buttons = new QHBoxLayout;
    auto* import = new QPushButton(tr("Import..."), records);
    import->setObjectName(QStringLiteral("importRecordButton"));
    explain(import, tr("Read an acceleration record: a CSV file of time (s) and acceleration, or a PEER NGA .AT2 file (in g)"));
    remove_ = new QPushButton(tr("Remove"), records);
    remove_->setObjectName(QStringLiteral("removeRecordButton"));
    buttons->addWidget(import);
    buttons->addWidget(remove_);
    buttons->addStretch(1);
    records_layout->addLayout(buttons);
    auto* record_form = new QFormLayout;
    name_ = new QLineEdit(records);
    name_->setObjectName(QStringLiteral("recordName"));
    record_form->addRow(tr("Name"), name_);
    units_ = new QComboBox(records);
    units_->setObjectName(QStringLiteral("recordUnits"));
    units_->addItem(tr("g"), static_cast<int>(GroundMotion::Units::G));
    units_->addItem(tr("m/s²"), static_cast<int>(GroundMotion::Units::MetresPerSecondSquared));
    record_form->addRow(tr("Units"), units_);
    explain(units_, tr("Unit of the accelerations in the file: g (as in .AT2 files) or m/s²"));
    scale_ = form::number(QStringLiteral("recordScale"), QString(), -1e3, 1e3, 4, records);
    scale_->setSingleStep(0.1);
    record_form->addRow(tr("Scale [–]"), scale_);
    explain(scale_, tr("Factor on the accelerations, e.g. to scale a record to a design peak ground acceleration"));
    baseline_ = new QCheckBox(tr("Baseline correction"), records);
    baseline_->setObjectName(QStringLiteral("recordBaseline"));
    record_form->addRow(QString(), baseline_);
    explain(baseline_, tr("Take a linear trend off the acceleration so that the base ends at rest where it began "
                          "(the integrated record does not drift)"));
    file_ = new QLabel(records);
    file_->setObjectName(QStringLiteral("recordFile"));
    file_->setWordWrap(true);
    file_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    record_form->addRow(tr("File"), file_);
    records_layout->addLayout(record_form);
    record_status_ = form::status_label(QStringLiteral("recordStatus"), records);
    records_layout->addWidget(record_status_);
    plot_ = new RecordPlot(records);
    plot_->setObjectName(QStringLiteral("recordPlot"));
    plot_->setMinimumHeight(200);
    records_layout->addWidget(plot_, 1);
    column->addWidget(records, 1);

    // The base.
    auto* base = new QGroupBox(tr("Base motion"), inner);
    auto* base_form = new QFormLayout(base);
    base_kind_ = new QComboBox(base);
    base_kind_->setObjectName(QStringLiteral("baseKind"));
    base_kind_->addItem(tr("None"), static_cast<int>(BaseMotion::Kind::None));
    base_kind_->addItem(tr("Rigid (supports move)"), static_cast<int>(BaseMotion::Kind::Rigid));
    base_kind_->addItem(tr("Compliant (dashpots)"), static_cast<int>(BaseMotion::Kind::Compliant));
    base_form->addRow(tr("Shaking"), base_kind_);
    explain(base_kind_, tr("Rigid: the supports move with the record and the analysis runs relative to them (a shaking "
                           "table). Compliant: the segment carries dashpots and the incoming wave, so waves sent down "
                           "leave the model. The base shakes the dynamic stages only"));
    base_x_ = new QComboBox(base);
    base_x_->setObjectName(QStringLiteral("baseX"));
    base_form->addRow(tr("Horizontal (x)"), base_x_);
    explain(base_x_, tr("The record of the horizontal acceleration"));
    base_y_ = new QComboBox(base);
    base_y_->setObjectName(QStringLiteral("baseY"));
    base_form->addRow(tr("Vertical (y)"), base_y_);
    explain(base_y_, tr("The record of the vertical acceleration"));
    auto point_row = [&](QDoubleSpinBox* boxes[2], const QString& name, const QString& label) {
        auto* row = new QHBoxLayout;
        for (int k = 0; k < 2; ++k) {
            boxes[k] = form::number(name + (k == 0 ? QStringLiteral("X") : QStringLiteral("Y")), tr("m"), -1e7, 1e7, 3, base);
            // Two on a row: they share the width instead of asking for room for ±10⁷ m each.
            boxes[k]->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
            boxes[k]->setMinimumWidth(70);
            row->addWidget(boxes[k]);
        }
        base_form->addRow(label, row);
    };
    point_row(base_from_, QStringLiteral("baseFrom"), tr("From (x, y)"));
    point_row(base_to_, QStringLiteral("baseTo"), tr("To (x, y)"));
    base_draw_ = new QPushButton(tr("Draw..."), base);
    base_draw_->setObjectName(QStringLiteral("baseDraw"));
    explain(base_draw_, tr("Click the two ends of the compliant base in the picture"));
    base_form->addRow(QString(), base_draw_);
    base_status_ = form::status_label(QStringLiteral("baseStatus"), base);
    base_form->addRow(base_status_);
    column->addWidget(base);

    // Pseudo-static.
    auto* seismic = new QGroupBox(tr("Seismic coefficient (pseudo-static)"), inner);
    auto* seismic_form = new QFormLayout(seismic);
    kh_ = form::number(QStringLiteral("seismicKh"), QString(), -2.0, 2.0, 3, seismic);
    kh_->setSingleStep(0.05);
    seismic_form->addRow(tr("kh [–]"), kh_);
    explain(kh_, tr("Horizontal seismic coefficient: every block carries kh·g per unit mass, towards +x for kh > 0"));
    kv_ = form::number(QStringLiteral("seismicKv"), QString(), -2.0, 2.0, 3, seismic);
    kv_->setSingleStep(0.05);
    seismic_form->addRow(tr("kv [–]"), kv_);
    explain(kv_, tr("Vertical seismic coefficient: kv·g per unit mass, upwards for kv > 0"));
    column->addWidget(seismic);
    // Typed values wait for Enter or Apply, as in every form (form::apply_on_enter); a choice
    // made in a list or a box ticked applies at once.
    auto* apply = new QPushButton(tr("Apply"), inner);
    apply->setObjectName(QStringLiteral("earthquakeApply"));
    apply->setToolTip(tr("Apply the values typed in the record, base and seismic coefficient fields"));
    column->addWidget(apply, 0, Qt::AlignRight);

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(inner);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);

    connect(import, &QPushButton::clicked, this, &EarthquakePanel::importDialog);
    connect(remove_, &QPushButton::clicked, this, &EarthquakePanel::removeRecord);
    connect(list_, &QListWidget::currentRowChanged, this, [this] { if (!loading_) showRecord(); });
    form::apply_on_enter(name_, [this] { if (!loading_) applyRecord(); });
    connect(units_, &QComboBox::currentIndexChanged, this, [this] { if (!loading_) applyRecord(); });
    form::apply_on_enter(scale_, [this] { if (!loading_) applyRecord(); });
    connect(baseline_, &QCheckBox::toggled, this, [this] { if (!loading_) applyRecord(); });
    // Long choices (record names, the base's kinds) must not widen the dock.
    for (QComboBox* box : {units_, base_kind_, base_x_, base_y_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(10);
        box->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        box->setMinimumWidth(100);
    }
    for (QComboBox* box : {base_kind_, base_x_, base_y_})
        connect(box, &QComboBox::currentIndexChanged, this, [this] { if (!loading_) applyBase(); });
    for (QDoubleSpinBox* box : {base_from_[0], base_from_[1], base_to_[0], base_to_[1]})
        form::apply_on_enter(box, [this] { if (!loading_) applyBase(); });
    connect(base_draw_, &QPushButton::clicked, this, &EarthquakePanel::drawBaseRequested);
    for (QDoubleSpinBox* box : {kh_, kv_}) form::apply_on_enter(box, [this] { if (!loading_) applySeismic(); });
    connect(apply, &QPushButton::clicked, this, [this] {
        if (loading_) return;
        applyRecord();
        applyBase();
        applySeismic();
    });
    connect(document_, &ModelDocument::changed, this, &EarthquakePanel::refresh);
    refresh();
}

int EarthquakePanel::currentRecord() const { return list_->currentRow(); }

void EarthquakePanel::setCurrentRecord(int index) { list_->setCurrentRow(index); }

QString EarthquakePanel::recordStatus() const { return record_status_->text(); }
QString EarthquakePanel::baseStatus() const { return base_status_->text(); }

void EarthquakePanel::importDialog()
{
    const QString folder = document_->path().isEmpty() ? QString() : QFileInfo(document_->path()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Import acceleration record"), folder,
                                                      tr("Acceleration records (*.csv *.txt *.at2 *.AT2);;All files (*)"));
    if (!path.isEmpty()) importRecord(path);
}

bool EarthquakePanel::importRecord(const QString& path)
{
    AccelerationRecord record;
    try {
        record = read_acceleration_record(QFile::encodeName(path).toStdString());
    } catch (const std::exception& e) {
        // The reader's own words: which file, which line, what is wrong there.
        const QString text = tr("The record was not imported: %1").arg(QString::fromLocal8Bit(e.what()));
        form::set_status(record_status_, text, true);
        emit message(text);
        return false;
    }
    const Model& m = document_->model();
    GroundMotion g;
    QString name = QFileInfo(path).completeBaseName();
    for (int n = 2; std::any_of(m.ground_motions.begin(), m.ground_motions.end(),
                                [&](const GroundMotion& x) { return to_qt(x.name) == name; });
         ++n)
        name = QStringLiteral("%1 (%2)").arg(QFileInfo(path).completeBaseName()).arg(n);
    g.name = name.toStdString();
    // Relative to the model's folder once it has one, so model and records move together.
    const QString absolute = QFileInfo(path).absoluteFilePath();
    g.file = (document_->path().isEmpty() ? path : QDir(QFileInfo(document_->path()).absolutePath()).relativeFilePath(absolute))
                 .toStdString();
    double peak = 0.0;
    for (const auto& p : record.points) peak = std::max(peak, std::fabs(p[1]));
    g.units = record.peer_at2 || peak <= largest_peak_in_g ? GroundMotion::Units::G : GroundMotion::Units::MetresPerSecondSquared;
    g.points = std::move(record.points);
    const int index = document_->addGroundMotion(g);
    setCurrentRecord(index);
    const QString text = tr("Imported \"%1\": %n point(s), read in %2 (change Units if the file is in the other unit).", "",
                            static_cast<int>(g.points.size()))
                             .arg(name, g.units == GroundMotion::Units::G ? tr("g") : tr("m/s²"));
    form::set_status(record_status_, text, false);
    emit message(text);
    return true;
}

void EarthquakePanel::refresh()
{
    const Model& m = document_->model();
    loading_ = true;
    const int row = list_->currentRow();
    {
        const QSignalBlocker block(list_);
        list_->clear();
        for (const GroundMotion& g : m.ground_motions) list_->addItem(record_label(g));
        list_->setCurrentRow(std::min(std::max(row, m.ground_motions.empty() ? -1 : 0), list_->count() - 1));
    }
    // The base: its choices are the records.
    const BaseMotion& b = m.base_motion;
    for (auto [box, chosen] : {std::pair{base_x_, b.x}, std::pair{base_y_, b.y}}) {
        box->clear();
        box->addItem(tr("none"), -1);
        for (std::size_t i = 0; i < m.ground_motions.size(); ++i) box->addItem(to_qt(m.ground_motions[i].name), static_cast<int>(i));
        box->setCurrentIndex(std::max(0, box->findData(chosen)));
    }
    base_kind_->setCurrentIndex(std::max(0, base_kind_->findData(static_cast<int>(b.kind))));
    const bool compliant = b.kind == BaseMotion::Kind::Compliant;
    for (int k = 0; k < 2; ++k) {
        form::display(base_from_[k], k == 0 ? b.from.x : b.from.y);
        form::display(base_to_[k], k == 0 ? b.to.x : b.to.y);
        base_from_[k]->setEnabled(compliant);
        base_to_[k]->setEnabled(compliant);
    }
    base_draw_->setEnabled(!m.ground_motions.empty());
    base_x_->setEnabled(b.present());
    base_y_->setEnabled(b.present());
    form::display(kh_, m.seismic_coefficient.kh);
    form::display(kv_, m.seismic_coefficient.kv);
    loading_ = false;
    showRecord();
}

void EarthquakePanel::showRecord()
{
    const Model& m = document_->model();
    const int i = list_->currentRow();
    const GroundMotion* g = i >= 0 && i < static_cast<int>(m.ground_motions.size()) ? &m.ground_motions[i] : nullptr;
    loading_ = true;
    for (QWidget* w : std::initializer_list<QWidget*>{name_, units_, scale_, baseline_, remove_}) w->setEnabled(g != nullptr);
    name_->setText(g ? to_qt(g->name) : QString());
    units_->setCurrentIndex(g && g->units == GroundMotion::Units::MetresPerSecondSquared ? 1 : 0);
    form::display(scale_, g ? g->scale : 1.0);
    baseline_->setChecked(g ? g->baseline_correction : true);
    file_->setText(!g ? QString() : g->file.empty() ? tr("points given in the model") : to_qt(g->file));
    loading_ = false;
    plot_->showRecord(g);
}

void EarthquakePanel::applyRecord()
{
    const Model& m = document_->model();
    const int i = list_->currentRow();
    if (i < 0 || i >= static_cast<int>(m.ground_motions.size())) return;
    GroundMotion g = m.ground_motions[static_cast<std::size_t>(i)];
    const QString name = name_->text().trimmed();
    // The base names its records in the file: a name must be there and be its own.
    for (std::size_t k = 0; k < m.ground_motions.size(); ++k)
        if (static_cast<int>(k) != i && to_qt(m.ground_motions[k].name) == name) {
            form::set_status(record_status_, tr("Not applied: another ground motion is called \"%1\".").arg(name), true);
            return;
        }
    if (name.isEmpty()) {
        form::set_status(record_status_, tr("Not applied: a ground motion needs a name."), true);
        return;
    }
    if (form::si(scale_, g.scale, 1.0) == 0.0) {
        form::set_status(record_status_, tr("Not applied: the scale must not be 0."), true);
        return;
    }
    g.name = name.toStdString();
    g.units = static_cast<GroundMotion::Units>(units_->currentData().toInt());
    g.scale = form::si(scale_, g.scale, 1.0);
    g.baseline_correction = baseline_->isChecked();
    const GroundMotion& old = m.ground_motions[static_cast<std::size_t>(i)];
    if (g.name == old.name && g.units == old.units && g.scale == old.scale && g.baseline_correction == old.baseline_correction)
        return;
    document_->setGroundMotion(i, g);
    form::set_status(record_status_, tr("Applied."), false);
}

void EarthquakePanel::removeRecord()
{
    const int i = list_->currentRow();
    if (i < 0) return;
    document_->removeGroundMotion(i);
    form::set_status(record_status_, QString(), false);
}

void EarthquakePanel::applyBase()
{
    const Model& m = document_->model();
    BaseMotion b = m.base_motion;
    b.kind = static_cast<BaseMotion::Kind>(base_kind_->currentData().toInt());
    b.x = base_x_->currentData().toInt();
    b.y = base_y_->currentData().toInt();
    if (b.present() && b.x < 0 && b.y < 0) {
        // A base moves with some record; the first one until another is chosen.
        if (m.ground_motions.empty()) {
            form::set_status(base_status_, tr("Import a ground motion first: the base moves with it."), true);
            refresh();
            return;
        }
        b.x = 0;
    }
    if (!b.present()) b.x = b.y = -1;
    b.from = {form::si(base_from_[0], m.base_motion.from.x, 1.0), form::si(base_from_[1], m.base_motion.from.y, 1.0)};
    b.to = {form::si(base_to_[0], m.base_motion.to.x, 1.0), form::si(base_to_[1], m.base_motion.to.y, 1.0)};
    if (b.kind == BaseMotion::Kind::Compliant && b.from.x == b.to.x && b.from.y == b.to.y && m.base_motion.kind != BaseMotion::Kind::Compliant) {
        // Not drawn yet: the model's bottom edge, to be moved or drawn again.
        const auto box = m.bounds();
        if (!m.regions.empty()) b.from = {box[0], box[1]}, b.to = {box[2], box[1]};
    }
    const BaseMotion& old = m.base_motion;
    if (b.kind == old.kind && b.x == old.x && b.y == old.y && b.from.x == old.from.x && b.from.y == old.from.y &&
        b.to.x == old.to.x && b.to.y == old.to.y)
        return;
    document_->setBaseMotion(b);
    form::set_status(base_status_,
                     b.kind == BaseMotion::Kind::Rigid     ? tr("The supports move with the record in the dynamic stages.")
                     : b.kind == BaseMotion::Kind::Compliant ? tr("The record enters through the compliant base in the dynamic stages.")
                                                             : tr("No base motion."),
                     false);
}

void EarthquakePanel::applySeismic()
{
    const Model& m = document_->model();
    SeismicCoefficient k;
    k.kh = form::si(kh_, m.seismic_coefficient.kh, 1.0);
    k.kv = form::si(kv_, m.seismic_coefficient.kv, 1.0);
    if (k.kh == m.seismic_coefficient.kh && k.kv == m.seismic_coefficient.kv) return;
    document_->setSeismicCoefficient(-1, k);
}

}  // namespace mcdda::gui
