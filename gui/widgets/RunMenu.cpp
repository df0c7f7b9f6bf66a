#include "widgets/RunMenu.hpp"

#include <QIcon>
#include <QKeySequence>
#include <QToolBar>

namespace mcdda::gui {

RunMenu::RunMenu(QWidget* parent) : QMenu(tr("&Run"), parent)
{
    auto action = [&](const QString& text, void (RunMenu::*signal)(), const QString& name, const QString& icon,
                      const QString& tip) {
        QAction* a = addAction(text, this, signal);
        a->setObjectName(name);
        a->setIcon(QIcon(icon));
        a->setStatusTip(tip);
        return a;
    };
    mesh_ = action(tr("&Mesh"), &RunMenu::meshRequested, QStringLiteral("meshAction"), QStringLiteral(":/icons/mesh.svg"),
                   tr("Cut the blocks and mesh them in the background (edits do this by themselves); "
                      "the statistics go to the status bar and the Messages dock"));
    mesh_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    run_ = action(tr("&Run"), &RunMenu::runRequested, QStringLiteral("runAction"), QStringLiteral(":/icons/run.svg"),
                  tr("Analyse the model; the picture follows the run"));
    run_->setShortcut(QKeySequence(Qt::Key_F5));
    pause_ = action(tr("&Pause"), &RunMenu::pauseToggled, QStringLiteral("pauseAction"),
                    QStringLiteral(":/icons/pause.svg"), tr("Pause or resume the run"));
    stop_ = action(tr("&Stop"), &RunMenu::stopRequested, QStringLiteral("stopAction"), QStringLiteral(":/icons/stop.svg"),
                   tr("Stop the run after the current step; the results so far are kept"));
    stop_->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    addSeparator();
    addAction(tr("Results &Folder..."), this, &RunMenu::folderRequested)
        ->setStatusTip(tr("Choose where runs write their files"));
}

QToolBar* RunMenu::createToolBar(QWidget* parent)
{
    auto* bar = new QToolBar(tr("Run"), parent);
    bar->setObjectName(QStringLiteral("run"));
    bar->addActions({mesh_, run_, pause_, stop_});
    return bar;
}

void RunMenu::update(bool can_mesh, bool can_run, bool running, bool paused)
{
    mesh_->setEnabled(can_mesh);
    run_->setEnabled(can_run);
    pause_->setEnabled(running);
    pause_->setText(paused ? tr("Res&ume") : tr("&Pause"));
    stop_->setEnabled(running);
}

void RunMenu::stopping()
{
    pause_->setEnabled(false);
    stop_->setEnabled(false);
}

}  // namespace mcdda::gui
