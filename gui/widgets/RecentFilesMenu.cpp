#include "widgets/RecentFilesMenu.hpp"

#include <QFileInfo>
#include <QSettings>

namespace mcdda::gui {

namespace {

constexpr int max_recent_files = 8;
const char* const recent_key = "recentFiles";

}  // namespace

RecentFilesMenu::RecentFilesMenu(QWidget* parent) : QMenu(tr("Recent &Files"), parent)
{
    setObjectName(QStringLiteral("recentMenu"));
    rebuild();
}

QStringList RecentFilesMenu::files() { return QSettings().value(QString::fromLatin1(recent_key)).toStringList(); }

void RecentFilesMenu::add(const QString& path)
{
    QStringList list = files();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    list.removeAll(absolute);
    list.prepend(absolute);
    while (list.size() > max_recent_files) list.removeLast();
    QSettings().setValue(QString::fromLatin1(recent_key), list);
    rebuild();
}

void RecentFilesMenu::rebuild()
{
    clear();
    const QStringList list = files();
    for (int i = 0; i < list.size(); ++i) {
        const QString path = list[i];
        QAction* action = addAction(tr("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()), this,
                                    [this, path] { emit fileChosen(path); });
        action->setStatusTip(path);
    }
    setEnabled(!list.isEmpty());
}

}  // namespace mcdda::gui
