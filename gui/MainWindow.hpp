#pragma once
/// \file MainWindow.hpp
/// The desktop program's main window: the wiring between the model document, the view, the docks
/// and menus, and the logic that runs without widgets (session/: RunSession runs the analysis on
/// a worker thread, PreprocessScheduler cuts and meshes after edits). It opens a model file,
/// pre-processes it and shows it; Run ▸ Run shows the latest result snapshot live, coloured as
/// the Results toolbar says. After a run the Steps dock replays the saved steps, the Plots dock
/// plots the history, and File ▸ Export writes the picture, the steps or the history.

#include "Preprocess.hpp"
#include "document/ModelItems.hpp"
#include "session/RunController.hpp"
#include "view/ResultSnapshot.hpp"

#include <QMainWindow>
#include <QString>

#include <memory>
#include <vector>

class QDockWidget;
class QMenu;

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
class MessageLog;
class PreprocessScheduler;
class RunSession;
class ResultToolBar;
class RecentFilesMenu;
class ExportMenu;
class ViewMenu;
class RunMenu;
class WindowStatusBar;
class QueryPlot;
class EarthquakePanel;

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
    /// File ▸ Import DXF: a new model made of the drawing at `path` (asks for one when empty).
    bool importDxf(const QString& path);
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
    /// The Edit menu's tools, their options and the selection.
    EditingTools* editingTools() const { return editing_; }
    /// The selected item or vertex (invalid when none).
    ItemRef selection() const;
    /// The Properties dock's forms.
    PropertyEditor* propertyEditor() const { return property_editor_; }
    /// Whether the document is being pre-processed again after an edit (on the thread pool;
    /// the view shows the previous picture meanwhile).
    bool isPreprocessing() const;
    /// The active drawing tool (null for Select).
    DrawTool* activeTool() const;
    /// Grid snapping of the drawing tools (View ▸ Snap to Grid) and its spacing (m).
    void setGridSpacing(double metres);
    double gridSpacing() const { return grid_spacing_; }
    /// Whether closing, New or Open ask before unsaved changes are lost, and whether running a
    /// model never saved asks where its results go (default true); false discards changes
    /// silently and runs an untitled model into a new temporary folder (for tests).
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
    bool isRunning() const;
    /// Folder the next run writes its files to; empty = the default, <model>-results next to
    /// the model file.
    void setRunOutputFolder(const QString& folder);
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
    QString resultsFolder() const;
    QString resultsPvdPath() const;
    QString resultsHistoryPath() const;
    StepSlider* stepSlider() const { return steps_; }
    /// The saved step the picture shows (empty: the model, or the run's latest state).
    QString shownStep() const { return shown_step_; }
    HistoryPlot* historyPlot() const { return plot_; }
    /// The factor of safety of the last strength reduction run as the status bar shows it
    /// ("Factor of safety 1.547"); empty after any other run or before one.
    QString factorOfSafetyText() const;
    /// The Earthquake dock: ground motions, the base they shake, the seismic coefficient.
    EarthquakePanel* earthquakePanel() const { return earthquake_; }
    /// The Query dock: the field along a line drawn with Edit ▸ Query Line.
    QueryPlot* queryPlot() const { return query_; }
    /// The run and its files, and the background pre-processing (the window's logic).
    RunSession* runSession() const { return session_; }
    PreprocessScheduler* preprocessScheduler() const { return scheduler_; }

    /// File ▸ Export: its dialogs suggest file names from the model and what the picture shows.
    ExportMenu* exportMenu() const;
    /// The model's name for file names: its file's base name, else the results' stem ("model").
    QString modelStem() const;
    /// What the result picture shows as part of a file name ("stress_1-step10"); empty for the
    /// model picture.
    QString shownResultName() const;
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
    /// Makes Select the tool and selects `ref` in the view and the tree.
    void selectItem(const ItemRef& ref);
    /// Edit ▸ Draw Region (the other tools: editingTools()).
    void drawRegionTool();
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
    void createDocks();
    /// A dock of `widget`; a tab behind `tab_of` when given.
    QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area,
                         QDockWidget* tab_of = nullptr);
    void createActions();
    void createRunActions();
    void connectRunSession();
    void refreshModelTree();
    void updateTitle();
    /// The model file shown (empty: none): Reload, the title, the results folder follow it.
    void setModelFile(const QString& path);
    /// The document changed: pre-processes it again and shows it, keeping the camera.
    void onDocumentChanged();
    /// Shows a pre-processed model; `interactive` reports failures in a message box.
    void showScene(std::shared_ptr<const Preprocessed> p, const QString& source, bool keep_camera,
                   bool interactive);
    /// Asks whether to save unsaved changes; false when the user cancelled.
    bool maybeSave();
    void onSelectionChanged(const ItemRef& ref);
    void applySnap();
    /// Clears the query line and its plot (another model is shown).
    void forgetQueryLine();
    /// Before running a model never saved and without a results folder chosen: asks whether to
    /// save it first or run into a new temporary folder (said in the log). False: cancelled.
    bool chooseUntitledResults();
    /// The untitled model's temporary results folder is no longer the next run's.
    void forgetUntitledResults();
    void showStep(const QString& vtu_path);
    void reportExportError(const QString& message);
    void showCursor(const QPointF& model_pos);
    void reportFailure(const Preprocessed& p, const QString& source);
    bool load(const QString& path, bool keep_camera);
    void updateRunActions();
    void onRunFinished(RunStatus status, const QString& message);
    /// Draws the result chosen: a saved step, or the run's latest snapshot.
    void showResult();
    void log(const QString& line);

    ModelView* view_ = nullptr;
    ModelDocument* document_ = nullptr;
    PreprocessScheduler* scheduler_ = nullptr;
    RunSession* session_ = nullptr;
    EditingTools* editing_ = nullptr;  ///< tools, tool options, selection
    MessageLog* messages_ = nullptr;
    ModelTree* tree_ = nullptr;
    PropertyEditor* property_editor_ = nullptr;
    StepSlider* steps_ = nullptr;
    HistoryPlot* plot_ = nullptr;
    QDockWidget* messages_dock_ = nullptr;
    QDockWidget* model_dock_ = nullptr;
    QDockWidget* steps_dock_ = nullptr;
    QDockWidget* plot_dock_ = nullptr;
    QDockWidget* query_dock_ = nullptr;
    QDockWidget* stages_dock_ = nullptr;
    QDockWidget* earthquake_dock_ = nullptr;
    EarthquakePanel* earthquake_ = nullptr;
    QueryPlot* query_ = nullptr;
    QDockWidget* property_dock_ = nullptr;
    WindowStatusBar* status_bar_ = nullptr;
    QAction* reload_action_ = nullptr;
    RecentFilesMenu* recent_menu_ = nullptr;
    ExportMenu* export_menu_ = nullptr;
    ViewMenu* view_menu_ = nullptr;
    RunMenu* run_menu_ = nullptr;
    QMenu* help_menu_ = nullptr;
    ResultToolBar* result_bar_ = nullptr;
    QString shown_step_;         ///< saved step chosen in the slider; empty = the last snapshot
    bool looking_back_ = false;  ///< during a run: an earlier saved step is shown, not the live state
    int trials_ = 0;             ///< strength reduction trials started in the current run
    bool factor_found_ = false;  ///< the current or last run found a factor of safety
    QString path_;
    QString last_folder_;
    QString untitled_results_;  ///< the temporary results folder of the untitled model shown
    bool syncing_ = false;  ///< the document is being set from an already pre-processed model
    bool ask_to_save_ = true;
    bool loading_ = false;
    bool close_after_load_ = false;
    double grid_spacing_ = 0.5;
};

}  // namespace mcdda::gui
