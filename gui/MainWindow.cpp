#include "MainWindow.hpp"

#include "Version.hpp"
#include "widgets/ModelView.hpp"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
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
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QStringList>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <exception>

namespace mcdda::gui {

namespace {

QString to_qt(const std::string& s) { return QString::fromStdString(s); }

bool is_model_file(const QUrl& url)
{
    return url.isLocalFile() && url.toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive);
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    view_ = new ModelView(this);
    setCentralWidget(view_);
    createDock();
    createActions();
    createStatusBar();
    setAcceptDrops(true);
    setWindowTitle(tr("mcdda"));
    resize(1100, 750);
    connect(view_, &ModelView::cursorMoved, this, &MainWindow::showCursor);
    connect(view_, &ModelView::cursorLeft, cursor_label_, &QLabel::clear);
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::openDialog);
    open->setShortcut(QKeySequence::Open);
    open->setStatusTip(tr("Open a model file (*.json)"));
    reload_action_ = file->addAction(tr("&Reload"), this, &MainWindow::reload);
    reload_action_->setShortcut(QKeySequence::Refresh);
    reload_action_->setStatusTip(tr("Read the model file again, e.g. after editing it"));
    reload_action_->setEnabled(false);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* fit = view->addAction(tr("&Fit"), view_, &ModelView::fitView);
    fit->setShortcut(QKeySequence(Qt::Key_F));
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
    view->addAction(dock_->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About mcdda"), this, [this] {
        QMessageBox::about(this, tr("About mcdda"),
                           tr("<b>mcdda %1</b><p>Pre- and post-processor for elastic-plastic "
                              "discontinuous deformation analysis.</p>"
                              "<p>Drag with the left or middle mouse button to pan, turn the wheel "
                              "to zoom, press F to fit.</p>")
                               .arg(QString::fromLatin1(mcdda::version_string)));
    });
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
    resizeDocks({dock_}, {140}, Qt::Vertical);  // the model gets most of the height
}

void MainWindow::createStatusBar()
{
    cursor_label_ = new QLabel(this);
    cursor_label_->setMinimumWidth(260);
    statistics_label_ = new QLabel(this);
    statusBar()->addPermanentWidget(statistics_label_);
    statusBar()->addPermanentWidget(cursor_label_);
}

QString MainWindow::messages() const { return messages_->toPlainText(); }

QString MainWindow::statisticsText() const { return statistics_label_->text(); }

void MainWindow::showCursor(const QPointF& model_pos)
{
    // As many decimals as one pixel resolves.
    const double resolution = view_->metresPerPixel();
    const int decimals =
        resolution > 0.0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(resolution))), 0, 6) : 3;
    cursor_label_->setText(tr("x = %1 m   y = %2 m")
                               .arg(model_pos.x(), 0, 'f', decimals)
                               .arg(model_pos.y(), 0, 'f', decimals));
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
    const QString path = QFileDialog::getOpenFileName(this, tr("Open model"), last_folder_,
                                                      tr("Model files (*.json);;All files (*)"));
    if (!path.isEmpty()) openModel(path);
}

void MainWindow::reload()
{
    if (!path_.isEmpty()) load(path_, true);
}

bool MainWindow::openModel(const QString& path) { return load(path, false); }

bool MainWindow::load(const QString& path, bool keep_camera)
{
    auto result = std::make_shared<Preprocessed>();
    QString failure;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    statusBar()->showMessage(tr("Reading %1...").arg(QFileInfo(path).fileName()));
    try {
        *result = preprocess_file(path.toStdString(), {}, PreprocessStage::Mesh);
    } catch (const std::exception& e) {  // preprocess_file reports bad input as diagnostics;
        failure = to_qt(e.what());        // this is for anything unforeseen
    }
    QApplication::restoreOverrideCursor();
    statusBar()->clearMessage();

    path_ = path;
    last_folder_ = QFileInfo(path).absolutePath();
    reload_action_->setEnabled(true);
    if (!failure.isEmpty()) {
        Diagnostic d;
        d.message = failure.toStdString();
        result->diagnostics.push_back(d);
        result->ok = false;
    }
    showPreprocessed(result, path, keep_camera);
    return result->ok;
}

void MainWindow::showPreprocessed(std::shared_ptr<const Preprocessed> p, const QString& source, bool keep_camera)
{
    if (!p) return;
    const QString name = p->model.name.empty() ? QFileInfo(source).fileName() : to_qt(p->model.name);
    setWindowTitle(tr("%1 - mcdda").arg(name));
    setWindowFilePath(source);

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
    if (!view_->scene()->ok) reportFailure(*view_->scene(), source);
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
