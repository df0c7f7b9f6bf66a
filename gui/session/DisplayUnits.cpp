#include "session/DisplayUnits.hpp"

#include "model/Defaults.hpp"

#include <QCoreApplication>
#include <QSettings>

namespace mcdda::gui {

namespace {

const QString stress_key = QStringLiteral("units/stress");
const QString length_key = QStringLiteral("units/length");

}  // namespace

DisplayUnits::DisplayUnits(QObject* parent) : QObject(parent)
{
    const QSettings settings;
    const int stress = settings.value(stress_key, 0).toInt();
    const int length = settings.value(length_key, 0).toInt();
    if (stress >= 0 && stress <= int(view::StressUnit::MPa)) stress_ = static_cast<view::StressUnit>(stress);
    if (length >= 0 && length <= int(view::LengthUnit::Millimetre)) length_ = static_cast<view::LengthUnit>(length);
}

DisplayUnits* DisplayUnits::instance()
{
    static DisplayUnits* units = nullptr;
    if (!units) {
        units = new DisplayUnits(QCoreApplication::instance());
        // Gone with the application: a later application (tests) gets a fresh one.
        QObject::connect(units, &QObject::destroyed, [] { units = nullptr; });
    }
    return units;
}

void DisplayUnits::set(view::StressUnit stress, view::LengthUnit length)
{
    if (stress == stress_ && length == length_) return;
    stress_ = stress;
    length_ = length;
    QSettings settings;
    settings.setValue(stress_key, int(stress));
    settings.setValue(length_key, int(length));
    emit changed();
}

QString DisplayUnits::formStressUnit() const
{
    return stress_ == view::StressUnit::MPa ? tr("MPa") : tr("kPa");
}

double DisplayUnits::formStressFactor() const { return stress_ == view::StressUnit::MPa ? 1e6 : 1e3; }

QString DisplayUnits::formModulusUnit() const
{
    return stress_ == view::StressUnit::KPa ? tr("kPa") : tr("MPa");
}

double DisplayUnits::formModulusFactor() const { return stress_ == view::StressUnit::KPa ? 1e3 : 1e6; }

QString DisplayUnits::unitOf(Quantity quantity) const
{
    switch (quantity) {
    case Quantity::Ratio: return QString();
    case Quantity::Modulus: return formModulusUnit();
    case Quantity::Stress: return formStressUnit();
    case Quantity::Density: return tr("kN/m³");
    case Quantity::Angle: return tr("°");
    case Quantity::Stiffness: return tr("MN/m");
    case Quantity::Force: return tr("kN/m");
    case Quantity::Time: return tr("s");
    case Quantity::Frequency: return tr("Hz");
    }
    return QString();
}

double DisplayUnits::factorOf(Quantity quantity) const
{
    switch (quantity) {
    case Quantity::Modulus: return formModulusFactor();
    case Quantity::Stress: return formStressFactor();
    case Quantity::Density: return 1e3 / standard_gravity;  // unit weight γ = ρ g in kN/m³
    case Quantity::Angle: return degree;
    case Quantity::Stiffness: return 1e6;
    case Quantity::Force: return 1e3;
    default: return 1.0;
    }
}

}  // namespace mcdda::gui
