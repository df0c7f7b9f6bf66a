#include "results/ExportMenu.hpp"

#include "results/ResultExport.hpp"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>

namespace mcdda::gui {

ExportMenu::ExportMenu(std::function<QImage()> grab, std::function<QString()> pvd, std::function<QString()> history,
                       QWidget* parent)
    : QMenu(tr("&Export"), parent), grab_(std::move(grab)), pvd_(std::move(pvd)), history_(std::move(history))
{
    QAction* png = addAction(tr("&Picture (PNG)..."), this, [this] {
        const QString path =
            QFileDialog::getSaveFileName(parentWidget(), tr("Export picture"), suggestedPicturePath(), tr("PNG pictures (*.png)"));
        if (!path.isEmpty())
            exportPng(path.endsWith(QStringLiteral(".png"), Qt::CaseInsensitive) ? path : path + QStringLiteral(".png"));
    });
    png->setObjectName(QStringLiteral("exportPngAction"));
    png->setStatusTip(tr("Save the picture of the view as a PNG file"));
    QAction* steps = addAction(tr("Saved &Steps (PVD/VTU)..."), this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(parentWidget(), tr("Export saved steps to"), start_folder_);
        if (!folder.isEmpty()) exportSteps(folder);
    });
    steps->setObjectName(QStringLiteral("exportStepsAction"));
    steps->setStatusTip(tr("Copy the run's .pvd collection and its .vtu steps to a folder"));
    QAction* history_action = addAction(tr("&History (CSV)..."), this, [this] {
        const QString path =
            QFileDialog::getSaveFileName(parentWidget(), tr("Export history"), suggestedHistoryPath(), tr("CSV files (*.csv)"));
        if (!path.isEmpty()) exportHistory(path);
    });
    history_action->setObjectName(QStringLiteral("exportHistoryAction"));
    history_action->setStatusTip(tr("Copy the run's history of loads and measured displacements"));
}

void ExportMenu::setSuggestion(std::function<QString()> stem, std::function<QString()> shown,
                               std::function<QString()> folder)
{
    stem_ = std::move(stem);
    shown_ = std::move(shown);
    folder_ = std::move(folder);
}

namespace {

QString in_folder(const QString& folder, const QString& name)
{
    return QDir(folder.isEmpty() ? QDir::homePath() : folder).absoluteFilePath(name);
}

}  // namespace

QString ExportMenu::suggestedPicturePath() const
{
    QString name = stem_ ? stem_() : QString();
    if (name.isEmpty()) name = QStringLiteral("model");
    if (const QString shown = shown_ ? shown_() : QString(); !shown.isEmpty()) name += QLatin1Char('-') + shown;
    return in_folder(folder_ ? folder_() : start_folder_, name + QStringLiteral(".png"));
}

QString ExportMenu::suggestedHistoryPath() const
{
    QString name = stem_ ? stem_() : QString();
    if (name.isEmpty()) name = QStringLiteral("model");
    return in_folder(folder_ ? folder_() : start_folder_, name + QStringLiteral("-history.csv"));
}

bool ExportMenu::exportPng(const QString& path)
{
    QString error;
    if (!export_png(grab_(), path, error)) {
        emit failed(error);
        return false;
    }
    emit exported(tr("Saved %1").arg(path));
    return true;
}

bool ExportMenu::exportSteps(const QString& folder)
{
    const QString pvd = pvd_();
    if (pvd.isEmpty() || !QFileInfo::exists(pvd)) {
        emit failed(tr("There are no saved steps yet: run the model first."));
        return false;
    }
    QString error;
    int copied = 0;
    if (!export_steps(pvd, folder, error, &copied)) {
        emit failed(error);
        return false;
    }
    emit exported(tr("Copied %n file(s) to %1", "", copied).arg(folder));
    return true;
}

bool ExportMenu::exportHistory(const QString& path)
{
    const QString history = history_();
    if (history.isEmpty() || !QFileInfo::exists(history)) {
        emit failed(tr("There is no history yet: run the model first."));
        return false;
    }
    QString error;
    if (!export_file(history, path, error)) {
        emit failed(error);
        return false;
    }
    emit exported(tr("Saved %1").arg(path));
    return true;
}

}  // namespace mcdda::gui
