#include "results/PvdFile.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QXmlStreamReader>

namespace mcdda::gui {

std::vector<PvdEntry> read_pvd(const QString& path, QString* error)
{
    auto fail = [error](const QString& why) {
        if (error != nullptr) *error = why;
        return std::vector<PvdEntry>{};
    };
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(QCoreApplication::translate("PvdFile", "cannot read %1: %2").arg(path, file.errorString()));
    const QDir folder = QFileInfo(path).absoluteDir();
    std::vector<PvdEntry> entries;
    bool collection = false;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) continue;
        if (xml.name() == QLatin1String("Collection")) collection = true;
        if (xml.name() != QLatin1String("DataSet")) continue;
        const auto attributes = xml.attributes();
        PvdEntry e;
        e.time = attributes.value(QLatin1String("timestep")).toDouble();
        e.file = folder.absoluteFilePath(attributes.value(QLatin1String("file")).toString());
        entries.push_back(e);
    }
    if (xml.hasError())
        return fail(QCoreApplication::translate("PvdFile", "%1 is not a valid collection: %2").arg(path, xml.errorString()));
    if (!collection) return fail(QCoreApplication::translate("PvdFile", "%1 holds no collection").arg(path));
    return entries;
}

QString contacts_file_for(const QString& vtu_path)
{
    static const QRegularExpression step(QStringLiteral("_(\\d{6})\\.vtu$"));
    const QRegularExpressionMatch m = step.match(vtu_path);
    if (!m.hasMatch()) return {};
    QString contacts = vtu_path;
    contacts.replace(m.capturedStart(), m.capturedLength(), QStringLiteral("_contacts_%1.vtp").arg(m.captured(1)));
    return QFileInfo::exists(contacts) ? contacts : QString();
}

}  // namespace mcdda::gui
