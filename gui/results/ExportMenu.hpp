#pragma once
/// \file ExportMenu.hpp
/// File ▸ Export: the picture of the view as PNG, the last run's saved steps (.pvd with its
/// .vtu files) and its history (CSV). Each action asks for a file or folder; the export*
/// functions do the same without asking.

#include <QMenu>
#include <QString>

#include <functional>

class QImage;

namespace mcdda::gui {

class ExportMenu : public QMenu {
    Q_OBJECT

public:
    /// `grab` draws the picture to export; `pvd` and `history` give the last run's files
    /// (empty before a run).
    ExportMenu(std::function<QImage()> grab, std::function<QString()> pvd, std::function<QString()> history,
               QWidget* parent);

    /// The folder the file dialogs start in.
    void setStartFolder(const QString& folder) { start_folder_ = folder; }
    /// The model's name ("tunnel"), what the picture shows ("stress_1-step10"; empty for the
    /// model) and the folder to suggest; asked each time a dialog opens.
    void setSuggestion(std::function<QString()> stem, std::function<QString()> shown, std::function<QString()> folder);
    /// The paths the dialogs start with: a name from the model and the field, never blank.
    QString suggestedPicturePath() const;
    QString suggestedHistoryPath() const;

    bool exportPng(const QString& path);
    bool exportSteps(const QString& folder);
    bool exportHistory(const QString& path);

signals:
    /// Something was written; `message` names it.
    void exported(const QString& message);
    /// Nothing was written; `message` says why.
    void failed(const QString& message);

private:
    std::function<QImage()> grab_;
    std::function<QString()> pvd_;
    std::function<QString()> history_;
    QString start_folder_;
    std::function<QString()> stem_;
    std::function<QString()> shown_;
    std::function<QString()> folder_;
};

}  // namespace mcdda::gui
