#include "session/DiagnosticText.hpp"

#include "material/MaterialLaw.hpp"
#include "material/MaterialLaws.hpp"
#include "session/DisplayUnits.hpp"

#include <QCoreApplication>
#include <QLocale>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace mcdda::gui {

namespace {

/// lupdate files the tr() of a free function under its namespace: the same context here.
QString tr(const char* text) { return QCoreApplication::translate("mcdda::gui", text); }
QString to_qt(const std::string& s) { return QString::fromStdString(s); }

std::vector<std::string> segments(const std::string& path)
{
    std::vector<std::string> parts;
    std::size_t at = 0;
    while (at < path.size()) {
        if (path[at] == '/') ++at;
        const std::size_t end = path.find('/', at);
        parts.push_back(path.substr(at, end == std::string::npos ? std::string::npos : end - at));
        if (end == std::string::npos) break;
        at = end;
    }
    return parts;
}

/// The index a pointer segment holds, or -1.
int index_of(const std::vector<std::string>& parts, std::size_t k)
{
    if (k >= parts.size() || parts[k].empty()) return -1;
    char* end = nullptr;
    const long i = std::strtol(parts[k].c_str(), &end, 10);
    return *end == '\0' && i >= 0 && i < std::numeric_limits<int>::max() ? static_cast<int>(i) : -1;
}

/// What a pointer names: the item in words and, for a declared number field, the field and its value.
struct Target {
    QString item;
    const NumberField* field = nullptr;
    double value = 0.0;
};

template <class Record>
void find_field(Target& t, const Record& record, const std::vector<RecordField<Record>>& fields, const std::string& key)
{
    for (const RecordField<Record>& f : fields)
        if (key == f.field.key) {
            t.field = &f.field;
            t.value = record.*f.member;
        }
}

/// The name of item `i` of a list, quoted, or nothing when the pointer is beyond the list.
template <class Item>
bool named(const std::vector<Item>& items, int i, const char* words, QString& item)
{
    if (i < 0 || static_cast<std::size_t>(i) >= items.size()) return false;
    item = tr(words).arg(to_qt(items[static_cast<std::size_t>(i)].name));
    return true;
}

Target locate(const Model& m, const std::string& path)
{
    Target t;
    const std::vector<std::string> p = segments(path);
    if (p.empty()) return t;
    const std::string& list = p[0];
    const int i = index_of(p, 1);
    const std::string key = p.size() > 2 ? p[2] : std::string();
    if (list == "materials") {
        if (!named(m.materials, i, QT_TRANSLATE_NOOP("mcdda::gui", "material \"%1\""), t.item)) return t;
        const Material& mat = m.materials[static_cast<std::size_t>(i)];
        find_field(t, mat, material_fields(), key);
        if (const MaterialLaw* law = find_material_law(mat.law); law && !t.field)
            for (const NumberField& f : law->fields)
                if (key == f.key) {
                    t.field = &f;
                    t.value = law_value(mat, f);
                }
    } else if (list == "joint_materials") {
        if (named(m.joint_materials, i, QT_TRANSLATE_NOOP("mcdda::gui", "joint material \"%1\""), t.item))
            find_field(t, m.joint_materials[static_cast<std::size_t>(i)], joint_material_fields(), key);
    } else if (list == "bolts") {
        if (named(m.bolts, i, QT_TRANSLATE_NOOP("mcdda::gui", "bolt \"%1\""), t.item))
            find_field(t, m.bolts[static_cast<std::size_t>(i)], bolt_fields(), key);
    } else if (list == "analysis") {
        t.item = tr("analysis settings");
        if (p.size() > 1) find_field(t, m.analysis, analysis_fields(), p[1]);
    } else if (list == "stages") {
        if (!named(m.stages, i, QT_TRANSLATE_NOOP("mcdda::gui", "stage \"%1\""), t.item)) return t;
        if (key == "analysis") {
            t.item = tr("%1, analysis settings").arg(t.item);
            if (p.size() > 3) find_field(t, m.stages[static_cast<std::size_t>(i)].analysis, analysis_fields(), p[3]);
        }
    } else if (list == "regions") {
        if (!named(m.regions, i, QT_TRANSLATE_NOOP("mcdda::gui", "region \"%1\""), t.item)) return t;
        if (key == "holes" && index_of(p, 3) >= 0) t.item = tr("%1, hole %2").arg(t.item).arg(index_of(p, 3) + 1);
    } else if (list == "load_tables") {
        if (!named(m.load_tables, i, QT_TRANSLATE_NOOP("mcdda::gui", "load table \"%1\""), t.item)) return t;
        if (key == "points" && index_of(p, 3) >= 0) t.item = tr("%1, point %2").arg(t.item).arg(index_of(p, 3) + 1);
    } else if (list == "joints") {
        named(m.joints, i, QT_TRANSLATE_NOOP("mcdda::gui", "joint \"%1\""), t.item);
        if (key == "points" && index_of(p, 3) >= 0) t.item = tr("%1, point %2").arg(t.item).arg(index_of(p, 3) + 1);
    } else if (list == "joint_sets") {
        named(m.joint_sets, i, QT_TRANSLATE_NOOP("mcdda::gui", "joint set \"%1\""), t.item);
    } else if (list == "fixed_points") {
        named(m.fixed_points, i, QT_TRANSLATE_NOOP("mcdda::gui", "fixed point \"%1\""), t.item);
    } else if (list == "rollers") {
        named(m.rollers, i, QT_TRANSLATE_NOOP("mcdda::gui", "roller \"%1\""), t.item);
    } else if (list == "point_loads") {
        named(m.point_loads, i, QT_TRANSLATE_NOOP("mcdda::gui", "point load \"%1\""), t.item);
    } else if (list == "edge_pressures") {
        named(m.edge_pressures, i, QT_TRANSLATE_NOOP("mcdda::gui", "edge pressure \"%1\""), t.item);
    } else if (list == "measurement_points") {
        named(m.measurement_points, i, QT_TRANSLATE_NOOP("mcdda::gui", "measurement point \"%1\""), t.item);
    } else if (list == "absorbing_boundaries") {
        named(m.absorbing_boundaries, i, QT_TRANSLATE_NOOP("mcdda::gui", "absorbing boundary \"%1\""), t.item);
    } else if (list == "ground_motions") {
        named(m.ground_motions, i, QT_TRANSLATE_NOOP("mcdda::gui", "ground motion \"%1\""), t.item);
    } else if (list == "mesh") {
        t.item = tr("mesh");
    } else if (list == "initial_stress") {
        t.item = tr("in-situ stress");
    } else if (list == "gravity") {
        t.item = tr("gravity");
    } else if (list == "water") {
        t.item = tr("ground water");
    } else if (list == "base_motion") {
        t.item = tr("base motion");
    } else if (list == "seismic_coefficient") {
        t.item = tr("seismic coefficient");
    }
    return t;
}

/// A field in messages: its form label where a translation is loaded (the solver's message
/// names are not marked for translation), else the name the solver's messages use.
QString field_words(const NumberField& f)
{
    const QString label = QCoreApplication::translate("ModelFields", f.label);
    return label != QString::fromUtf8(f.label) ? label : QString::fromUtf8(f.name);
}

/// An end of an allowed interval: a ratio without unit, angles and others with theirs.
QString bound_text(const NumberField& f, double v) { return quantity_text(f.quantity, v); }

/// range_error() of ModelFields.cpp in words and display units.
QString range_text(const NumberField& f, double value)
{
    QString rule;
    if (f.lower && f.upper) {
        rule = tr("must lie in %1%2, %3%4")
                   .arg(f.lower->inclusive ? QStringLiteral("[") : QStringLiteral("("), bound_text(f, f.lower->value),
                        bound_text(f, f.upper->value), f.upper->inclusive ? QStringLiteral("]") : QStringLiteral(")"));
    } else if (f.lower && f.lower->value == 0.0) {
        rule = f.lower->inclusive ? tr("must not be negative") : tr("must be positive");
    } else if (f.lower) {
        rule = (f.lower->inclusive ? tr("must be at least %1") : tr("must be more than %1")).arg(bound_text(f, f.lower->value));
    } else if (f.upper) {
        rule = (f.upper->inclusive ? tr("must be at most %1") : tr("must be less than %1")).arg(bound_text(f, f.upper->value));
    }
    QString got = tr("got %1").arg(quantity_text(f.quantity, value));
    if (f.zero_means) got = tr("%1; 0 = %2").arg(got, QCoreApplication::translate("ModelFields", f.zero_means));
    return tr("%1 %2 (%3)").arg(field_words(f), rule, got);
}

QString limit_text(const NumberField& f, double value)
{
    return tr("%1 of %2 is beyond any physical value (at most %3): check the units")
        .arg(field_words(f), quantity_text(f.quantity, value), quantity_text(f.quantity, f.physical_limit));
}

}  // namespace

QString quantity_text(Quantity quantity, double model_value)
{
    const DisplayUnits* units = DisplayUnits::instance();
    const double shown = model_value / units->factorOf(quantity);
    QString number = QLocale().toString(shown, 'g', 6);
    if (number.startsWith(QLatin1Char('-'))) number.replace(0, 1, QChar(0x2212));  // a true minus
    const QString unit = units->unitOf(quantity);
    if (unit.isEmpty()) return number;
    return quantity == Quantity::Angle ? number + unit : number + QLatin1Char(' ') + unit;
}

QString item_words(const Model& model, const std::string& path) { return locate(model, path).item; }

QString diagnostic_text(const Model& model, const Diagnostic& d)
{
    if (is_empty_model_notice(model, d)) return empty_model_hint();
    const Target t = locate(model, d.path);
    QString text;
    if (t.field) {
        // Restated only when it is the declared range or limit message: other messages about
        // the field (a law's cross-field check) keep their own words.
        if (const std::string why = range_error(*t.field, t.value); !why.empty() && why == d.message)
            text = range_text(*t.field, t.value);
        else if (const std::string why = limit_error(*t.field, t.value); !why.empty() && why == d.message)
            text = limit_text(*t.field, t.value);
    }
    if (text.isEmpty()) text = to_qt(d.message);
    return t.item.isEmpty() ? text : tr("%1: %2").arg(t.item, text);
}

QString diagnostic_line(const Model& model, const Diagnostic& d)
{
    if (is_empty_model_notice(model, d)) return empty_model_hint();
    return (d.severity == Diagnostic::Severity::Error ? tr("error: %1") : tr("warning: %1")).arg(diagnostic_text(model, d));
}

bool is_empty_model_notice(const Model& model, const Diagnostic& d)
{
    return model.regions.empty() && d.path == "/regions";
}

QString empty_model_hint()
{
    return tr("Draw a region to start: choose the Region tool (Edit ▸ Draw Region) and click its corners, or type "
              "them as x, y in the coordinate field.");
}

}  // namespace mcdda::gui
