#include "MainWindow.hpp"

#include "dialogs/DxfImportDialog.hpp"
#include "dialogs/HelpMenu.hpp"
#include "document/ModelDocument.hpp"
#include "model/Defaults.hpp"
#include "panels/EarthquakePanel.hpp"
#include "panels/PropertyEditor.hpp"
#include "panels/StagesPanel.hpp"
#include "results/ExportMenu.hpp"
#include "results/HistoryPlot.hpp"
#include "results/PvdFile.hpp"
#include "results/QueryPlot.hpp"
#include "results/UnbalancedPlot.hpp"
#include "results/StepSlider.hpp"
#include "session/PreprocessScheduler.hpp"
#include "session/RunMessages.hpp"
#include "session/RunSession.hpp"
#include "run/StrengthReduction.hpp"
#include "tools/EditingTools.hpp"
#include "widgets/ModelTree.hpp"
#include "widgets/ModelView.hpp"
#include "widgets/MessageLog.hpp"
#include "widgets/RecentFilesMenu.hpp"
#include "widgets/ResultToolBar.hpp"
#include "widgets/RunMenu.hpp"
#include "widgets/ViewMenu.hpp"
#include "widgets/WindowStatusBar.hpp"

#include <QAction>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QIcon>
#include <QKeySequence>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>
#include <QUrl>

#include <algorithm>

namespace mcdda::gui {

namespace {

bool is_model_file(const QUrl& url)
{
    return url.isLocalFile() && url.toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive);
}

/// A message box that does not block: the program and its tests keep running.
void show_box(QWidget* parent, QMessageBox::Icon icon, const QString& title, const QString& text,
              const QString& informative = {}, const QString& details = {})
{
    auto* box = new QMessageBox(icon, title, text, QMessageBox::Ok, parent);
    if (!informative.isEmpty()) box->setInformativeText(informative);
    if (!details.isEmpty()) box->setDetailedText(details);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    view_ = new ModelView(this);
    setCentralWidget(view_);
    document_ = new ModelDocument(this);
    scheduler_ = new PreprocessScheduler(this);
    connect(scheduler_, &PreprocessScheduler::ready, this, [this](std::shared_ptr<const Preprocessed> p) {
        const QString source = document_->path().isEmpty() ? tr("Untitled") : document_->path();
        showScene(std::move(p), source, true, false);
    });
    connect(scheduler_, &PreprocessScheduler::busyChanged, this, [this](bool busy) {
        statusBar()->showMessage(busy ? tr("Pre-processing...") : QString());
        updateRunActions();
    });
    session_ = new RunSession(this);
    connectRunSession();
    editing_ = new EditingTools(this, view_, document_);
    connect(editing_, &EditingTools::message, this, &MainWindow::log);
    connect(editing_, &EditingTools::selectionChanged, this, &MainWindow::onSelectionChanged);
    createDocks();
    createActions();
    createRunActions();
    status_bar_ = new WindowStatusBar(this);
    setStatusBar(status_bar_);
    setAcceptDrops(true);
    setWindowTitle(tr("mcdda"));
    resize(1100, 750);
    connect(view_, &ModelView::cursorMoved, this, &MainWindow::showCursor);
    connect(view_, &ModelView::cursorLeft, status_bar_, &WindowStatusBar::clearCursor);
    connect(document_, &ModelDocument::changed, this, &MainWindow::onDocumentChanged);
    connect(document_, &ModelDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(document_, &ModelDocument::pathChanged, this, &MainWindow::updateTitle);
    applySnap();
    refreshModelTree();
}

MainWindow::~MainWindow() { session_->abandon(); scheduler_->drop(); }

void MainWindow::createDocks()
{
    messages_ = new MessageLog(this);
    messages_dock_ = addDock(tr("Messages"), QStringLiteral("messages"), messages_, Qt::BottomDockWidgetArea);
    resizeDocks({messages_dock_}, {messages_->preferredHeight()}, Qt::Vertical);  // the model keeps the height

    tree_ = new ModelTree(this);
    connect(tree_, &ModelTree::itemChosen, this, [this](const ItemRef& ref) { if (ref.valid()) selectItem(ref); });
    model_dock_ = addDock(tr("Model"), QStringLiteral("model"), tree_, Qt::RightDockWidgetArea);

    steps_ = new StepSlider(this);
    steps_dock_ = addDock(tr("Steps"), QStringLiteral("steps"), steps_, Qt::BottomDockWidgetArea);
    connect(steps_, &StepSlider::stepChosen, this, &MainWindow::showStep);

    query_ = new QueryPlot(this);
    query_dock_ = addDock(tr("Query"), QStringLiteral("query"), query_, Qt::BottomDockWidgetArea, steps_dock_);
    connect(editing_, &EditingTools::queryLineDrawn, this, [this](const Point2& from, const Point2& to) {
        query_->setLine(from, to);
        query_->setFileStem(modelStem());
        query_->refresh(view_->resultProbe());
        view_->setQueryLine(from, to);  // seen on the picture, not only in the plot
        query_dock_->raise();
    });

    plot_ = new HistoryPlot(this);
    plot_dock_ = addDock(tr("Plots"), QStringLiteral("plots"), plot_, Qt::RightDockWidgetArea, model_dock_);
    resizeDocks({plot_dock_}, {320}, Qt::Horizontal);  // the view keeps its width
    auto* stages = new StagesPanel(document_, view_, this);
    stages_dock_ = addDock(tr("Stages"), QStringLiteral("stages"), stages, Qt::RightDockWidgetArea, model_dock_);
    // The stage's Draw button: the Water Table tool draws the water of the stage shown.
    connect(stages, &StagesPanel::drawWaterRequested, editing_, &EditingTools::useWaterTable);
    earthquake_ = new EarthquakePanel(document_, this);
    earthquake_dock_ = addDock(tr("Earthquake"), QStringLiteral("earthquake"), earthquake_, Qt::RightDockWidgetArea,
                               model_dock_);
    connect(earthquake_, &EarthquakePanel::message, this, &MainWindow::log);
    connect(earthquake_, &EarthquakePanel::drawBaseRequested, editing_, &EditingTools::useCompliantBase);
    property_editor_ = new PropertyEditor(document_, this);
    property_dock_ = addDock(tr("Properties"), QStringLiteral("properties"), property_editor_, Qt::RightDockWidgetArea,
                             model_dock_);
}

QDockWidget* MainWindow::addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area,
                                 QDockWidget* tab_of)
{
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    if (tab_of) {  // a tab behind `tab_of`, which stays in front
        tabifyDockWidget(tab_of, dock);
        tab_of->raise();
    }
    return dock;
}

void MainWindow::createActions()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* new_action = file->addAction(tr("&New"), this, &MainWindow::newModel);
    new_action->setObjectName(QStringLiteral("newAction"));
    new_action->setShortcut(QKeySequence::New);
    new_action->setStatusTip(tr("Start an empty model"));
    QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::openDialog);
    open->setShortcut(QKeySequence::Open);
    open->setIcon(QIcon(QStringLiteral(":/icons/open.svg")));
    open->setStatusTip(tr("Open a model file (*.json)"));
    reload_action_ = file->addAction(tr("&Reload"), this, &MainWindow::reload);
    // Not QKeySequence::Refresh: that is F5, which runs the analysis (Run ▸ Run).
    reload_action_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    reload_action_->setStatusTip(tr("Read the model file again, e.g. after editing it"));
    reload_action_->setEnabled(false);
    recent_menu_ = new RecentFilesMenu(this);
    connect(recent_menu_, &RecentFilesMenu::fileChosen, this, [this](const QString& path) {
        if (maybeSave()) openModel(path);
    });
    file->addMenu(recent_menu_);
    file->addSeparator();
    QAction* save_action = file->addAction(tr("&Save"), this, &MainWindow::save);
    save_action->setObjectName(QStringLiteral("saveAction"));
    save_action->setShortcut(QKeySequence::Save);
    save_action->setIcon(QIcon(QStringLiteral(":/icons/save.svg")));
    save_action->setStatusTip(tr("Write the model to its file"));
    QAction* save_as = file->addAction(tr("Save &As..."), this, &MainWindow::saveAsDialog);
    save_as->setObjectName(QStringLiteral("saveAsAction"));
    save_as->setShortcut(QKeySequence::SaveAs);
    save_as->setStatusTip(tr("Write the model to a new file"));
    file->addSeparator();
    export_menu_ = new ExportMenu([this] { return view_->grabFrame(); }, [this] { return resultsPvdPath(); },
                                  [this] { return resultsHistoryPath(); }, this);
    // The dialogs suggest a name saying what was exported (they suggested none).
    export_menu_->setSuggestion([this] { return modelStem(); }, [this] { return shownResultName(); },
                                [this] {
                                    if (!resultsFolder().isEmpty()) return resultsFolder();
                                    return document_->path().isEmpty() ? last_folder_
                                                                       : QFileInfo(document_->path()).absolutePath();
                                });
    connect(export_menu_, &ExportMenu::failed, this, &MainWindow::reportExportError);
    connect(export_menu_, &ExportMenu::exported, this, [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    file->addMenu(export_menu_);
    file->addSeparator();
    file->addAction(tr("&Import DXF..."), this, [this] { importDxf(QString()); })->setObjectName(QStringLiteral("importDxfAction"));
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    editing_->createActions(edit);
    tree_->addAction(editing_->deleteAction());

    view_menu_ = new ViewMenu(view_, this);
    view_menu_->addDocks({model_dock_, stages_dock_, earthquake_dock_, messages_dock_, steps_dock_, query_dock_, plot_dock_,
                          property_dock_});
    connect(view_menu_, &ViewMenu::snappingChanged, this, &MainWindow::applySnap);
    menuBar()->addMenu(view_menu_);

    help_menu_ = create_help_menu(this);
    menuBar()->addMenu(help_menu_);
}

bool MainWindow::importDxf(const QString& path)
{
    const bool imported =
        import_dxf_into(this, document_, [this] { return maybeSave(); }, [this](const QString& line) { log(line); }, path);
    if (imported) {
        forgetQueryLine();
        forgetUntitledResults();
    }
    return imported;
}

QString MainWindow::modelStem() const
{
    return document_->path().isEmpty() ? session_->stem() : QFileInfo(document_->path()).completeBaseName();
}

QString MainWindow::shownResultName() const
{
    if (!view_->result() && view_->resultFile().isEmpty()) return QString();  // the model picture
    QString name = resultField();
    if (!view_->resultFile().isEmpty()) {
        // <stem>_000010.vtu: step 10.
        const QString number = QFileInfo(view_->resultFile()).completeBaseName().section(QLatin1Char('_'), -1);
        bool ok = false;
        const int step = number.toInt(&ok);
        if (ok) name += QStringLiteral("-step") + QString::number(step);
    } else if (view_->result()) {
        name += QStringLiteral("-step") + QString::number(view_->result()->step);
    }
    return name;
}

ExportMenu* MainWindow::exportMenu() const { return export_menu_; }

void MainWindow::forgetUntitledResults()
{
    // The temporary results folder was for the untitled model only.
    if (untitled_results_.isEmpty()) return;
    if (session_->outputFolder() == untitled_results_) session_->setOutputFolder(QString());
    untitled_results_.clear();
}

void MainWindow::forgetQueryLine()
{
    // A line drawn across another model means nothing here: neither plotted nor drawn.
    query_->clear();
    view_->clearQueryLine();
}

DrawTool* MainWindow::activeTool() const { return editing_->activeTool(); }
ItemRef MainWindow::selection() const { return editing_->selection(); }
void MainWindow::drawRegionTool() { editing_->useRegion(); }
void MainWindow::selectItem(const ItemRef& ref) { editing_->selectItem(ref); }
bool MainWindow::enterCoordinates(const QString& text) { return editing_->enterCoordinates(text); }

void MainWindow::onSelectionChanged(const ItemRef& ref)
{
    tree_->selectItem(ref);
    property_editor_->setSelection(ref);
    if (ref.valid())
        statusBar()->showMessage(tr("Selected %1: drag to move, Delete removes").arg(document_->itemName(ref)), 5000);
}

void MainWindow::setGridSpacing(double metres)
{
    if (metres > 0.0) grid_spacing_ = metres;
    applySnap();
}

void MainWindow::applySnap() { editing_->setSnapping(view_menu_->snapping(), grid_spacing_); }

void MainWindow::refreshModelTree() { tree_->refresh(document_->model(), view_->scene().get()); }

QStringList MainWindow::recentFiles() const { return RecentFilesMenu::files(); }

void MainWindow::updateTitle()
{
    setWindowTitle(tr("%1[*] - mcdda").arg(document_->displayName()));
    setWindowModified(document_->isModified());
}

bool MainWindow::maybeSave()
{
    if (!document_->isModified() || !ask_to_save_) return true;
    const auto answer = QMessageBox::warning(this, tr("Unsaved changes"),
                                             tr("The model has been modified. Save the changes?"),
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                             QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::newModel()
{
    if (!maybeSave()) return;
    setModelFile({});
    forgetQueryLine();
    document_->setModel(new_model(tr("rock").toStdString(), tr("joint").toStdString()));  // → an empty picture
    view_->showBox(-5.0, -5.0, 25.0, 20.0);
    log(tr("New model: draw regions with Edit ▸ Draw Region."));
}

void MainWindow::setModelFile(const QString& path)
{
    forgetUntitledResults();
    path_ = path;
    if (!path.isEmpty()) last_folder_ = QFileInfo(path).absolutePath();
    reload_action_->setEnabled(!path.isEmpty());
    setWindowFilePath(path);
    session_->setSourcePath(path);  // names the results folder
}

bool MainWindow::save()
{
    if (document_->path().isEmpty()) return saveAsDialog();
    return saveModelAs(document_->path());
}

bool MainWindow::saveAsDialog()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save model"), last_folder_, tr("Model files (*.json)"));
    if (path.isEmpty()) return false;
    if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) path += QStringLiteral(".json");
    return saveModelAs(path);
}

bool MainWindow::saveModelAs(const QString& path)
{
    QString error;
    if (!document_->saveAs(path, &error)) {
        reportExportError(error);
        return false;
    }
    setModelFile(path);
    recent_menu_->add(path);
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

void MainWindow::onDocumentChanged()
{
    editing_->documentChanged();
    refreshModelTree();
    updateTitle();
    if (syncing_)
        scheduler_->drop();  // the caller shows a picture itself; one still being made is dropped
    else
        scheduler_->request(document_->model());
    updateRunActions();
}

bool MainWindow::meshModel()
{
    if (isRunning() || loading_) return false;
    view_menu_->showMesh();  // what was asked for is seen
    if (!isPreprocessing()) scheduler_->request(document_->model());  // else a newer picture is on its way
    return true;
}

bool MainWindow::isPreprocessing() const { return scheduler_->isBusy(); }

bool MainWindow::exportPng(const QString& path) { return export_menu_->exportPng(path); }
bool MainWindow::exportSteps(const QString& folder) { return export_menu_->exportSteps(folder); }
bool MainWindow::exportHistory(const QString& path) { return export_menu_->exportHistory(path); }

void MainWindow::reportExportError(const QString& message)
{
    log(message);
    show_box(this, QMessageBox::Critical, tr("Export failed"), message);
}

QString MainWindow::resultsFolder() const { return session_->resultsFolder(); }
QString MainWindow::resultsPvdPath() const { return session_->resultsPvdPath(); }
QString MainWindow::resultsHistoryPath() const { return session_->resultsHistoryPath(); }

void MainWindow::showStep(const QString& vtu_path)
{
    // While running, an earlier saved step is looked at until the slider is back on the last
    // one, when the picture follows the run again.
    if (isRunning()) looking_back_ = steps_->currentIndex() + 1 < steps_->count();
    shown_step_ = isRunning() && !looking_back_ ? QString() : vtu_path;
    showResult();
}

QString MainWindow::messages() const { return messages_->toPlainText(); }
QString MainWindow::statisticsText() const { return status_bar_->statistics(); }
QString MainWindow::cursorText() const { return status_bar_->cursorText(); }

void MainWindow::showCursor(const QPointF& model_pos)
{
    status_bar_->showCursor(model_pos, view_->metresPerPixel(), view_->resultValueAt(model_pos));
}

void MainWindow::openDialog()
{
    if (!maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open model"), last_folder_,
                                                      tr("Model files (*.json);;All files (*)"));
    if (!path.isEmpty()) openModel(path);
}

void MainWindow::reload()
{
    if (!path_.isEmpty() && maybeSave()) load(path_, true);
}

bool MainWindow::openModel(const QString& path) { return load(path, false); }

bool MainWindow::load(const QString& path, bool keep_camera)
{
    if (loading_) return false;  // one file at a time
    loading_ = true;
    updateRunActions();
    status_bar_->showBusy(tr("Reading and meshing %1...").arg(QFileInfo(path).fileName()));
    // The window keeps painting meanwhile; input waits, so nothing changes the model under the
    // reader's feet.
    const std::shared_ptr<Preprocessed> result = PreprocessScheduler::readFile(path);
    status_bar_->hideBusy();
    loading_ = false;

    if (QFileInfo(path).absoluteFilePath() != QFileInfo(path_).absoluteFilePath() || path_.isEmpty())
        forgetQueryLine();  // another model (Reload keeps the line)
    setModelFile(path);
    syncing_ = true;
    if (has_errors(document_->open(path))) document_->setModel(result->model);  // what could be read, without a file
    syncing_ = false;
    if (document_->path() == path) recent_menu_->add(path);
    showScene(result, path, keep_camera, true);
    if (close_after_load_) QTimer::singleShot(0, this, &QWidget::close);
    return result->ok;
}

void MainWindow::showPreprocessed(std::shared_ptr<const Preprocessed> p, const QString& source, bool keep_camera)
{
    if (!p) return;
    forgetQueryLine();
    forgetUntitledResults();
    syncing_ = true;
    document_->setModel(p->model);  // edits start from it; saving asks for a file
    syncing_ = false;
    showScene(std::move(p), source, keep_camera, true);
}

void MainWindow::showScene(std::shared_ptr<const Preprocessed> p, const QString& source, bool keep_camera,
                           bool interactive)
{
    if (!p) return;
    if (isRunning()) {
        session_->abandon();
        status_bar_->hideProgress();
        log(interactive ? tr("The run was stopped: another model was opened.")
                        : tr("The run was stopped: the model was edited."));
    }
    session_->clearResults();
    status_bar_->setFactorOfSafety(QString());
    shown_step_.clear();
    looking_back_ = false;
    steps_->clear();
    plot_->clear();
    // A static model's steps are load steps: plots and labels count them, not seconds.
    const bool load_steps = !has_dynamic_stage(p->model);
    plot_->setLoadSteps(load_steps);
    steps_->setLoadSteps(load_steps);
    if (interactive) {
        setWindowFilePath(source);
        session_->setSourcePath(source);
    }
    updateTitle();
    messages_->setPlainText(preprocess_report(*p, source).join(QLatin1Char('\n')));
    status_bar_->setStatistics(mesh_summary(*p));
    const bool first_region = view_->scene() && view_->scene()->model.regions.empty() && !p->model.regions.empty();
    view_->setScene(std::move(p), keep_camera);
    if (result_bar_) result_bar_->setWaterResults(has_water(view_->scene()->model));  // the fields a run will have
    if (first_region) view_->ensureRegionsVisible();  // the view fits the first region drawn
    refreshModelTree();  // its blocks
    updateRunActions();
    if (!view_->scene()->ok && interactive) reportFailure(*view_->scene(), source);
}

void MainWindow::reportFailure(const Preprocessed& p, const QString& source)
{
    const QStringList errors = error_lines(p);
    show_box(this, QMessageBox::Critical, tr("Model not usable"),
             tr("%1 could not be pre-processed.").arg(QFileInfo(source).fileName()), first_lines(errors, 8),
             errors.join(QLatin1Char('\n')));
}

void MainWindow::createRunActions()
{
    run_menu_ = new RunMenu(this);
    menuBar()->insertMenu(help_menu_->menuAction(), run_menu_);  // Help stays last
    QToolBar* run_bar = run_menu_->createToolBar(this);
    addToolBar(run_bar);
    connect(run_menu_, &RunMenu::meshRequested, this, &MainWindow::meshModel);
    connect(run_menu_, &RunMenu::runRequested, this, &MainWindow::startRun);
    connect(run_menu_, &RunMenu::pauseToggled, this, &MainWindow::togglePause);
    connect(run_menu_, &RunMenu::stopRequested, this, &MainWindow::stopRun);
    connect(run_menu_, &RunMenu::folderRequested, this, [this] {
        const QString chosen = QFileDialog::getExistingDirectory(this, tr("Folder for the results"), runOutputFolder());
        if (!chosen.isEmpty()) setRunOutputFolder(chosen);
    });
    addToolBar(result_bar_ = new ResultToolBar(this));
    insertToolBarBreak(run_bar);  // Run and Results on a row of their own: never behind a chevron
    connect(result_bar_, &ResultToolBar::optionsChanged, this, &MainWindow::showResult);
    updateRunActions();
}

void MainWindow::updateRunActions()
{
    if (!run_menu_) return;  // during construction
    const auto scene = view_->scene();
    // Not on a stale picture: an edit's pre-processing must have finished.
    const bool can_run = !isRunning() && !loading_ && scene && scene->ok && !isPreprocessing();
    run_menu_->update(!isRunning() && !loading_, can_run, isRunning(), session_->isPaused());
}

bool MainWindow::isRunning() const { return session_->isRunning(); }
void MainWindow::setRunOutputFolder(const QString& folder) { session_->setOutputFolder(folder); }
QString MainWindow::runOutputFolder() const { return session_->runFolder(); }
void MainWindow::setRunThrottle(int progress_ms, int snapshot_ms) { session_->setThrottle(progress_ms, snapshot_ms); }
QString MainWindow::factorOfSafetyText() const { return status_bar_->factorOfSafety(); }
QString MainWindow::resultField() const { return result_bar_->shownField(); }
void MainWindow::setResultField(const QString& field) { result_bar_->setField(field); }
double MainWindow::deformFactor() const { return result_bar_->deformFactor(); }
void MainWindow::setDeformFactor(double factor) { result_bar_->setDeformFactor(factor); }

void MainWindow::log(const QString& line) { messages_->log(line); }

bool MainWindow::startRun()
{
    const auto scene = view_->scene();
    if (isRunning() || !scene || !scene->ok || isPreprocessing()) return false;
    if (!chooseUntitledResults()) return false;
    // Results are looked at with Select: a drawing tool's grid and snap marker would cover them.
    editing_->useSelect();
    return session_->start(*scene);
}

bool MainWindow::chooseUntitledResults()
{
    // A saved model's results go beside it, and a folder chosen with Run ▸ Results Folder is
    // the user's; an untitled model has neither, and its results once went silently into
    // whatever the current folder was.
    if (!document_->path().isEmpty()) return true;
    if (!session_->outputFolder().isEmpty() && session_->outputFolder() != untitled_results_) return true;
    if (!untitled_results_.isEmpty() && QFileInfo(untitled_results_).isDir()) return true;  // asked once per model
    if (ask_to_save_) {
        QMessageBox box(QMessageBox::Question, tr("Run an unsaved model"),
                        tr("The model has not been saved yet. Where should its results go?"), QMessageBox::Cancel, this);
        box.setInformativeText(tr("Save the model first to keep its results in a folder beside it "
                                  "(<model>-results), or run it now with the results in a new temporary folder."));
        QPushButton* save_first = box.addButton(tr("Save and Run..."), QMessageBox::AcceptRole);
        QPushButton* temporary = box.addButton(tr("Run in a Temporary Folder"), QMessageBox::DestructiveRole);
        box.setDefaultButton(save_first);
        box.exec();
        if (box.clickedButton() == save_first) return saveAsDialog();  // the results go beside the file
        if (box.clickedButton() != temporary) return false;
    }
    QTemporaryDir folder(QDir(QDir::tempPath()).filePath(QStringLiteral("mcdda-untitled-XXXXXX")));
    if (!folder.isValid()) {
        reportExportError(tr("No folder for the results: %1").arg(folder.errorString()));
        return false;
    }
    folder.setAutoRemove(false);  // the results stay after the program ends
    untitled_results_ = folder.path();
    session_->setOutputFolder(untitled_results_);
    const QString text = tr("The model is not saved: its results go to the new folder %1 "
                            "(File ▸ Save As keeps the model; its next run writes beside it).")
                             .arg(QDir::toNativeSeparators(untitled_results_));
    log(text);
    statusBar()->showMessage(text, 10000);
    return true;
}

void MainWindow::togglePause() { session_->togglePause(); }

void MainWindow::stopRun()
{
    if (!isRunning()) return;
    session_->stop();  // finished(Cancelled) follows
    run_menu_->stopping();
    log(tr("Stopping the run..."));
}

void MainWindow::connectRunSession()
{
    connect(session_, &RunSession::started, this, [this](int planned, const QString& folder) {
        shown_step_.clear();
        looking_back_ = false;
        steps_->clear();
        trials_ = 0;
        factor_found_ = false;
        status_bar_->setFactorOfSafety(QString());
        plot_->setTitle(QString());
        // A strength reduction's trials are as many as its search needs: a busy bar.
        const bool search = is_strength_reduction(view_->scene()->model);
        status_bar_->showProgress(search ? 0 : std::max(1, planned));
        plot_->unbalancedPlot()->setLimit(view_->scene()->model.analysis.equilibrium_ratio);
        log(tr("Run started: %n step(s); results in %1", "", planned).arg(folder));
        updateRunActions();
    });
    connect(session_, &RunSession::progress, this, [this](const RunProgress& p) {
        status_bar_->setProgress(p.step);
        log(progress_line(p));
        emit runProgressed(p);
    });
    connect(session_, &RunSession::iterating, this, [this](const IterationInfo& info) {
        // Between steps the progress bar moves; inside a long step this line does.
        statusBar()->showMessage(iteration_line(info), 5000);
        emit runIterating(info);
    });
    connect(session_, &RunSession::trialStarted, this, [this](double factor) {
        statusBar()->showMessage(trial_start_line(++trials_, factor));
    });
    connect(session_, &RunSession::trialFinished, this, [this](const StrengthTrial& trial) {
        log(trial_line(trial));
        plot_->load(QDir(session_->runFolder()).absoluteFilePath(QStringLiteral("history.csv")));  // the SSR graph grows
    });
    connect(session_, &RunSession::factorOfSafety, this, [this](const FactorOfSafety& factor) {
        factor_found_ = factor.found;
        status_bar_->setFactorOfSafety(factor_text(factor), factor_line(factor));
        log(factor_line(factor));
    });
    connect(session_, &RunSession::snapshot, this, [this] {
        if (looking_back_) return;
        shown_step_.clear();
        showResult();
    });
    // A live plot, and a Steps dock to look back with during the run.
    connect(session_, &RunSession::filesGrew, this, [this](const QString& pvd, const QString& history) {
        plot_->load(history);
        steps_->load(pvd, looking_back_);
    });
    connect(session_, &RunSession::pausedChanged, this, [this](bool paused) {
        log(paused ? tr("Run paused.") : tr("Run resumed."));
        updateRunActions();
    });
    connect(session_, &RunSession::finished, this, &MainWindow::onRunFinished);
}

void MainWindow::showResult()
{
    // A run of a model with ground water writes pore pressures and effective stresses (RunOutput).
    result_bar_->setWaterResults(view_->scene() && has_water(view_->scene()->model));
    view::ResultOptions options = result_bar_->options();
    if (!shown_step_.isEmpty() && (!isRunning() || looking_back_)) {
        if (result_bar_->showContacts()) options.contacts = contacts_file_for(shown_step_).toStdString();
        view_->setResultFile(shown_step_, options);
    }
    else if (session_->lastSnapshot())
        view_->setResult(session_->lastSnapshot(), options);
    query_->refresh(view_->resultProbe());  // the query line follows the picture
    result_bar_->showInfo(view_->resultInfo());
}

void MainWindow::onRunFinished(RunStatus status, const QString& message)
{
    looking_back_ = false;  // the picture goes to the last saved step below
    editing_->useSelect();  // a tool chosen during the run would draw its grid over the result
    status_bar_->hideProgress();
    const auto last = session_->lastSnapshot();
    const QString text = status == RunStatus::Completed && factor_found_
                             ? tr("Strength reduction completed: %1.").arg(status_bar_->factorOfSafety())
                             : end_line(status, last ? last->step : 0, message);
    log(text);
    // An earthquake's result in one line: what the shaking left, relative to the base.
    if (const QString permanent = permanent_displacement_line(QDir(session_->resultsFolder()).absoluteFilePath(
            QStringLiteral("summary.json")));
        !permanent.isEmpty())
        log(permanent);
    log(tr("Results in %1").arg(session_->resultsFolder()));
    plot_->load(resultsHistoryPath());
    if (!status_bar_->factorOfSafety().isEmpty()) plot_->setTitle(status_bar_->factorOfSafety());
    if (steps_->load(resultsPvdPath()) > 0) showStep(steps_->entries().back().file);  // with its contacts
    // A strength reduction that found its factor ends on the mechanism (its last saved step):
    // the plastic strain increment where material yields, the displacement increment where
    // only blocks slide.
    if (factor_found_) {
        const Model& m = view_->scene()->model;
        const bool yields = m.analysis.plasticity && std::any_of(m.materials.begin(), m.materials.end(),
                                                                 [](const Material& x) { return x.may_yield(); });
        result_bar_->setField(yields ? QStringLiteral("plastic_strain_increment")
                                     : QStringLiteral("displacement_increment"));
    }
    statusBar()->showMessage(text, 10000);
    updateRunActions();
    // (Not in equilibrium is said in the status bar and the log: the results are complete.)
    if (status == RunStatus::Collapsed || status == RunStatus::Failed)
        show_box(this, status == RunStatus::Collapsed ? QMessageBox::Warning : QMessageBox::Critical,
                 status == RunStatus::Collapsed ? tr("Collapse") : tr("Run failed"), text,
                 tr("The results up to the last accepted step are kept in %1.").arg(session_->resultsFolder()));
    emit runFinished(status, message);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (loading_) {  // the window goes once the file is read (load() is on the stack)
        close_after_load_ = true;
        event->ignore();
        return;
    }
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    session_->abandon();
    QMainWindow::closeEvent(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (std::any_of(urls.begin(), urls.end(), is_model_file)) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    for (const QUrl& url : event->mimeData()->urls())
        if (is_model_file(url)) {
            openModel(url.toLocalFile());
            event->acceptProposedAction();
            return;
        }
}

}  // namespace mcdda::gui
