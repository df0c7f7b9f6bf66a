#pragma once
/// \file RecentFilesMenu.hpp
/// File ▸ Recent Files: the last model files opened or saved, newest first, kept in the
/// program's settings (QSettings) between sessions.

#include <QMenu>
#include <QStringList>

namespace mcdda::gui {

class RecentFilesMenu : public QMenu {
    Q_OBJECT

public:
    explicit RecentFilesMenu(QWidget* parent = nullptr);

    /// The list, newest first (absolute paths).
    static QStringList files();
    /// Puts `path` first (once) and keeps the newest eight.
    void add(const QString& path);

signals:
    void fileChosen(const QString& path);

private:
    void rebuild();
};

}  // namespace mcdda::gui
