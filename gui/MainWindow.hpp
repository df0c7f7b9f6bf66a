#pragma once
/// \file MainWindow.hpp
/// The desktop program's main window: opens a model file, pre-processes it (read, check, cut,
/// mesh) and shows the result; messages go to a dock, cursor position and mesh figures to the
/// status bar. Run ▸ Run analyses the model on a worker thread (RunController) and shows the
/// latest result snapshot live, coloured by the field chosen in the Run toolbar and drawn
/// deformed by its scale factor. After a run the Steps dock replays the saved steps, the Plots
/// dock plots the history, and File ▸ Export writes the picture, the steps or the history.

#include "Preprocess.hpp"
#include "document/ModelItems.hpp"
#include "run/ResultSnapshot.hpp"
#include "run/RunController.hpp"
#include "run/RunOutput.hpp"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QString>

#include <memory>
#include <vector>

class QAction;
class QMenu;
class QLabel;
class QPlainTextEdit;
class QDockWidget;
class QComboBox;
class QDoubleSpinBox;
class QProgressBar;
class QThread;
template <typename T>
class QFutureWatcher;

namespace mcdda::gui {

class ModelView;
class StepSlider;
class HistoryPlot;
class ModelDocument;
class DrawTool;
class PropertyEditor;
class SelectTool;
class EditingTools;
class ModelTree;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Pre-processes the model file at `path` and shows it. Returns false when that reported
    /// errors: they are listed in the Messages dock and summarised in a (non-blocking) message
    /// box; whatever could be read is still drawn. The work runs on the thread pool; the window
    /// keeps painting (input waits) until it is done. False at once while another file loads.
    bool openModel(const QString& path);
    /// Whether a model file is being read and meshed (openModel on the stack).
    bool isLoading() const { return loading_; }

    /// Shows an already pre-processed model; `source` names it in the title and messages.
    /// The camera is fitted unless `keep_camera` is set.
    void showPreprocessed(std::shared_ptr<const Preprocessed> p, const QString& source,
                          bool keep_camera = false);

    ModelView* modelView() const { return view_; }
    /// The model being edited (what the view shows).
    ModelDocument* document() const { return document_; }
    /// The Model dock's tree.
    ModelTree* modelTree() const { return tree_; }
    /// The Select tool (always there; active when no drawing tool is).
    SelectTool* selectionTool() const;
    /// The selected item or vertex (invalid when none).
    ItemRef selection() const;
    /// The Properties dock's forms.
    PropertyEditor* propertyEditor() const { return property_editor_; }
    /// Whether the document is being pre-processed again after an edit (on the thread pool;
    /// the view shows the previous picture meanwhile).
    bool isPreprocessing() const { return requested_ != 0; }
    /// The active drawing tool (null for Select).
    DrawTool* activeTool() const;
    /// Grid snapping of the drawing tools (View ▸ Snap to Grid) and its spacing (m).
    void setGridSpacing(double metres);
    double gridSpacing() const { return grid_spacing_; }
    /// Whether closing, New or Open ask before unsaved changes are lost (default true);
    /// false discards them silently (for tests).
    void setAskToSave(bool ask) { ask_to_save_ = ask; }
    /// File ▸ Save As without its dialog: writes the document to `path`.
    bool saveModelAs(const QString& path);
    /// The Recent Files list (newest first).
    QStringList recentFiles() const;
    /// The file shown, empty when none was opened.
    QString modelPath() const { return path_; }
    /// The text of the Messages dock.
    QString messages() const;
    /// The mesh figures in the status bar.
    QString statisticsText() const;
    /// The cursor position (and the result value under it) in the status bar.
    QString cursorText() const;

    /// Whether an analysis is running (possibly paused).
    bool isRunning() const { return controller_ != nullptr; }
    /// Folder the next run writes its files to; empty = the default, <model>-results next to
    /// the model file.
    void setRunOutputFolder(const QString& folder) { output_folder_ = folder; }
    /// The folder the current or next run writes to.
    QString runOutputFolder() const;
    /// Minimum intervals between progress and snapshot updates of the next runs (ms).
    void setRunThrottle(int progress_ms, int snapshot_ms);
    /// The field shown while and after running: one of view::result_field_names().
    QString resultField() const;
    void setResultField(const QString& field);
    /// Scale factor of the drawn displacements (0 = undeformed).
    double deformFactor() const;
    void setDeformFactor(double factor);
    /// The results folder of the last finished run (empty before one), and its files.
    QString resultsFolder() const { return results_folder_; }
    QString resultsPvdPath() const;
    QString resultsHistoryPath() const;
    StepSlider* stepSlider() const { return steps_; }
    /// The saved step the picture shows (empty: the model, or the run's latest state).
    QString shownStep() const { return shown_step_; }
    HistoryPlot* historyPlot() const { return plot_; }

    /// The File ▸ Export actions without their dialogs; errors go to a message box and give false.
    bool exportPng(const QString& path);
    bool exportSteps(const QString& folder);
    bool exportHistory(const QString& path);

public slots:
    /// File ▸ New: an empty model with a default material and joint material.
    void newModel();
    /// File ▸ Save (Save As when the model has no file yet).
    bool save();
    /// File ▸ Save As: asks for a file.
    bool saveAsDialog();
    /// Edit ▸ tools: select/move (and navigate), drawing regions, drawing joints.
    void selectTool();
    /// Makes Select the tool and selects `ref` in the view and the tree.
    void selectItem(const ItemRef& ref);
    /// Edit ▸ Delete: deletes `ref` (undoable); false with a message when it cannot go.
    bool deleteSelection(const ItemRef& ref);
    void drawRegionTool();
    void drawJointTool();
    /// Edit ▸ tools for supports, loads and measurement points: Fixed Point (click), Roller
    /// (two clicks; fixed directions from the Tool Options bar), Point Load (click; force from
    /// the bar, default (0, −1) kN/m), Edge Pressure (two clicks; default 100 kPa), Measurement
    /// Point (click; named "point N").
    void fixedPointTool();
    void rollerTool();
    void pointLoadTool();
    void edgePressureTool();
    void measurementPointTool();
    /// Edit ▸ Add Joint Set: asks for a joint set and adds it (undoable).
    void addJointSetDialog();
    /// The Tool Options' coordinate field: "x, y" (metres) places a vertex there as a click
    /// does; empty text finishes the shape (as Enter in the view). False when no drawing tool
    /// is active or the text is not two numbers.
    bool enterCoordinates(const QString& text);
    /// Run ▸ Mesh: cuts and meshes the document on the thread pool (as an edit does) and shows
    /// the mesh; false while a run or a file load is going on.
    bool meshModel();
    /// Run ▸ Run: analyses the shown model on a worker thread. False when there is no usable
    /// model or a run is going on.
    bool startRun();
    /// Run ▸ Pause / Resume.
    void togglePause();
    /// Run ▸ Stop: the run ends after the current step (finished with Cancelled).
    void stopRun();
    /// File ▸ Open: asks for a *.json model.
    void openDialog();
    /// File ▸ Reload: reads the current file again, keeping the view.
    void reload();

signals:
    /// A run reported progress (throttled) / ended.
    void runProgressed(const mcdda::gui::RunProgress& progress);
    void runFinished(mcdda::RunStatus status, const QString& message);
    /// Inside a long step: its iterations so far (the status bar shows them).
    void runIterating(const mcdda::IterationInfo& info);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createEditActions();
    /// Pre-processes the document on the thread pool (a newer request supersedes it).
    void startPreprocess();
    void onPreprocessed();
    void createModelDock();
    void refreshModelTree();
    void refreshRecentMenu();
    void addRecentFile(const QString& path);
    void updateTitle();
    /// The document changed: pre-processes it again and shows it, keeping the camera.
    void onDocumentChanged();
    /// Shows a pre-processed model; `interactive` reports failures in a message box.
    void showScene(std::shared_ptr<const Preprocessed> p, const QString& source, bool keep_camera,
                   bool interactive);
    /// Asks whether to save unsaved changes; false when the user cancelled.
    bool maybeSave();
    void onSelectionChanged(const ItemRef& ref);
    void applySnap();
    void createDock();
    void createStatusBar();
    void createResultDocks();
    void createExportActions(QMenu* file);
    /// Reads the results folder again into the step slider and the plot.
    void refreshResults();
    void showStep(const QString& vtu_path);
    void reportExportError(const QString& message);
    void applySceneOptions();
    void showCursor(const QPointF& model_pos);
    void reportFailure(const Preprocessed& p, const QString& source);
    bool load(const QString& path, bool keep_camera);
    void createRunActions();
    void updateRunActions();
    void onRunProgress(const RunProgress& progress);
    void onRunSnapshot(std::shared_ptr<const ResultSnapshot> snapshot);
    void onRunIterating(const IterationInfo& info);
    /// Shows a document compiled into the program (":/docs/…md") in a window of its own.
    void showDocument(const QString& title, const QString& resource);
    void onRunFinished(RunStatus status, const QString& message);
    void showResult();
    void log(const QString& line);
    /// Stops the run if one is going on and joins its thread.
    void joinRun();

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
    QAction* run_action_ = nullptr;
    QAction* mesh_action_ = nullptr;
    QAction* pause_action_ = nullptr;
    QAction* stop_action_ = nullptr;
    QComboBox* field_box_ = nullptr;
    QDoubleSpinBox* deform_box_ = nullptr;
    StepSlider* steps_ = nullptr;
    HistoryPlot* plot_ = nullptr;
    QDockWidget* steps_dock_ = nullptr;
    QDockWidget* plot_dock_ = nullptr;
    QString results_folder_;  ///< of the last finished run
    QString results_stem_;
    QString shown_step_;      ///< saved step chosen in the slider; empty = the last snapshot
    bool looking_back_ = false;  ///< during a run: an earlier saved step is shown, not the live state
    QProgressBar* progress_bar_ = nullptr;
    QThread* run_thread_ = nullptr;
    RunController* controller_ = nullptr;
    std::shared_ptr<const ResultSnapshot> last_snapshot_;
    QElapsedTimer plot_clock_;  ///< since the plot last re-read the running history
    QString output_folder_;  ///< chosen by the user; empty = default
    QString running_folder_;  ///< of the current run
    int progress_ms_ = 100, snapshot_ms_ = 250;
    QString path_;
    QString last_folder_;
    ModelDocument* document_ = nullptr;
    bool syncing_ = false;  ///< the document is being set from an already pre-processed model
    bool ask_to_save_ = true;
    bool loading_ = false;
    bool close_after_load_ = false;
    ModelTree* tree_ = nullptr;
    EditingTools* editing_ = nullptr;  ///< tools, tool options, selection

    QDockWidget* model_dock_ = nullptr;
    QMenu* recent_menu_ = nullptr;
    QMenu* help_menu_ = nullptr;
    QAction* snap_action_ = nullptr;
    PropertyEditor* property_editor_ = nullptr;
    QDockWidget* property_dock_ = nullptr;
    QFutureWatcher<std::shared_ptr<Preprocessed>>* preprocess_ = nullptr;
    unsigned long generation_ = 0;  ///< counts model changes
    unsigned long requested_ = 0;   ///< generation waiting for its picture; 0 = none
    unsigned long running_ = 0;     ///< generation being pre-processed
    double grid_spacing_ = 0.5;
};

}  // namespace mcdda::gui
