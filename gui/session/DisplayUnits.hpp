#pragma once
/// \file DisplayUnits.hpp
/// The one choice of units the user makes (Results toolbar ▸ Units): stresses in kPa, MPa or
/// automatic, displacements in m or mm. Kept between sessions (QSettings "units/stress",
/// "units/length") and shared by the legend and read-outs, the property forms and the Model
/// tree; changed() tells them all to show their values again.

#include "model/ModelFields.hpp"
#include "view/ResultScene.hpp"

#include <QObject>
#include <QString>

namespace mcdda::gui {

class DisplayUnits : public QObject {
    Q_OBJECT

public:
    /// The application's choice (created on first use, a child of the application).
    static DisplayUnits* instance();

    view::StressUnit stress() const { return stress_; }
    view::LengthUnit length() const { return length_; }
    /// Stores the choice and emits changed() when it differs.
    void set(view::StressUnit stress, view::LengthUnit length);

    /// The unit forms show a stress in, and its size in Pa: MPa when MPa was chosen, else kPa
    /// (automatic keeps kPa in forms: a field's unit does not jump with the value typed).
    QString formStressUnit() const;
    double formStressFactor() const;
    /// The same for moduli (E): kPa or MPa as chosen; automatic: MPa.
    QString formModulusUnit() const;
    double formModulusFactor() const;
    /// The unit forms and messages show a declared quantity in (MPa, kPa, kN/m³, °, MN/m, kN/m,
    /// s, Hz; empty for a ratio), and its size in model units: model value = shown × factor.
    QString unitOf(Quantity quantity) const;
    double factorOf(Quantity quantity) const;

signals:
    void changed();

private:
    explicit DisplayUnits(QObject* parent);

    view::StressUnit stress_ = view::StressUnit::Automatic;
    view::LengthUnit length_ = view::LengthUnit::Metre;
};

}  // namespace mcdda::gui
