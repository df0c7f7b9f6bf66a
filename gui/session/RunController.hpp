#pragma once
/// \file RunController.hpp
/// Runs the solver for the desktop program (docs/architecture.md): a QObject moved to its own QThread
/// that owns the Simulation. Between steps it checks a stop token and a pause flag; it publishes
/// progress (at most about 10 a second, always the latest) and immutable result snapshots (at
/// most about 4 a second, always the last step) through queued signals, and writes the run's
/// files with RunOutput so that results stay on disk whatever the ending. A strength reduction
/// analysis runs its search (run/StrengthReduction.hpp) and reports each trial as it ends.

#include "Preprocess.hpp"
#include "view/ResultSnapshot.hpp"
#include "run/FactorOfSafety.hpp"
#include "run/RunOutput.hpp"

#include <QMetaType>
#include <QObject>
#include <QString>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>

namespace mcdda::gui {

/// What the last accepted step did (a copy of the solver's StepReport, plus the total).
struct RunProgress {
    int step = 0;
    int total_steps = 0;
    double time = 0.0;       ///< s
    double time_step = 0.0;  ///< Δt of the step (s)
    int open = 0, sliding = 0, locked = 0;  ///< contacts
    int plastic_iterations = 0;
    int yielding = 0;  ///< elements yielding in the step
    /// No stage is dynamic: the steps are load steps and their time only orders them, so the
    /// log leaves it out.
    bool load_steps = false;
};

class RunController : public QObject {
    Q_OBJECT

public:
    /// `model` must be pre-processed without errors; it is copied. When `output_folder` is not
    /// empty the run's files (<stem>.pvd, .vtu, history.csv, summary.json) are written there.
    RunController(const Preprocessed& model, QString output_folder, QString stem, QObject* parent = nullptr);
    ~RunController() override;

    /// Minimum intervals between two progress signals and two snapshot signals (ms).
    void setThrottle(int progress_ms, int snapshot_ms);

    bool isPaused() const { return paused_; }
    QString outputFolder() const { return output_folder_; }

public slots:
    /// Runs the analysis to its end, a stop, a collapse or a failure; emits finished() last.
    /// Meant to run on the worker thread (e.g. connected to QThread::started).
    void start();
    /// These three are thread-safe: call them directly from any thread (the worker's event
    /// loop is busy inside start()). They take effect between steps.
    void pause();
    void resume();
    void stop();

signals:
    void progress(const mcdda::gui::RunProgress& progress);
    void snapshot(std::shared_ptr<const mcdda::ResultSnapshot> snapshot);
    /// Inside a step: its equilibrium iterations so far (throttled like progress), so that a
    /// long step is not silent.
    void iterating(const mcdda::IterationInfo& info);
    /// A strength reduction analysis: a trial with the strengths divided by `factor` starts,
    /// and one ended (a snapshot of its state was sent before); at the end, before finished(),
    /// the factor of safety the search found (or how far it got).
    void trialStarted(double factor);
    void trialFinished(const mcdda::StrengthTrial& trial);
    void factorOfSafety(const mcdda::FactorOfSafety& factor);
    /// The run ended; `message` says why unless it completed. Results up to the last
    /// accepted step are kept (last snapshot sent, files written).
    void finished(mcdda::RunStatus status, const QString& message);

private:
    /// Waits while paused; returns false when a stop was asked for.
    bool waitWhilePaused();

    std::shared_ptr<const Preprocessed> model_;
    QString output_folder_;
    QString stem_;
    int progress_ms_ = 100;
    int snapshot_ms_ = 250;
    std::atomic<bool> stop_{false};
    std::atomic<bool> paused_{false};
    std::mutex mutex_;
    std::condition_variable wake_;
};

/// Registers the signal argument types for queued connections (done by the constructor too).
void register_run_types();

}  // namespace mcdda::gui

Q_DECLARE_METATYPE(mcdda::gui::RunProgress)
Q_DECLARE_METATYPE(std::shared_ptr<const mcdda::ResultSnapshot>)
Q_DECLARE_METATYPE(mcdda::RunStatus)
Q_DECLARE_METATYPE(mcdda::IterationInfo)
Q_DECLARE_METATYPE(mcdda::StrengthTrial)
Q_DECLARE_METATYPE(mcdda::FactorOfSafety)
