#include "MainWindow.hpp"

#include "Version.hpp"
#include "document/ModelDocument.hpp"
#include "panels/PropertyEditor.hpp"
#include "tools/EditingTools.hpp"
#include "results/HistoryPlot.hpp"
#include "results/ResultExport.hpp"
#include "results/StepSlider.hpp"
#include "widgets/ModelTree.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QWhatsThis>
#include <QVBoxLayout>
#include <QTextBrowser>
#include <QFile>
#include <QDialog>
#include <QScrollBar>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QHeaderView>
#include <QIcon>
#include <QSettings>
#include <QTreeWidget>
#include <QUndoStack>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QStatusBar>
#include <QStringList>
#include <QThread>
#include <QTimer>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QToolBar>
#include <QUrl>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <exception>

namespace mcdda::gui {

namespace {

/// The steps a run of `model` plans: its stages' (a stage may end early on its target ratio).
int plannedSteps(const Model& model)
{
    if (model.stages.empty()) return model.analysis.steps;
    int steps = 0;
    for (const Stage& stage : model.stages) steps += stage.analysis.steps;
    return steps;
}


QString to_qt(const std::string& s) { return QString::fromStdString(s); }

constexpr int max_recent_files = 8;
const char* const recent_key = "recentFiles";

bool is_model_file(const QUrl& url)
{
    return url.isLocalFile() && url.toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive);
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    view_ = new ModelView(this);
    setCentralWidget(view_);
    document_ = new ModelDocument(this);
    preprocess_ = new QFutureWatcher<std::shared_ptr<Preprocessed>>(this);
    connect(preprocess_, &QFutureWatcherBase::finished, this, &MainWindow::onPreprocessed);
    editing_ = new EditingTools(this, view_, document_);
    connect(editing_, &EditingTools::message, this, &MainWindow::log);
    connect(editing_, &EditingTools::selectionChanged, this, &MainWindow::onSelectionChanged);
    createDock();
    createModelDock();
    createResultDocks();
    tabifyDockWidget(plot_dock_, model_dock_);  // the view keeps its width
    property_editor_ = new PropertyEditor(document_, this);
    property_editor_->setObjectName(QStringLiteral("propertyEditor"));
    property_dock_ = new QDockWidget(tr("Properties"), this);
    property_dock_->setObjectName(QStringLiteral("properties"));
    property_dock_->setWidget(property_editor_);
    addDockWidget(Qt::RightDockWidgetArea, property_dock_);
    tabifyDockWidget(model_dock_, property_dock_);
    model_dock_->raise();
    createActions();
    createEditActions();
    createRunActions();
    createStatusBar();
    setAcceptDrops(true);
    setWindowTitle(tr("mcdda"));
    resize(1100, 750);
    connect(view_, &ModelView::cursorMoved, this, &MainWindow::showCursor);
    connect(view_, &ModelView::cursorLeft, cursor_label_, &QLabel::clear);
    connect(document_, &ModelDocument::changed, this, &MainWindow::onDocumentChanged);
    connect(document_, &ModelDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(document_, &ModelDocument::pathChanged, this, &MainWindow::updateTitle);
    applySnap();
    refreshModelTree();
}

MainWindow::~MainWindow()
{
    joinRun();
    requested_ = 0;
    preprocess_->waitForFinished();  // its result is dropped
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
    recent_menu_ = file->addMenu(tr("Recent &Files"));
    recent_menu_->setObjectName(QStringLiteral("recentMenu"));
    refreshRecentMenu();
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
    createExportActions(file);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* fit = view->addAction(tr("&Fit"), view_, &ModelView::fitView);
    fit->setShortcut(QKeySequence(Qt::Key_F));
    fit->setIcon(QIcon(QStringLiteral(":/icons/fit-view.svg")));
    fit->setStatusTip(tr("Show the whole model"));
    view->addSeparator();
    auto toggle = [&](const QString& text, const QString& tip) {
        QAction* action = view->addAction(text);
        action->setCheckable(true);
        action->setChecked(true);
        action->setStatusTip(tip);
        connect(action, &QAction::toggled, this, &MainWindow::applySceneOptions);
        return action;
    };
    show_mesh_ = toggle(tr("&Mesh"), tr("Show the element edges"));
    show_joints_ = toggle(tr("&Joints"), tr("Show the joint traces"));
    show_supports_ = toggle(tr("&Supports"), tr("Show fixed points and rollers"));
    show_loads_ = toggle(tr("&Loads"), tr("Show point loads and edge pressures"));
    show_points_ = toggle(tr("Measurement &points"), tr("Show the measurement points"));
    show_legend_ = toggle(tr("Le&gend"), tr("Show the legend"));
    view->addSeparator();
    snap_action_ = view->addAction(tr("Snap to &Grid"));
    snap_action_->setObjectName(QStringLiteral("snapToGridAction"));
    snap_action_->setCheckable(true);
    snap_action_->setChecked(true);
    snap_action_->setStatusTip(tr("Drawn points snap to a grid (0.5 m) and to nearby region vertices"));
    connect(snap_action_, &QAction::toggled, this, &MainWindow::applySnap);
    view->addSeparator();
    view->addAction(model_dock_->toggleViewAction());
    view->addAction(dock_->toggleViewAction());
    view->addAction(steps_dock_->toggleViewAction());
    view->addAction(plot_dock_->toggleViewAction());
    view->addAction(property_dock_->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help_menu_ = help;
    // The documentation is compiled in (resources/mcdda.qrc): it matches the program and needs
    // no network or installed files.
    QAction* guide = help->addAction(tr("&User Guide"), this, [this] {
        showDocument(tr("User Guide"), QStringLiteral(":/docs/desktop.md"));
    });
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("Model &File Format"), this, [this] {
        showDocument(tr("Model File Format"), QStringLiteral(":/docs/model-format.md"));
    })->setObjectName(QStringLiteral("modelFormatHelpAction"));
    help->addAction(tr("&Running and Results"), this, [this] {
        showDocument(tr("Running and Results"), QStringLiteral(":/docs/running.md"));
    })->setObjectName(QStringLiteral("runningHelpAction"));
    QAction* whats_this = QWhatsThis::createAction(this);
    whats_this->setObjectName(QStringLiteral("whatsThisAction"));
    help->addAction(whats_this);
    help->addSeparator();
    help->addAction(tr("&About mcdda"), this, [this] {
        QMessageBox::about(this, tr("About mcdda"),
                           tr("<b>mcdda %1</b><p>Pre- and post-processor for elastic-plastic "
                              "discontinuous deformation analysis.</p>"
                              "<p>Drag with the left or middle mouse button to pan, turn the wheel "
                              "to zoom, press F to fit.</p>")
                               .arg(QString::fromLatin1(mcdda::version_string)));
    });
}

void MainWindow::showDocument(const QString& title, const QString& resource)
{
    QFile file(resource);
    if (!file.open(QIODevice::ReadOnly)) {
        reportExportError(tr("The document %1 is missing from this build.").arg(resource));
        return;
    }
    auto* dialog = new QDialog(this);
    dialog->setObjectName(QStringLiteral("helpDialog"));
    dialog->setWindowTitle(tr("mcdda — %1").arg(title));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* browser = new QTextBrowser(dialog);
    browser->setObjectName(QStringLiteral("helpBrowser"));
    browser->setOpenExternalLinks(true);
    browser->setMarkdown(QString::fromUtf8(file.readAll()));
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(browser);
    dialog->resize(760, 640);
    dialog->show();  // beside the window, not modal: read while working
}

void MainWindow::createEditActions()
{
    // Between File and View (created before it).
    auto* edit = new QMenu(tr("&Edit"), this);
    menuBar()->insertMenu(menuBar()->actions().at(1), edit);
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(QIcon(QStringLiteral(":/icons/undo.svg")));
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setIcon(QIcon(QStringLiteral(":/icons/redo.svg")));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    editing_->createActions(edit);
    tree_->addAction(editing_->deleteAction());
}

DrawTool* MainWindow::activeTool() const { return editing_->activeTool(); }
SelectTool* MainWindow::selectionTool() const { return editing_->selectTool(); }
ItemRef MainWindow::selection() const { return editing_->selection(); }
void MainWindow::selectTool() { editing_->useSelect(); }
void MainWindow::drawRegionTool() { editing_->useRegion(); }
void MainWindow::drawJointTool() { editing_->useJoint(); }
void MainWindow::fixedPointTool() { editing_->useFixedPoint(); }
void MainWindow::rollerTool() { editing_->useRoller(); }
void MainWindow::pointLoadTool() { editing_->usePointLoad(); }
void MainWindow::edgePressureTool() { editing_->useEdgePressure(); }
void MainWindow::measurementPointTool() { editing_->useMeasurementPoint(); }
void MainWindow::selectItem(const ItemRef& ref) { editing_->selectItem(ref); }
bool MainWindow::deleteSelection(const ItemRef& ref) { return editing_->deleteItem(ref); }
bool MainWindow::enterCoordinates(const QString& text) { return editing_->enterCoordinates(text); }
void MainWindow::addJointSetDialog() { editing_->addJointSetDialog(); }

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

void MainWindow::applySnap() { editing_->setSnapping(snap_action_ && snap_action_->isChecked(), grid_spacing_); }

void MainWindow::createModelDock()
{
    tree_ = new ModelTree(this);
    tree_->setObjectName(QStringLiteral("modelTree"));
    connect(tree_, &ModelTree::itemChosen, this, [this](const ItemRef& ref) {
        if (ref.valid()) selectItem(ref);
    });
    model_dock_ = new QDockWidget(tr("Model"), this);
    model_dock_->setObjectName(QStringLiteral("model"));
    model_dock_->setWidget(tree_);
    addDockWidget(Qt::RightDockWidgetArea, model_dock_);
}

void MainWindow::refreshModelTree() { tree_->refresh(document_->model(), view_->scene().get()); }

QStringList MainWindow::recentFiles() const
{
    return QSettings().value(QString::fromLatin1(recent_key)).toStringList();
}

void MainWindow::addRecentFile(const QString& path)
{
    QStringList files = recentFiles();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > max_recent_files) files.removeLast();
    QSettings().setValue(QString::fromLatin1(recent_key), files);
    refreshRecentMenu();
}

void MainWindow::refreshRecentMenu()
{
    recent_menu_->clear();
    const QStringList files = recentFiles();
    for (int i = 0; i < files.size(); ++i) {
        const QString path = files[i];
        QAction* action = recent_menu_->addAction(tr("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()), this,
                                                  [this, path] {
                                                      if (maybeSave()) openModel(path);
                                                  });
        action->setStatusTip(path);
    }
    recent_menu_->setEnabled(!files.isEmpty());
}

void MainWindow::updateTitle()
{
    QString name;
    const QString path = document_->path();
    const QString model_name = to_qt(document_->model().name);
    if (!path.isEmpty())
        name = model_name.isEmpty() ? QFileInfo(path).fileName()
                                    : tr("%1 (%2)").arg(QFileInfo(path).fileName(), model_name);
    else
        name = model_name.isEmpty() ? tr("Untitled") : model_name;
    setWindowTitle(tr("%1[*] - mcdda").arg(name));
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
    constexpr double pi = 3.14159265358979323846;
    Model m;
    Material rock;
    rock.name = tr("rock").toStdString();
    rock.young_modulus = 10e9;
    rock.poisson_ratio = 0.25;
    rock.density = 25.5e3 / 9.81;  // a unit weight of 25.5 kN/m³, as the forms show it (not 25.506)
    rock.cohesion = 1e6;
    rock.friction_angle = 35.0 * pi / 180.0;
    rock.dilation_angle = 0.0;
    m.materials.push_back(rock);
    JointMaterial joint;
    joint.name = tr("joint").toStdString();
    joint.friction_angle = 30.0 * pi / 180.0;
    m.joint_materials.push_back(joint);
    m.default_joint_material = 0;
    m.gravity = {0.0, -9.81};
    path_.clear();
    reload_action_->setEnabled(false);
    document_->setModel(m);  // → onDocumentChanged: an empty picture
    setWindowFilePath(QString());
    view_->showBox(-5.0, -5.0, 25.0, 20.0);
    log(tr("New model: draw regions with Edit ▸ Draw Region."));
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
    path_ = path;
    last_folder_ = QFileInfo(path).absolutePath();
    reload_action_->setEnabled(true);
    setWindowFilePath(path);
    addRecentFile(path);
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

void MainWindow::onDocumentChanged()
{
    editing_->documentChanged();
    refreshModelTree();
    updateTitle();
    ++generation_;
    if (syncing_) {
        requested_ = 0;  // the caller shows a picture itself; one still being made is dropped
        return;
    }
    requested_ = generation_;
    // One computation at a time: a newer change waits for the running one and supersedes it.
    if (!preprocess_->isRunning()) startPreprocess();
    updateRunActions();
}

bool MainWindow::meshModel()
{
    if (isRunning() || loading_) return false;
    show_mesh_->setChecked(true);  // what was asked for is seen
    if (isPreprocessing()) return true;  // a newer picture is on its way already
    requested_ = ++generation_;
    startPreprocess();
    updateRunActions();
    return true;
}

void MainWindow::startPreprocess()
{
    running_ = requested_;
    statusBar()->showMessage(tr("Pre-processing..."));
    preprocess_->setFuture(QtConcurrent::run([model = document_->model()] {
        auto p = std::make_shared<Preprocessed>();
        try {
            *p = preprocess_model(model, PreprocessStage::Mesh);
        } catch (const std::exception& e) {
            Diagnostic d;
            d.message = e.what();
            p->diagnostics.push_back(d);
            p->model = model;
            p->ok = false;
        }
        return p;
    }));
}

void MainWindow::onPreprocessed()
{
    if (requested_ == 0) {  // dropped (a model was opened meanwhile)
        statusBar()->clearMessage();
        updateRunActions();
        return;
    }
    if (running_ != requested_) {  // superseded by a newer change
        startPreprocess();
        return;
    }
    requested_ = 0;
    statusBar()->clearMessage();
    const auto p = preprocess_->result();
    const QString source = document_->path().isEmpty() ? tr("Untitled") : document_->path();
    showScene(p, source, true, false);
}

void MainWindow::createDock()
{
    messages_ = new QPlainTextEdit(this);
    messages_->setReadOnly(true);
    messages_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    messages_->setPlaceholderText(tr("Messages about the model appear here."));
    dock_ = new QDockWidget(tr("Messages"), this);
    dock_->setObjectName(QStringLiteral("messages"));
    dock_->setWidget(messages_);
    addDockWidget(Qt::BottomDockWidgetArea, dock_);
    // Ten lines of messages; the model keeps most of the height.
    resizeDocks({dock_}, {10 * messages_->fontMetrics().lineSpacing() + 24}, Qt::Vertical);
}

void MainWindow::createResultDocks()
{
    steps_ = new StepSlider(this);
    steps_dock_ = new QDockWidget(tr("Steps"), this);
    steps_dock_->setObjectName(QStringLiteral("steps"));
    steps_dock_->setWidget(steps_);
    addDockWidget(Qt::BottomDockWidgetArea, steps_dock_);
    connect(steps_, &StepSlider::stepChosen, this, [this](const QString& vtu) { showStep(vtu); });

    plot_ = new HistoryPlot(this);
    plot_dock_ = new QDockWidget(tr("Plots"), this);
    plot_dock_->setObjectName(QStringLiteral("plots"));
    plot_dock_->setWidget(plot_);
    addDockWidget(Qt::RightDockWidgetArea, plot_dock_);
    resizeDocks({plot_dock_}, {320}, Qt::Horizontal);
}

void MainWindow::createExportActions(QMenu* file)
{
    QMenu* menu = file->addMenu(tr("&Export"));
    QAction* png = menu->addAction(tr("&Picture (PNG)..."), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export picture"), last_folder_,
                                                          tr("PNG pictures (*.png)"));
        if (!path.isEmpty()) exportPng(path.endsWith(QStringLiteral(".png"), Qt::CaseInsensitive)
                                           ? path : path + QStringLiteral(".png"));
    });
    png->setObjectName(QStringLiteral("exportPngAction"));
    png->setStatusTip(tr("Save the picture of the view as a PNG file"));
    QAction* steps = menu->addAction(tr("Saved &Steps (PVD/VTU)..."), this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Export saved steps to"), last_folder_);
        if (!folder.isEmpty()) exportSteps(folder);
    });
    steps->setObjectName(QStringLiteral("exportStepsAction"));
    steps->setStatusTip(tr("Copy the run's .pvd collection and its .vtu steps to a folder"));
    QAction* history = menu->addAction(tr("&History (CSV)..."), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export history"), last_folder_,
                                                          tr("CSV files (*.csv)"));
        if (!path.isEmpty()) exportHistory(path);
    });
    history->setObjectName(QStringLiteral("exportHistoryAction"));
    history->setStatusTip(tr("Copy the run's history of loads and measured displacements"));
}

void MainWindow::reportExportError(const QString& message)
{
    log(message);
    auto* box = new QMessageBox(QMessageBox::Critical, tr("Export failed"), message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();  // non-blocking, like reportFailure()
}

bool MainWindow::exportPng(const QString& path)
{
    QString error;
    if (!export_png(view_->grabFrame(), path, error)) {
        reportExportError(error);
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

bool MainWindow::exportSteps(const QString& folder)
{
    if (results_folder_.isEmpty() || !QFileInfo::exists(resultsPvdPath())) {
        reportExportError(tr("There are no saved steps yet: run the model first."));
        return false;
    }
    QString error;
    int copied = 0;
    if (!export_steps(resultsPvdPath(), folder, error, &copied)) {
        reportExportError(error);
        return false;
    }
    statusBar()->showMessage(tr("Copied %n file(s) to %1", "", copied).arg(folder), 5000);
    return true;
}

bool MainWindow::exportHistory(const QString& path)
{
    if (results_folder_.isEmpty() || !QFileInfo::exists(resultsHistoryPath())) {
        reportExportError(tr("There is no history yet: run the model first."));
        return false;
    }
    QString error;
    if (!export_file(resultsHistoryPath(), path, error)) {
        reportExportError(error);
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

QString MainWindow::resultsPvdPath() const
{
    if (results_folder_.isEmpty()) return {};
    return QDir(results_folder_).absoluteFilePath(results_stem_ + QStringLiteral(".pvd"));
}

QString MainWindow::resultsHistoryPath() const
{
    if (results_folder_.isEmpty()) return {};
    return QDir(results_folder_).absoluteFilePath(QStringLiteral("history.csv"));
}

void MainWindow::refreshResults()
{
    steps_->load(resultsPvdPath());
    plot_->load(resultsHistoryPath());
}

void MainWindow::showStep(const QString& vtu_path)
{
    // While running, an earlier saved step is looked at until the slider is back on the last
    // one, when the picture follows the run again (issue 13, item 15).
    if (isRunning()) {
        looking_back_ = steps_->currentIndex() + 1 < steps_->count();
        if (!looking_back_) {
            shown_step_.clear();
            showResult();
            return;
        }
    }
    shown_step_ = vtu_path;
    showResult();
}

void MainWindow::createStatusBar()
{
    cursor_label_ = new QLabel(this);
    cursor_label_->setMinimumWidth(260);
    statistics_label_ = new QLabel(this);
    progress_bar_ = new QProgressBar(this);
    progress_bar_->setMaximumWidth(200);
    progress_bar_->setTextVisible(true);
    progress_bar_->setVisible(false);
    statusBar()->addPermanentWidget(progress_bar_);
    statusBar()->addPermanentWidget(statistics_label_);
    statusBar()->addPermanentWidget(cursor_label_);
}

QString MainWindow::messages() const { return messages_->toPlainText(); }

QString MainWindow::statisticsText() const { return statistics_label_->text(); }

QString MainWindow::cursorText() const { return cursor_label_->text(); }

void MainWindow::showCursor(const QPointF& model_pos)
{
    // As many decimals as one pixel resolves.
    const double resolution = view_->metresPerPixel();
    const int decimals =
        resolution > 0.0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(resolution))), 0, 6) : 3;
    QString text = tr("x = %1 m   y = %2 m").arg(model_pos.x(), 0, 'f', decimals).arg(model_pos.y(), 0, 'f', decimals);
    const QString value = view_->resultValueAt(model_pos);  // a query of the result shown
    if (!value.isEmpty()) text += QStringLiteral("   ") + value;
    cursor_label_->setText(text);
}

void MainWindow::applySceneOptions()
{
    view::SceneOptions options = view_->sceneOptions();
    options.show_mesh = show_mesh_->isChecked();
    options.show_joints = show_joints_->isChecked();
    options.show_supports = show_supports_->isChecked();
    options.show_loads = show_loads_->isChecked();
    options.show_points = show_points_->isChecked();
    options.show_legend = show_legend_->isChecked();
    view_->setSceneOptions(options);
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
    if (!maybeSave()) return;
    if (!path_.isEmpty()) load(path_, true);
}

bool MainWindow::openModel(const QString& path) { return load(path, false); }

bool MainWindow::load(const QString& path, bool keep_camera)
{
    if (loading_) return false;  // one file at a time
    loading_ = true;
    updateRunActions();
    QApplication::setOverrideCursor(Qt::BusyCursor);
    statusBar()->showMessage(tr("Reading and meshing %1...").arg(QFileInfo(path).fileName()));
    progress_bar_->setRange(0, 0);  // busy: the pipeline reports no fraction
    progress_bar_->setVisible(true);

    // Reading, cutting and meshing run on the thread pool; this loop keeps the window painted
    // meanwhile. Input waits (as under a progress dialog), so nothing changes the model under
    // the reader's feet.
    QFutureWatcher<std::shared_ptr<Preprocessed>> watcher;
    QEventLoop loop;
    connect(&watcher, &QFutureWatcherBase::finished, &loop, &QEventLoop::quit);
    watcher.setFuture(QtConcurrent::run([file = path.toStdString()] {
        auto p = std::make_shared<Preprocessed>();
        try {
            *p = preprocess_file(file, {}, PreprocessStage::Mesh);
        } catch (const std::exception& e) {  // bad input comes as diagnostics; this is for
            Diagnostic d;                    // anything unforeseen
            d.message = e.what();
            p->diagnostics.push_back(d);
            p->ok = false;
        }
        return p;
    }));
    if (!watcher.isFinished()) loop.exec(QEventLoop::ExcludeUserInputEvents);
    const std::shared_ptr<Preprocessed> result = watcher.result();

    progress_bar_->setVisible(false);
    QApplication::restoreOverrideCursor();
    statusBar()->clearMessage();
    loading_ = false;

    path_ = path;
    last_folder_ = QFileInfo(path).absolutePath();
    reload_action_->setEnabled(true);
    syncing_ = true;
    const std::vector<Diagnostic> read = document_->open(path);
    if (std::any_of(read.begin(), read.end(), [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::Error; }))
        document_->setModel(result->model);  // what could be read, without a file to save to
    syncing_ = false;
    if (document_->path() == path) addRecentFile(path);
    showScene(result, path, keep_camera, true);
    if (close_after_load_) QTimer::singleShot(0, this, &QWidget::close);
    return result->ok;
}

void MainWindow::showPreprocessed(std::shared_ptr<const Preprocessed> p, const QString& source, bool keep_camera)
{
    if (!p) return;
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
        joinRun();
        log(interactive ? tr("The run was stopped: another model was opened.")
                        : tr("The run was stopped: the model was edited."));
    }
    last_snapshot_.reset();
    shown_step_.clear();
    results_folder_.clear();
    steps_->clear();
    plot_->clear();
    if (interactive) setWindowFilePath(source);
    updateTitle();

    QStringList lines;
    lines << tr("Model: %1").arg(source);
    for (const Diagnostic& d : p->diagnostics) lines << to_qt(format_diagnostic(d));
    if (p->ok) {
        lines << to_qt(describe(p->statistics));
        lines << tr("Times: read %1 ms, checked %2 ms, cut %3 ms, meshed %4 ms")
                     .arg(1e3 * p->seconds_read, 0, 'f', 0)
                     .arg(1e3 * p->seconds_validate, 0, 'f', 0)
                     .arg(1e3 * p->seconds_cut, 0, 'f', 0)
                     .arg(1e3 * p->seconds_mesh, 0, 'f', 0);
        const MeshStatistics& s = p->statistics;
        statistics_label_->setText(tr("%1 blocks, %2 nodes, %3 elements, smallest angle %4°")
                                       .arg(s.blocks)
                                       .arg(s.nodes)
                                       .arg(s.elements)
                                       .arg(s.min_angle_deg, 0, 'f', 1));
    } else {
        const auto errors = std::count_if(p->diagnostics.begin(), p->diagnostics.end(), [](const Diagnostic& d) {
            return d.severity == Diagnostic::Severity::Error;
        });
        statistics_label_->setText(tr("Not meshed: %n error(s)", "", static_cast<int>(errors)));
    }
    messages_->setPlainText(lines.join(QLatin1Char('\n')));
    view_->setScene(std::move(p), keep_camera);
    refreshModelTree();  // its blocks
    updateRunActions();
    if (!view_->scene()->ok && interactive) reportFailure(*view_->scene(), source);
}

void MainWindow::reportFailure(const Preprocessed& p, const QString& source)
{
    QStringList errors;
    for (const Diagnostic& d : p.diagnostics)
        if (d.severity == Diagnostic::Severity::Error) errors << to_qt(format_diagnostic(d));
    if (errors.isEmpty()) errors << tr("pre-processing stopped without a message");

    constexpr int shown = 8;
    QString summary = QStringList(errors.mid(0, shown)).join(QLatin1Char('\n'));
    if (errors.size() > shown) summary += QLatin1Char('\n') + tr("... and %n more", "", int(errors.size() - shown));

    // Non-blocking (open(), not exec()): the program and its tests keep running.
    auto* box = new QMessageBox(QMessageBox::Critical, tr("Model not usable"),
                                tr("%1 could not be pre-processed.").arg(QFileInfo(source).fileName()),
                                QMessageBox::Ok, this);
    box->setInformativeText(summary);
    box->setDetailedText(errors.join(QLatin1Char('\n')));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::createRunActions()
{
    auto* run = new QMenu(tr("&Run"), this);
    menuBar()->insertMenu(help_menu_->menuAction(), run);  // Help stays last
    QToolBar* bar = addToolBar(tr("Run"));
    bar->setObjectName(QStringLiteral("run"));
    mesh_action_ = run->addAction(tr("&Mesh"), this, &MainWindow::meshModel);
    mesh_action_->setObjectName(QStringLiteral("meshAction"));
    mesh_action_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    mesh_action_->setIcon(QIcon(QStringLiteral(":/icons/mesh.svg")));
    mesh_action_->setStatusTip(tr("Cut the blocks and mesh them in the background (edits do this by "
                                  "themselves); the statistics go to the status bar and the Messages dock"));
    bar->addAction(mesh_action_);
    run_action_ = run->addAction(tr("&Run"), this, &MainWindow::startRun);
    run_action_->setObjectName(QStringLiteral("runAction"));
    run_action_->setShortcut(QKeySequence(Qt::Key_F5));
    run_action_->setIcon(QIcon(QStringLiteral(":/icons/run.svg")));
    run_action_->setStatusTip(tr("Analyse the model; the picture follows the run"));
    pause_action_ = run->addAction(tr("&Pause"), this, &MainWindow::togglePause);
    pause_action_->setObjectName(QStringLiteral("pauseAction"));
    pause_action_->setIcon(QIcon(QStringLiteral(":/icons/pause.svg")));
    pause_action_->setStatusTip(tr("Pause or resume the run"));
    stop_action_ = run->addAction(tr("&Stop"), this, &MainWindow::stopRun);
    stop_action_->setObjectName(QStringLiteral("stopAction"));
    stop_action_->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    stop_action_->setIcon(QIcon(QStringLiteral(":/icons/stop.svg")));
    stop_action_->setStatusTip(tr("Stop the run after the current step; the results so far are kept"));
    run->addSeparator();
    QAction* folder = run->addAction(tr("Results &Folder..."), this, [this] {
        const QString chosen =
            QFileDialog::getExistingDirectory(this, tr("Folder for the results"), runOutputFolder());
        if (!chosen.isEmpty()) output_folder_ = chosen;
    });
    folder->setStatusTip(tr("Choose where runs write their files"));
    bar->addAction(run_action_);
    bar->addAction(pause_action_);
    bar->addAction(stop_action_);
    bar->addSeparator();
    field_box_ = new QComboBox(this);
    field_box_->setToolTip(tr("Field shown for results"));
    field_box_->setObjectName(QStringLiteral("fieldBox"));
    field_box_->addItem(tr("Displacement |u|"), QStringLiteral("displacement"));
    field_box_->addItem(tr("Displacement ux"), QStringLiteral("ux"));
    field_box_->addItem(tr("Displacement uy"), QStringLiteral("uy"));
    field_box_->addItem(tr("Stress σxx"), QStringLiteral("stress_xx"));
    field_box_->addItem(tr("Stress σyy"), QStringLiteral("stress_yy"));
    field_box_->addItem(tr("Stress τxy"), QStringLiteral("stress_xy"));
    field_box_->addItem(tr("Principal stress σ1"), QStringLiteral("stress_1"));
    field_box_->addItem(tr("Principal stress σ3"), QStringLiteral("stress_3"));
    field_box_->addItem(tr("Plastic state"), QStringLiteral("plastic_state"));
    field_box_->addItem(tr("Plastic strain"), QStringLiteral("plastic_strain"));
    connect(field_box_, &QComboBox::currentIndexChanged, this, [this] { showResult(); });
    bar->addWidget(field_box_);
    auto* deform_label = new QLabel(tr("Deformation ×"), this);
    deform_label->setContentsMargins(6, 0, 2, 0);
    bar->addWidget(deform_label);
    deform_box_ = new QDoubleSpinBox(this);
    deform_box_->setObjectName(QStringLiteral("deformBox"));
    deform_box_->setToolTip(tr("Scale factor of the drawn displacements (0 = undeformed)"));
    deform_box_->setRange(0.0, 1e6);
    deform_box_->setDecimals(1);
    deform_box_->setSingleStep(10.0);
    deform_box_->setValue(0.0);
    connect(deform_box_, &QDoubleSpinBox::valueChanged, this, [this] { showResult(); });
    bar->addWidget(deform_box_);
    updateRunActions();
}

void MainWindow::updateRunActions()
{
    const bool running = isRunning();
    const auto scene = view_->scene();
    run_action_->setEnabled(!running && !loading_ && scene && scene->ok && !isPreprocessing());  // not a stale picture
    mesh_action_->setEnabled(!running && !loading_);
    pause_action_->setEnabled(running);
    pause_action_->setText(running && controller_->isPaused() ? tr("Res&ume") : tr("&Pause"));
    stop_action_->setEnabled(running);
}

QString MainWindow::runOutputFolder() const
{
    if (running_folder_.size() > 0 && isRunning()) return running_folder_;
    if (!output_folder_.isEmpty()) return output_folder_;
    const QString source = windowFilePath();
    if (source.isEmpty()) return QDir::current().absoluteFilePath(QStringLiteral("model-results"));
    const QFileInfo info(source);
    return info.absoluteDir().absoluteFilePath(info.completeBaseName() + QStringLiteral("-results"));
}

void MainWindow::setRunThrottle(int progress_ms, int snapshot_ms)
{
    progress_ms_ = progress_ms;
    snapshot_ms_ = snapshot_ms;
}

QString MainWindow::resultField() const { return field_box_->currentData().toString(); }

void MainWindow::setResultField(const QString& field)
{
    const int index = field_box_->findData(field);
    if (index >= 0) field_box_->setCurrentIndex(index);
}

double MainWindow::deformFactor() const { return deform_box_->value(); }

void MainWindow::setDeformFactor(double factor) { deform_box_->setValue(factor); }

void MainWindow::log(const QString& line)
{
    messages_->appendPlainText(line);
    // The newest line stays in sight, even when the user scrolled up earlier (the run's log).
    messages_->verticalScrollBar()->setValue(messages_->verticalScrollBar()->maximum());
}

bool MainWindow::startRun()
{
    const auto scene = view_->scene();
    if (isRunning() || !scene || !scene->ok || isPreprocessing()) return false;
    running_folder_ = runOutputFolder();
    const QString stem = windowFilePath().isEmpty() ? QStringLiteral("model")
                                                    : QFileInfo(windowFilePath()).completeBaseName();
    controller_ = new RunController(*scene, running_folder_, stem);
    controller_->setThrottle(progress_ms_, snapshot_ms_);
    run_thread_ = new QThread(this);
    run_thread_->setObjectName(QStringLiteral("mcdda-run"));
    controller_->moveToThread(run_thread_);
    connect(run_thread_, &QThread::started, controller_, &RunController::start);
    connect(controller_, &RunController::progress, this, &MainWindow::onRunProgress, Qt::QueuedConnection);
    connect(controller_, &RunController::snapshot, this, &MainWindow::onRunSnapshot, Qt::QueuedConnection);
    connect(controller_, &RunController::iterating, this, &MainWindow::onRunIterating, Qt::QueuedConnection);
    connect(controller_, &RunController::finished, this, &MainWindow::onRunFinished, Qt::QueuedConnection);

    last_snapshot_.reset();
    shown_step_.clear();
    looking_back_ = false;
    steps_->clear();
    plot_clock_.invalidate();
    results_stem_ = stem;
    progress_bar_->setRange(0, std::max(1, plannedSteps(scene->model)));
    progress_bar_->setValue(0);
    progress_bar_->setVisible(true);
    log(tr("Run started: %n step(s); results in %1", "", plannedSteps(scene->model)).arg(running_folder_));
    run_thread_->start();
    updateRunActions();
    return true;
}

void MainWindow::togglePause()
{
    if (!isRunning()) return;
    if (controller_->isPaused()) {
        controller_->resume();
        log(tr("Run resumed."));
    } else {
        controller_->pause();
        log(tr("Run paused."));
    }
    updateRunActions();
}

void MainWindow::stopRun()
{
    if (!isRunning()) return;
    controller_->stop();  // thread-safe; finished(Cancelled) follows
    stop_action_->setEnabled(false);
    pause_action_->setEnabled(false);
    log(tr("Stopping the run..."));
}

void MainWindow::onRunProgress(const RunProgress& p)
{
    progress_bar_->setValue(std::min(p.step, progress_bar_->maximum()));
    log(tr("step %1/%2  t = %3 s  dt = %4 s  contacts open/sliding/locked %5/%6/%7  "
           "plastic iterations %8  yielding %9")
            .arg(p.step)
            .arg(p.total_steps)
            .arg(p.time, 0, 'g', 6)
            .arg(p.time_step, 0, 'g', 4)
            .arg(p.open)
            .arg(p.sliding)
            .arg(p.locked)
            .arg(p.plastic_iterations)
            .arg(p.yielding));
    emit runProgressed(p);
}

void MainWindow::onRunIterating(const IterationInfo& info)
{
    if (!isRunning()) return;
    // Between steps the progress bar moves; inside a long step this line does.
    statusBar()->showMessage(tr("Step %1: equilibrium iteration %2, out-of-balance %3 (tolerance %4), %n point(s) yielding",
                                "", info.yielding)
                                 .arg(info.step)
                                 .arg(info.iteration)
                                 .arg(info.out_of_balance, 0, 'e', 2)
                                 .arg(info.tolerance, 0, 'e', 0),
                             5000);
    emit runIterating(info);
}

void MainWindow::onRunSnapshot(std::shared_ptr<const ResultSnapshot> snapshot)
{
    if (!isRunning()) return;  // a late one from a run already joined
    last_snapshot_ = std::move(snapshot);
    if (!looking_back_) {
        shown_step_.clear();
        showResult();
    }
    // The history grows a flushed row per step and the collection a step per save: re-read them
    // now and then for a live plot and a Steps dock to look back with (about once a second,
    // whatever the snapshot rate, so long histories stay cheap).
    if (!plot_clock_.isValid() || plot_clock_.elapsed() >= 1000) {
        plot_->load(QDir(running_folder_).absoluteFilePath(QStringLiteral("history.csv")));
        steps_->load(QDir(running_folder_).absoluteFilePath(results_stem_ + QStringLiteral(".pvd")), looking_back_);
        plot_clock_.restart();
    }
}

void MainWindow::showResult()
{
    view::ResultOptions options;
    options.field = resultField().toStdString();
    options.deform = deformFactor();
    if (!shown_step_.isEmpty() && (!isRunning() || looking_back_))
        view_->setResultFile(shown_step_, options);
    else if (last_snapshot_)
        view_->setResult(last_snapshot_, options);
}

void MainWindow::onRunFinished(RunStatus status, const QString& message)
{
    const QString folder = running_folder_;
    joinRun();
    if (looking_back_) {  // the slider goes to the last step below: the picture with it
        looking_back_ = false;
        shown_step_.clear();
        showResult();
    }
    progress_bar_->setVisible(false);
    const int step = last_snapshot_ ? last_snapshot_->step : 0;
    QString text;
    switch (status) {
        case RunStatus::Completed: text = tr("Run completed: %n step(s).", "", step); break;
        case RunStatus::Unbalanced: text = tr("Run ended but the model is not in equilibrium: %1").arg(message); break;
        case RunStatus::Cancelled: text = tr("Run stopped after step %1.").arg(step); break;
        case RunStatus::Collapsed: text = tr("The model collapsed: %1").arg(message); break;
        default: text = tr("The run failed: %1").arg(message); break;
    }
    log(text);
    log(tr("Results in %1").arg(folder));
    results_folder_ = folder;
    refreshResults();
    statusBar()->showMessage(text, 10000);
    // (Not in equilibrium is said in the status bar and the log: the results are complete.)
    if (status == RunStatus::Collapsed || status == RunStatus::Failed) {
        // Non-blocking, like reportFailure().
        auto* box = new QMessageBox(status == RunStatus::Collapsed ? QMessageBox::Warning : QMessageBox::Critical,
                                    status == RunStatus::Collapsed ? tr("Collapse") : tr("Run failed"), text,
                                    QMessageBox::Ok, this);
        box->setInformativeText(tr("The results up to the last accepted step are kept in %1.").arg(folder));
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
    emit runFinished(status, message);
}

void MainWindow::joinRun()
{
    if (run_thread_ == nullptr) return;
    controller_->stop();
    controller_->resume();  // a paused run must wake up to see the stop
    run_thread_->quit();    // takes effect once start() has returned
    run_thread_->wait();
    delete controller_;  // its thread has ended: safe from here
    controller_ = nullptr;
    delete run_thread_;
    run_thread_ = nullptr;
    updateRunActions();
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
    joinRun();
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
