#include "results/ResultExport.hpp"

#include "results/PvdFile.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>

namespace mcdda::gui {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("ResultExport", text); }

}  // namespace

bool export_png(const QImage& image, const QString& path, QString& error)
{
    if (image.isNull()) {
        error = tr("There is no picture to save.");
        return false;
    }
    QSaveFile file(path);  // a temporary file, renamed to `path` by commit()
    if (!file.open(QIODevice::WriteOnly)) {
        error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    QImageWriter writer(&file, "png");
    if (!writer.write(image)) {
        error = tr("Cannot write %1: %2").arg(path, writer.errorString());
        file.cancelWriting();
        return false;
    }
    if (!file.commit()) {
        error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool export_file(const QString& source, const QString& target, QString& error)
{
    QFile in(source);
    if (!in.open(QIODevice::ReadOnly)) {
        error = tr("Cannot read %1: %2").arg(source, in.errorString());
        return false;
    }
    if (QFileInfo(source).absoluteFilePath() == QFileInfo(target).absoluteFilePath()) return true;
    QSaveFile out(target);
    if (!out.open(QIODevice::WriteOnly)) {
        error = tr("Cannot write %1: %2").arg(target, out.errorString());
        return false;
    }
    while (!in.atEnd()) {
        const QByteArray chunk = in.read(1 << 20);
        if (chunk.isEmpty() && in.error() != QFileDevice::NoError) {
            error = tr("Cannot read %1: %2").arg(source, in.errorString());
            out.cancelWriting();
            return false;
        }
        if (out.write(chunk) != chunk.size()) break;
    }
    if (!out.commit()) {
        error = tr("Cannot write %1: %2").arg(target, out.errorString());
        return false;
    }
    return true;
}

bool export_steps(const QString& pvd_path, const QString& target, QString& error, int* copied)
{
    if (copied != nullptr) *copied = 0;
    QString why;
    const std::vector<PvdEntry> entries = read_pvd(pvd_path, &why);
    if (entries.empty()) {
        error = why.isEmpty() ? tr("%1 lists no saved steps.").arg(pvd_path) : why;
        return false;
    }
    QDir folder(target);
    if (!folder.mkpath(QStringLiteral("."))) {
        error = tr("Cannot create the folder %1.").arg(target);
        return false;
    }
    const QDir source_folder = QFileInfo(pvd_path).absoluteDir();
    // The steps first, the collection that lists them last.
    for (const PvdEntry& e : entries) {
        const QString relative = source_folder.relativeFilePath(e.file);
        const QString destination = folder.absoluteFilePath(relative);
        QDir().mkpath(QFileInfo(destination).absolutePath());
        if (!export_file(e.file, destination, error)) return false;
        if (copied != nullptr) ++*copied;
    }
    if (!export_file(pvd_path, folder.absoluteFilePath(QFileInfo(pvd_path).fileName()), error)) return false;
    if (copied != nullptr) ++*copied;
    return true;
}

}  // namespace mcdda::gui
