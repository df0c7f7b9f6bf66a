#include "results/HistoryCsv.hpp"

#include <QCoreApplication>
#include <QFile>
#include <QTextStream>

#include <limits>

namespace mcdda::gui {

bool read_history(const QString& path, HistoryTable& table, QString* error)
{
    table = {};
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        if (error != nullptr)
            *error = QCoreApplication::translate("HistoryCsv", "cannot read %1: %2").arg(path, file.errorString());
        return false;
    }
    QTextStream in(&file);
    bool header = true;
    while (!in.atEnd()) {
        const QString line = in.readLine().trimmed();
        if (line.isEmpty()) continue;
        const QStringList cells = line.split(QLatin1Char(','));
        if (header) {
            table.columns = cells;
            header = false;
            continue;
        }
        if (cells.size() != table.columns.size()) continue;
        // A cell of words (a strength reduction trial's status) is NaN; a row with no number at
        // all is not a row.
        std::vector<double> row;
        row.reserve(cells.size());
        bool any = false;
        for (const QString& c : cells) {
            bool ok = false;
            const double v = c.toDouble(&ok);
            row.push_back(ok ? v : std::numeric_limits<double>::quiet_NaN());
            any = any || ok;
        }
        if (any) table.rows.push_back(std::move(row));
    }
    if (header) {
        if (error != nullptr) *error = QCoreApplication::translate("HistoryCsv", "%1 is empty").arg(path);
        return false;
    }
    return true;
}

}  // namespace mcdda::gui
