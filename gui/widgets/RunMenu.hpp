#pragma once
/// \file RunMenu.hpp
/// Run: Mesh (Ctrl+M), Run (F5), Pause/Resume, Stop (Shift+F5) and the results folder, and the
/// Run toolbar with the same actions. Which are enabled follows the window's state (update()).

#include <QMenu>

class QToolBar;

namespace mcdda::gui {

class RunMenu : public QMenu {
    Q_OBJECT

public:
    explicit RunMenu(QWidget* parent);

    /// A toolbar with Mesh, Run, Pause and Stop.
    QToolBar* createToolBar(QWidget* parent);
    /// Enables what the state allows; Pause reads Resume while paused.
    void update(bool can_mesh, bool can_run, bool running, bool paused);
    /// While a stop is on its way: neither Pause nor Stop.
    void stopping();

signals:
    void meshRequested();
    void runRequested();
    void pauseToggled();
    void stopRequested();
    void folderRequested();

private:
    QAction* mesh_ = nullptr;
    QAction* run_ = nullptr;
    QAction* pause_ = nullptr;
    QAction* stop_ = nullptr;
};

}  // namespace mcdda::gui
