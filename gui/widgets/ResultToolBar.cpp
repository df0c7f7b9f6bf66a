#include "widgets/ResultToolBar.hpp"

#include "session/DisplayUnits.hpp"

#include <QActionGroup>
#include <QComboBox>
#include <QMenu>
#include <QToolButton>
#include <QDoubleSpinBox>
#include <QDoubleValidator>
#include <QIcon>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSpinBox>

#include <cmath>
#include <limits>

namespace mcdda::gui {

namespace {

/// A number typed in `edit` (in the user's locale), NaN when empty or not a number.
double typed_number(const QLineEdit* edit)
{
    bool ok = false;
    const double v = QLocale().toDouble(edit->text().trimmed(), &ok);
    return ok && std::isfinite(v) ? v : std::numeric_limits<double>::quiet_NaN();
}

/// The stress fields that have an effective counterpart ("effective_" + name); τxy is the same
/// total and effective.
bool has_effective(const QString& field)
{
    return field == QLatin1String("stress_xx") || field == QLatin1String("stress_yy") ||
           field == QLatin1String("stress_1") || field == QLatin1String("stress_3");
}

const QLatin1String effective_prefix("effective_");

QLabel* label(const QString& text, QWidget* parent)
{
    auto* l = new QLabel(text, parent);
    l->setContentsMargins(6, 0, 2, 0);
    return l;
}

}  // namespace

namespace {

/// The list drops down below the box, as in a web form: the style's default lays it over the
/// box with the current item under the pointer, so that a field further down the list opened
/// far above the toolbar and the next click could choose an item by accident.
void drop_down_below(QComboBox* box)
{
    box->setStyleSheet(QStringLiteral("QComboBox { combobox-popup: 0; }"));
    box->setMaxVisibleItems(16);
}

}  // namespace

ResultToolBar::ResultToolBar(QWidget* parent) : QToolBar(tr("Results"), parent)
{
    setObjectName(QStringLiteral("results"));
    field_box_ = new QComboBox(this);
    field_box_->setToolTip(tr("Field shown for results"));
    field_box_->setObjectName(QStringLiteral("fieldBox"));
    field_box_->addItem(tr("Displacement |u|"), QStringLiteral("displacement"));
    field_box_->addItem(tr("Displacement ux"), QStringLiteral("ux"));
    field_box_->addItem(tr("Displacement uy"), QStringLiteral("uy"));
    field_box_->addItem(tr("Stress σxx"), QStringLiteral("stress_xx"));
    field_box_->addItem(tr("Stress σyy"), QStringLiteral("stress_yy"));
    field_box_->addItem(tr("Stress τxy"), QStringLiteral("stress_xy"));
    field_box_->addItem(tr("Principal stress σ1"), QStringLiteral("stress_1"));
    field_box_->addItem(tr("Principal stress σ3"), QStringLiteral("stress_3"));
    field_box_->addItem(tr("Plastic state"), QStringLiteral("plastic_state"));
    field_box_->addItem(tr("Plastic strain"), QStringLiteral("plastic_strain"));
    // The mechanism of a strength reduction (its last saved step): what changed between the
    // last factor that stood and the one before.
    field_box_->addItem(tr("Mechanism: plastic strain increment"), QStringLiteral("plastic_strain_increment"));
    field_box_->addItem(tr("Mechanism: displacement increment"), QStringLiteral("displacement_increment"));
    connect(field_box_, &QComboBox::currentIndexChanged, this, &ResultToolBar::optionsChanged);
    drop_down_below(field_box_);
    addWidget(field_box_);

    sign_box_ = new QComboBox(this);
    sign_box_->setObjectName(QStringLiteral("stressSignBox"));
    sign_box_->addItem(tr("compression +"), int(view::StressSign::CompressionPositive));
    sign_box_->addItem(tr("tension +"), int(view::StressSign::TensionPositive));
    sign_box_->setToolTip(tr("Sign of the stresses shown. Compression positive (as RS2, PLAXIS and UDEC): σ1 is the "
                             "major compressive stress, σ1 ≥ σ3. Tension positive: the result files' convention."));
    connect(sign_box_, &QComboBox::currentIndexChanged, this, &ResultToolBar::optionsChanged);
    addWidget(sign_box_);

    basis_box_ = new QComboBox(this);
    basis_box_->setObjectName(QStringLiteral("stressBasisBox"));
    basis_box_->addItem(tr("Total stress"), false);
    basis_box_->addItem(tr("Effective stress"), true);
    basis_box_->setToolTip(tr("Stresses of a run with ground water: total stress σ, or effective stress σ′ (the total "
                              "stress less the pore pressure: what the rock or soil yields on). τxy is the same in "
                              "both. Without water the stresses are total."));
    basis_box_->setEnabled(false);
    connect(basis_box_, &QComboBox::currentIndexChanged, this, &ResultToolBar::optionsChanged);
    addWidget(basis_box_);

    addWidget(label(tr("Deformation ×"), this));
    deform_box_ = new QDoubleSpinBox(this);
    deform_box_->setObjectName(QStringLiteral("deformBox"));
    deform_box_->setToolTip(tr("Scale factor of the drawn displacements: 0 = undeformed; one step below 0 = auto, the "
                               "largest displacement drawn as 5 % of the model's size"));
    deform_box_->setRange(-1.0, 1e6);
    deform_box_->setSpecialValueText(tr("auto"));  // shown at the minimum, −1
    deform_box_->setDecimals(1);
    deform_box_->setSingleStep(10.0);
    deform_box_->setValue(0.0);
    connect(deform_box_, &QDoubleSpinBox::valueChanged, this, &ResultToolBar::optionsChanged);
    addWidget(deform_box_);
    info_ = new QLabel(this);
    info_->setObjectName(QStringLiteral("deformInfo"));
    info_->setContentsMargins(4, 0, 4, 0);
    addWidget(info_);

    contacts_ = addAction(QIcon(QStringLiteral(":/icons/contacts.svg")), tr("Contacts"));
    contacts_->setObjectName(QStringLiteral("contactsAction"));
    contacts_->setCheckable(true);
    contacts_->setChecked(true);
    contacts_->setToolTip(tr("Draw the contact forces (lines along the force, the largest 6 % of the model long), "
                             "joint slip and opening, and the bolts of the saved step shown"));
    connect(contacts_, &QAction::toggled, this, &ResultToolBar::optionsChanged);

    // Units: one choice for the legend, the read-out under the cursor and the query lines.
    auto* units = new QToolButton(this);
    units->setObjectName(QStringLiteral("unitsButton"));
    units->setText(tr("Units"));
    units->setToolTip(tr("Units of stresses and displacements in the legend, the cursor read-out and query lines"));
    units->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(units);
    auto choice = [&](QActionGroup* group, const QString& text, const QString& name, int value) {
        QAction* a = menu->addAction(text);
        a->setObjectName(name);
        a->setCheckable(true);
        a->setData(value);
        group->addAction(a);
    };
    stress_units_ = new QActionGroup(this);
    menu->addSection(tr("Stresses"));
    choice(stress_units_, tr("kPa, or MPa from 1 MPa on"), QStringLiteral("stressUnitAuto"), int(view::StressUnit::Automatic));
    choice(stress_units_, tr("kPa"), QStringLiteral("stressUnitKPa"), int(view::StressUnit::KPa));
    choice(stress_units_, tr("MPa"), QStringLiteral("stressUnitMPa"), int(view::StressUnit::MPa));
    length_units_ = new QActionGroup(this);
    menu->addSection(tr("Displacements"));
    choice(length_units_, tr("m"), QStringLiteral("lengthUnitM"), int(view::LengthUnit::Metre));
    choice(length_units_, tr("mm"), QStringLiteral("lengthUnitMm"), int(view::LengthUnit::Millimetre));
    units->setMenu(menu);
    addWidget(units);
    // One choice for the whole program (legend, read-outs, forms, tree), kept between sessions.
    DisplayUnits* chosen = DisplayUnits::instance();
    setUnits(chosen->stress(), chosen->length());
    for (QActionGroup* group : {stress_units_, length_units_})
        connect(group, &QActionGroup::triggered, this, [this] { DisplayUnits::instance()->set(stressUnit(), lengthUnit()); });
    connect(chosen, &DisplayUnits::changed, this, [this] {
        setUnits(DisplayUnits::instance()->stress(), DisplayUnits::instance()->length());
    });

    addSeparator();
    map_box_ = new QComboBox(this);
    map_box_->setObjectName(QStringLiteral("colourMapBox"));
    map_box_->addItem(tr("Rainbow"), int(view::ColourMap::Rainbow));
    map_box_->addItem(tr("Viridis"), int(view::ColourMap::Viridis));
    map_box_->addItem(tr("Grey"), int(view::ColourMap::Grey));
    map_box_->addItem(tr("Blue–white–red"), int(view::ColourMap::Diverging));
    map_box_->setToolTip(tr("Colour map of the scale"));
    connect(map_box_, &QComboBox::currentIndexChanged, this, &ResultToolBar::optionsChanged);
    addWidget(map_box_);
    bands_box_ = new QSpinBox(this);
    bands_box_->setObjectName(QStringLiteral("bandsBox"));
    bands_box_->setRange(0, 64);
    bands_box_->setSpecialValueText(tr("smooth"));
    bands_box_->setSuffix(tr(" bands"));
    bands_box_->setToolTip(tr("Number of colour bands (contours); smooth = a continuous scale"));
    connect(bands_box_, &QSpinBox::valueChanged, this, &ResultToolBar::optionsChanged);
    addWidget(bands_box_);
    addWidget(label(tr("Range"), this));
    for (QLineEdit** edit : {&min_edit_, &max_edit_}) {
        *edit = new QLineEdit(this);
        (*edit)->setPlaceholderText(tr("auto"));
        (*edit)->setMaximumWidth(70);
        (*edit)->setValidator(new QDoubleValidator(*edit));
        connect(*edit, &QLineEdit::editingFinished, this, &ResultToolBar::optionsChanged);
        addWidget(*edit);
    }
    min_edit_->setObjectName(QStringLiteral("rangeMinEdit"));
    max_edit_->setObjectName(QStringLiteral("rangeMaxEdit"));
    min_edit_->setToolTip(tr("Lower end of the colour scale in the legend's units; empty = automatic"));
    max_edit_->setToolTip(tr("Upper end of the colour scale in the legend's units; empty = automatic"));
}

QString ResultToolBar::field() const { return field_box_->currentData().toString(); }

void ResultToolBar::setField(const QString& field)
{
    QString chosen = field;
    if (field.startsWith(effective_prefix) && has_effective(field.mid(effective_prefix.size()))) {
        chosen = field.mid(effective_prefix.size());
        if (basis_box_->isEnabled()) setEffectiveStress(true);
    }
    const int index = field_box_->findData(chosen);
    if (index >= 0) field_box_->setCurrentIndex(index);
}

QString ResultToolBar::shownField() const
{
    const QString chosen = field();
    return effectiveStress() && has_effective(chosen) ? effective_prefix + chosen : chosen;
}

void ResultToolBar::setWaterResults(bool water)
{
    const QSignalBlocker block_fields(field_box_), block_basis(basis_box_);
    const QString pore = QStringLiteral("pore_pressure");
    const int at = field_box_->findData(pore);
    if (water && at < 0) {
        // After the stresses it changes, before the plastic state.
        field_box_->insertItem(field_box_->findData(QStringLiteral("stress_3")) + 1, tr("Pore pressure u"), pore);
    } else if (!water && at >= 0) {
        const bool shown = field_box_->currentIndex() == at;
        field_box_->removeItem(at);
        if (shown) field_box_->setCurrentIndex(field_box_->findData(QStringLiteral("displacement")));
    }
    basis_box_->setEnabled(water);
    if (!water) basis_box_->setCurrentIndex(0);
}

bool ResultToolBar::waterResults() const { return basis_box_->isEnabled(); }

bool ResultToolBar::effectiveStress() const { return basis_box_->isEnabled() && basis_box_->currentData().toBool(); }

void ResultToolBar::setEffectiveStress(bool effective) { basis_box_->setCurrentIndex(effective ? 1 : 0); }

double ResultToolBar::deformFactor() const { return std::max(0.0, deform_box_->value()); }

void ResultToolBar::setDeformFactor(double factor) { deform_box_->setValue(std::max(0.0, factor)); }

bool ResultToolBar::deformAuto() const { return deform_box_->value() < 0.0; }

void ResultToolBar::setDeformAuto(bool on) { deform_box_->setValue(on ? -1.0 : 0.0); }

void ResultToolBar::setUnits(view::StressUnit stress, view::LengthUnit length)
{
    for (auto [group, value] : {std::pair{stress_units_, int(stress)}, std::pair{length_units_, int(length)}})
        for (QAction* a : group->actions()) a->setChecked(a->data().toInt() == value);
    DisplayUnits::instance()->set(stress, length);  // nothing when it is the choice already
    emit optionsChanged();
}

view::StressUnit ResultToolBar::stressUnit() const
{
    QAction* a = stress_units_->checkedAction();
    return a ? static_cast<view::StressUnit>(a->data().toInt()) : view::StressUnit::Automatic;
}

view::LengthUnit ResultToolBar::lengthUnit() const
{
    QAction* a = length_units_->checkedAction();
    return a ? static_cast<view::LengthUnit>(a->data().toInt()) : view::LengthUnit::Metre;
}

view::StressSign ResultToolBar::stressSign() const { return static_cast<view::StressSign>(sign_box_->currentData().toInt()); }

void ResultToolBar::setStressSign(view::StressSign sign) { sign_box_->setCurrentIndex(sign_box_->findData(int(sign))); }

void ResultToolBar::setColourScale(view::ColourMap map, int bands, double min, double max)
{
    const QSignalBlocker a(map_box_), b(bands_box_);
    map_box_->setCurrentIndex(map_box_->findData(int(map)));
    bands_box_->setValue(bands);
    min_edit_->setText(std::isfinite(min) ? QLocale().toString(min) : QString());
    max_edit_->setText(std::isfinite(max) ? QLocale().toString(max) : QString());
    emit optionsChanged();
}

bool ResultToolBar::showContacts() const { return contacts_->isChecked(); }

void ResultToolBar::setShowContacts(bool show) { contacts_->setChecked(show); }

view::ResultOptions ResultToolBar::options() const
{
    view::ResultOptions options;
    options.field = shownField().toStdString();
    options.stress_sign = stressSign();
    options.stress_unit = stressUnit();
    options.length_unit = lengthUnit();
    options.deform = deformFactor();
    options.deform_auto = deformAuto();
    options.colour_map = static_cast<view::ColourMap>(map_box_->currentData().toInt());
    options.bands = bands_box_->value();
    options.range_min = typed_number(min_edit_);
    options.range_max = typed_number(max_edit_);
    return options;
}

void ResultToolBar::showInfo(const view::ResultInfo& info)
{
    QString text;
    if (info.deform_factor != 0.0)
        text = deformAuto() ? tr("×%1 (auto)").arg(QLocale().toString(info.deform_factor, 'g', 3)) : QString();
    if (info.inverted_elements > 0)
        text += (text.isEmpty() ? QString() : QStringLiteral("  ")) +
                tr("⚠ %n element(s) drawn inside out: lower the scale", "", info.inverted_elements);
    info_->setText(text);
    info_->setStyleSheet(info.inverted_elements > 0 ? QStringLiteral("color: #b00020") : QString());
}

QString ResultToolBar::infoText() const { return info_->text(); }

}  // namespace mcdda::gui
