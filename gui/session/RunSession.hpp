#pragma once
/// \file RunSession.hpp
/// One analysis at a time for the desktop program, without widgets (Qt Core only, so it is
/// tested without a screen): the worker thread and its RunController, where the files go
/// (<model>-results next to the model file unless a folder was chosen), the throttling of
/// progress and snapshots, the latest snapshot, and the results folder of the last finished
/// run. The window connects its signals to the picture, the log and the docks (the logic and
/// widget split of 3D Slicer's modules).

#include "Preprocess.hpp"
#include "session/RunController.hpp"
#include "view/ResultSnapshot.hpp"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <memory>

class QThread;

namespace mcdda::gui {

class RunSession : public QObject {
    Q_OBJECT

public:
    explicit RunSession(QObject* parent = nullptr);
    /// Stops a run going on and waits for its thread.
    ~RunSession() override;

    /// The model file being shown: names the default results folder and the files' stem.
    /// Empty: "model" in the current directory.
    void setSourcePath(const QString& path) { source_path_ = path; }
    /// The folder chosen for the results of the next runs; empty = <model>-results beside the
    /// model file.
    void setOutputFolder(const QString& folder) { output_folder_ = folder; }
    /// The folder chosen (empty: none, the default applies).
    QString outputFolder() const { return output_folder_; }
    /// The folder the current run writes to or, between runs, the next run will.
    QString runFolder() const;
    /// The name of the .pvd and .vtu files (the model file's base name, or "model").
    QString stem() const;

    /// Minimum intervals between progress and snapshot updates of the next runs (ms).
    void setThrottle(int progress_ms, int snapshot_ms);

    /// Starts analysing `model` (copied) on a worker thread. False when one is running or the
    /// model has errors.
    bool start(const Preprocessed& model);
    bool isRunning() const { return controller_ != nullptr; }
    bool isPaused() const { return controller_ != nullptr && controller_->isPaused(); }
    /// The steps the run plans (its stages' sum); 0 between runs.
    int plannedSteps() const { return planned_steps_; }
    /// Pause and resume (a paused run waits between steps).
    void togglePause();
    /// The run ends after the current step; finished(Cancelled) follows.
    void stop();
    /// Stops a run going on at once and waits for its thread; no finished() is sent.
    void abandon();

    /// The latest state of the run (or of the last one); null before any.
    std::shared_ptr<const ResultSnapshot> lastSnapshot() const { return last_snapshot_; }
    /// The results folder of the last finished run; empty before one or after clearResults().
    QString resultsFolder() const { return results_folder_; }
    /// Its .pvd collection and history (empty without a finished run).
    QString resultsPvdPath() const;
    QString resultsHistoryPath() const;
    /// Forgets the last results (another model is shown).
    void clearResults();

signals:
    void started(int planned_steps, const QString& folder);
    void progress(const mcdda::gui::RunProgress& progress);
    void snapshot(std::shared_ptr<const mcdda::ResultSnapshot> snapshot);
    void iterating(const mcdda::IterationInfo& info);
    /// A strength reduction analysis: each trial's start and end, and the search's result
    /// (just before finished()).
    void trialStarted(double factor);
    void trialFinished(const mcdda::StrengthTrial& trial);
    void factorOfSafety(const mcdda::FactorOfSafety& factor);
    /// While running, about once a second: the .pvd collection and history.csv have grown
    /// (a row per step, a step per save) and can be read again for a live plot and step list.
    void filesGrew(const QString& pvd_path, const QString& history_path);
    void pausedChanged(bool paused);
    /// The run ended (thread joined, results folder set); `message` says why unless it completed.
    void finished(mcdda::RunStatus status, const QString& message);

private:
    void onSnapshot(std::shared_ptr<const ResultSnapshot> snapshot);
    void onFinished(RunStatus status, const QString& message);
    /// Stops the controller, waits for the thread and deletes both.
    void join();

    QString source_path_;
    QString output_folder_;
    QString running_folder_;
    QString running_stem_;
    QString results_folder_;
    QString results_stem_;
    int progress_ms_ = 100, snapshot_ms_ = 250;
    int planned_steps_ = 0;
    QThread* thread_ = nullptr;
    RunController* controller_ = nullptr;
    std::shared_ptr<const ResultSnapshot> last_snapshot_;
    QElapsedTimer files_clock_;  ///< since filesGrew was last sent
};

}  // namespace mcdda::gui
