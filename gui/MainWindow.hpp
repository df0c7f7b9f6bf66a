#pragma once
/// \file MainWindow.hpp
/// The desktop program's main window: opens a model file, pre-processes it (read, check, cut,
/// mesh) and shows the result; messages go to a dock, cursor position and mesh figures to the
/// status bar.

#include "Preprocess.hpp"

#include <QMainWindow>
#include <QString>

#include <memory>

class QAction;
class QLabel;
class QPlainTextEdit;
class QDockWidget;

namespace mcdda::gui {

class ModelView;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Pre-processes the model file at `path` and shows it. Returns false when that reported
    /// errors: they are listed in the Messages dock and summarised in a (non-blocking) message
    /// box; whatever could be read is still drawn.
    bool openModel(const QString& path);

    /// Shows an already pre-processed model; `source` names it in the title and messages.
    /// The camera is fitted unless `keep_camera` is set.
    void showPreprocessed(std::shared_ptr<const Preprocessed> p, const QString& source,
                          bool keep_camera = false);

    ModelView* modelView() const { return view_; }
    /// The file shown, empty when none was opened.
    QString modelPath() const { return path_; }
    /// The text of the Messages dock.
    QString messages() const;
    /// The mesh figures in the status bar.
    QString statisticsText() const;

public slots:
    /// File ▸ Open: asks for a *.json model.
    void openDialog();
    /// File ▸ Reload: reads the current file again, keeping the view.
    void reload();

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createDock();
    void createStatusBar();
    void applySceneOptions();
    void showCursor(const QPointF& model_pos);
    void reportFailure(const Preprocessed& p, const QString& source);
    bool load(const QString& path, bool keep_camera);

    ModelView* view_ = nullptr;
    QPlainTextEdit* messages_ = nullptr;
    QDockWidget* dock_ = nullptr;
    QLabel* cursor_label_ = nullptr;
    QLabel* statistics_label_ = nullptr;
    QAction* reload_action_ = nullptr;
    QAction* show_mesh_ = nullptr;
    QAction* show_joints_ = nullptr;
    QAction* show_supports_ = nullptr;
    QAction* show_loads_ = nullptr;
    QAction* show_points_ = nullptr;
    QAction* show_legend_ = nullptr;
    QString path_;
    QString last_folder_;
};

}  // namespace mcdda::gui
