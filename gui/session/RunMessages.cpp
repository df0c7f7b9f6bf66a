#include "session/RunMessages.hpp"

#include "session/DiagnosticText.hpp"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>

#include <algorithm>

namespace mcdda::gui {

namespace {



bool is_error(const Diagnostic& d) { return d.severity == Diagnostic::Severity::Error; }

}  // namespace

QStringList preprocess_report(const Preprocessed& p, const QString& source)
{
    QStringList lines;
    lines << QCoreApplication::translate("mcdda::gui::RunMessages", "Model: %1").arg(source);
    for (const Diagnostic& d : p.diagnostics) lines << diagnostic_line(p.model, d);
    if (p.ok) {
        lines << mesh_report(p.statistics);
        lines << QCoreApplication::translate("mcdda::gui::RunMessages", "Times: read %1 ms, checked %2 ms, cut %3 ms, meshed %4 ms")
                     .arg(1e3 * p.seconds_read, 0, 'f', 0)
                     .arg(1e3 * p.seconds_validate, 0, 'f', 0)
                     .arg(1e3 * p.seconds_cut, 0, 'f', 0)
                     .arg(1e3 * p.seconds_mesh, 0, 'f', 0);
    }
    return lines;
}

QString mesh_report(const MeshStatistics& s)
{
    const QLocale locale;  // decimal comma in German
    auto number = [&](double v) { return locale.toString(v, 'g', 4); };
    QStringList histogram;
    for (int k = 0; k < 6; ++k)
        histogram << (k < 5 ? QStringLiteral("%1–%2°: %3").arg(10 * k).arg(10 * k + 10) : QStringLiteral("50+°: %3"))
                         .arg(s.min_angle_histogram[k]);
    return QCoreApplication::translate("mcdda::gui::RunMessages", "%1 blocks, %2 nodes, %3 triangles")
               .arg(s.blocks)
               .arg(s.nodes)
               .arg(s.elements) +
           QLatin1Char('\n') +
           QCoreApplication::translate("mcdda::gui::RunMessages", "angles: smallest %1°, largest %2°")
               .arg(number(s.min_angle_deg), number(s.max_angle_deg)) +
           QLatin1Char('\n') +
           QCoreApplication::translate("mcdda::gui::RunMessages", "areas: smallest %1 m², largest %2 m², total %3 m²")
               .arg(number(s.min_area), number(s.max_area), number(s.total_area)) +
           QLatin1Char('\n') +
           QCoreApplication::translate("mcdda::gui::RunMessages", "sharpest block corner: %1°").arg(number(s.min_input_angle_deg)) +
           QLatin1Char('\n') +
           QCoreApplication::translate("mcdda::gui::RunMessages", "triangles by smallest angle: %1").arg(histogram.join(QStringLiteral(", ")));
}

QString permanent_displacement_line(const QString& summary_path)
{
    QFile file(summary_path);
    if (!file.open(QIODevice::ReadOnly)) return QString();
    const QJsonObject summary = QJsonDocument::fromJson(file.readAll()).object();
    const QJsonObject p = summary.value(QStringLiteral("permanent_displacement")).toObject();
    if (p.isEmpty()) return QString();
    auto mm = [](double metres) { return QLocale().toString(metres * 1e3, 'f', 1); };
    const QJsonArray at = p.value(QStringLiteral("at")).toArray();
    QString line = QCoreApplication::translate("mcdda::gui::RunMessages", "Permanent displacement (relative to the base): largest %1 mm at (%2, %3)")
                       .arg(mm(p.value(QStringLiteral("largest")).toDouble()),
                            QLocale().toString(at.at(0).toDouble(), 'g', 4), QLocale().toString(at.at(1).toDouble(), 'g', 4));
    const QJsonObject points = p.value(QStringLiteral("points")).toObject();
    for (auto it = points.begin(); it != points.end(); ++it) {
        const QJsonArray u = it.value().toArray();
        line += QCoreApplication::translate("mcdda::gui::RunMessages", "; %1: ux %2 mm, uy %3 mm")
                    .arg(it.key(), mm(u.at(0).toDouble()), mm(u.at(1).toDouble()));
    }
    return line;
}

QString mesh_summary(const Preprocessed& p)
{
    if (!p.ok) {
        // An empty model is not in error: it asks for its first region (a file that could not be
        // read has errors of its own and says so).
        const bool empty = std::all_of(p.diagnostics.begin(), p.diagnostics.end(), [&](const Diagnostic& d) {
            return !is_error(d) || is_empty_model_notice(p.model, d);
        });
        if (empty && p.model.regions.empty())
            return QCoreApplication::translate("mcdda::gui::RunMessages", "Draw a region to start");
        const int errors = static_cast<int>(std::count_if(p.diagnostics.begin(), p.diagnostics.end(), is_error));
        return QCoreApplication::translate("mcdda::gui::RunMessages", "Not meshed: %n error(s)", "", errors);
    }
    const MeshStatistics& s = p.statistics;
    return QCoreApplication::translate("mcdda::gui::RunMessages", "%1 blocks, %2 nodes, %3 elements, smallest angle %4°")
        .arg(s.blocks)
        .arg(s.nodes)
        .arg(s.elements)
        .arg(QLocale().toString(s.min_angle_deg, 'f', 1));
}

QStringList error_lines(const Preprocessed& p)
{
    QStringList errors;
    for (const Diagnostic& d : p.diagnostics)
        if (is_error(d)) errors << diagnostic_line(p.model, d);
    if (errors.isEmpty())
        errors << QCoreApplication::translate("mcdda::gui::RunMessages", "pre-processing stopped without a message");
    return errors;
}

QString first_lines(const QStringList& lines, int count)
{
    QString text = QStringList(lines.mid(0, count)).join(QLatin1Char('\n'));
    if (lines.size() > count)
        text += QLatin1Char('\n') +
                QCoreApplication::translate("mcdda::gui::RunMessages", "... and %n more", "", int(lines.size() - count));
    return text;
}

QString progress_line(const RunProgress& p)
{
    if (p.load_steps)  // static DDA: load steps, their Δt a numerical setting (Advanced), not time
        return QCoreApplication::translate("mcdda::gui::RunMessages", "load step %1/%2  contacts open/sliding/locked %3/%4/%5  "
                                                                      "plastic iterations %6  yielding %7")
            .arg(p.step)
            .arg(p.total_steps)
            .arg(p.open)
            .arg(p.sliding)
            .arg(p.locked)
            .arg(p.plastic_iterations)
            .arg(p.yielding);
    return QCoreApplication::translate("mcdda::gui::RunMessages", "step %1/%2  t = %3 s  dt = %4 s  contacts open/sliding/locked %5/%6/%7  "
                                                "plastic iterations %8  yielding %9")
        .arg(p.step)
        .arg(p.total_steps)
        .arg(QLocale().toString(p.time, 'g', 6))
        .arg(QLocale().toString(p.time_step, 'g', 4))
        .arg(p.open)
        .arg(p.sliding)
        .arg(p.locked)
        .arg(p.plastic_iterations)
        .arg(p.yielding);
}

QString iteration_line(const IterationInfo& info)
{
    return QCoreApplication::translate(
               "mcdda::gui::RunMessages", "Step %1: equilibrium iteration %2, out-of-balance %3 (tolerance %4), %n point(s) yielding", "",
               info.yielding)
        .arg(info.step)
        .arg(info.iteration)
        .arg(info.out_of_balance, 0, 'e', 2)
        .arg(info.tolerance, 0, 'e', 0);
}

QString trial_start_line(int number, double factor)
{
    return QCoreApplication::translate("mcdda::gui::RunMessages", "Strength reduction: trial %1, strengths divided by %2...")
        .arg(number)
        .arg(QLocale().toString(factor, 'f', 4));
}

QString trial_line(const StrengthTrial& trial)
{
    const QString numbers = QCoreApplication::translate("mcdda::gui::RunMessages",
                                                        "largest displacement %1 m, %n iteration(s), %2 s", "",
                                                        trial.iterations)
                                .arg(QLocale().toString(trial.max_displacement, 'g', 4))
                                .arg(QLocale().toString(trial.seconds, 'f', 1));
    if (trial.stands)
        return QCoreApplication::translate("mcdda::gui::RunMessages", "Trial %1: F = %2 stands (%3)")
            .arg(trial.number)
            .arg(QLocale().toString(trial.factor, 'f', 4))
            .arg(numbers);
    return QCoreApplication::translate("mcdda::gui::RunMessages", "Trial %1: F = %2 does not stand (%3): %4")
        .arg(trial.number)
        .arg(QLocale().toString(trial.factor, 'f', 4))
        .arg(numbers, QString::fromStdString(trial.message));
}

QString factor_text(const FactorOfSafety& factor)
{
    if (factor.found) return QLocale().toString(factor.value, 'f', 3);
    if (factor.converged > 0.0 && factor.not_converged == 0.0)
        return QCoreApplication::translate("mcdda::gui::RunMessages", "above %1").arg(QLocale().toString(factor.converged, 'f', 3));
    if (factor.not_converged > 0.0 && factor.converged == 0.0)
        return QCoreApplication::translate("mcdda::gui::RunMessages", "below %1").arg(QLocale().toString(factor.not_converged, 'f', 3));
    if (factor.converged > 0.0)
        return QCoreApplication::translate("mcdda::gui::RunMessages", "between %1 and %2")
            .arg(QLocale().toString(factor.converged, 'f', 3))
            .arg(QLocale().toString(factor.not_converged, 'f', 3));
    return QCoreApplication::translate("mcdda::gui::RunMessages", "not found");
}

QString factor_line(const FactorOfSafety& factor)
{
    if (!factor.found)
        return QCoreApplication::translate("mcdda::gui::RunMessages", "Factor of safety %1 (%n trial(s)).", "", factor.trials)
            .arg(factor_text(factor));
    return QCoreApplication::translate("mcdda::gui::RunMessages",
                                       "Factor of safety %1: the model stands with its strengths divided by %2, not by "
                                       "%3 (%n trial(s)).", "", factor.trials)
        .arg(factor_text(factor))
        .arg(QLocale().toString(factor.converged, 'f', 4))
        .arg(QLocale().toString(factor.not_converged, 'f', 4));
}

QString end_line(RunStatus status, int step, const QString& message)
{
    switch (status) {
        case RunStatus::Completed: return QCoreApplication::translate("mcdda::gui::RunMessages", "Run completed: %n step(s).", "", step);
        case RunStatus::Unbalanced: {
            // The solver's message says "not in equilibrium: ..." itself: said once, translated.
            const QString prefix = QStringLiteral("not in equilibrium: ");
            const QString why = message.startsWith(prefix) ? message.mid(prefix.size()) : message;
            return QCoreApplication::translate("mcdda::gui::RunMessages", "Run ended but the model is not in equilibrium: %1").arg(why);
        }
        case RunStatus::Cancelled: return QCoreApplication::translate("mcdda::gui::RunMessages", "Run stopped after step %1.").arg(step);
        case RunStatus::Collapsed: return QCoreApplication::translate("mcdda::gui::RunMessages", "The model collapsed: %1").arg(message);
        default: return QCoreApplication::translate("mcdda::gui::RunMessages", "The run failed: %1").arg(message);
    }
}

}  // namespace mcdda::gui
