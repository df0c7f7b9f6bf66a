#include "session/RunSession.hpp"

#include <QDir>
#include <QFileInfo>
#include <QThread>

namespace mcdda::gui {

RunSession::RunSession(QObject* parent) : QObject(parent) { register_run_types(); }

RunSession::~RunSession() { join(); }

QString RunSession::runFolder() const
{
    if (isRunning()) return running_folder_;
    if (!output_folder_.isEmpty()) return output_folder_;
    if (source_path_.isEmpty()) return QDir::current().absoluteFilePath(QStringLiteral("model-results"));
    const QFileInfo info(source_path_);
    return info.absoluteDir().absoluteFilePath(info.completeBaseName() + QStringLiteral("-results"));
}

QString RunSession::stem() const
{
    if (isRunning()) return running_stem_;
    return source_path_.isEmpty() ? QStringLiteral("model") : QFileInfo(source_path_).completeBaseName();
}

void RunSession::setThrottle(int progress_ms, int snapshot_ms)
{
    progress_ms_ = progress_ms;
    snapshot_ms_ = snapshot_ms;
}

bool RunSession::start(const Preprocessed& model)
{
    if (isRunning() || !model.ok) return false;
    running_folder_ = runFolder();
    running_stem_ = stem();
    controller_ = new RunController(model, running_folder_, running_stem_);
    controller_->setThrottle(progress_ms_, snapshot_ms_);
    thread_ = new QThread(this);
    thread_->setObjectName(QStringLiteral("mcdda-run"));
    controller_->moveToThread(thread_);
    connect(thread_, &QThread::started, controller_, &RunController::start);
    // Queued calls from a controller already joined may still arrive: each carries its run.
    RunController* run = controller_;
    connect(controller_, &RunController::progress, this, [this, run](const RunProgress& p) {
        if (controller_ == run) emit progress(p);
    }, Qt::QueuedConnection);
    connect(controller_, &RunController::iterating, this, [this, run](const IterationInfo& info) {
        if (controller_ == run) emit iterating(info);
    }, Qt::QueuedConnection);
    connect(controller_, &RunController::trialStarted, this, [this, run](double factor) {
        if (controller_ == run) emit trialStarted(factor);
    }, Qt::QueuedConnection);
    connect(controller_, &RunController::trialFinished, this, [this, run](const StrengthTrial& trial) {
        if (controller_ == run) emit trialFinished(trial);
    }, Qt::QueuedConnection);
    connect(controller_, &RunController::factorOfSafety, this, [this, run](const FactorOfSafety& factor) {
        if (controller_ == run) emit factorOfSafety(factor);
    }, Qt::QueuedConnection);
    connect(controller_, &RunController::snapshot, this, [this, run](std::shared_ptr<const ResultSnapshot> s) {
        if (controller_ == run) onSnapshot(std::move(s));
    }, Qt::QueuedConnection);
    connect(controller_, &RunController::finished, this, [this, run](RunStatus status, const QString& message) {
        if (controller_ == run) onFinished(status, message);
    }, Qt::QueuedConnection);

    last_snapshot_.reset();
    files_clock_.invalidate();
    planned_steps_ = model.model.stages.empty() ? model.model.analysis.steps : 0;
    for (const Stage& stage : model.model.stages) planned_steps_ += stage.analysis.steps;
    emit started(planned_steps_, running_folder_);
    thread_->start();
    return true;
}

void RunSession::togglePause()
{
    if (!isRunning()) return;
    if (controller_->isPaused())
        controller_->resume();
    else
        controller_->pause();
    emit pausedChanged(controller_->isPaused());
}

void RunSession::stop()
{
    if (isRunning()) controller_->stop();  // thread-safe
}

void RunSession::abandon() { join(); }

QString RunSession::resultsPvdPath() const
{
    if (results_folder_.isEmpty()) return {};
    return QDir(results_folder_).absoluteFilePath(results_stem_ + QStringLiteral(".pvd"));
}

QString RunSession::resultsHistoryPath() const
{
    if (results_folder_.isEmpty()) return {};
    return QDir(results_folder_).absoluteFilePath(QStringLiteral("history.csv"));
}

void RunSession::clearResults()
{
    results_folder_.clear();
    results_stem_.clear();
    last_snapshot_.reset();
}

void RunSession::onSnapshot(std::shared_ptr<const ResultSnapshot> snapshot)
{
    last_snapshot_ = snapshot;
    emit this->snapshot(std::move(snapshot));
    // Re-reading the files costs more the longer the run: about once a second, whatever the
    // snapshot rate.
    if (!files_clock_.isValid() || files_clock_.elapsed() >= 1000) {
        const QDir folder(running_folder_);
        emit filesGrew(folder.absoluteFilePath(running_stem_ + QStringLiteral(".pvd")),
                       folder.absoluteFilePath(QStringLiteral("history.csv")));
        files_clock_.restart();
    }
}

void RunSession::onFinished(RunStatus status, const QString& message)
{
    join();
    results_folder_ = running_folder_;
    results_stem_ = running_stem_;
    planned_steps_ = 0;
    emit finished(status, message);
}

void RunSession::join()
{
    if (thread_ == nullptr) return;
    controller_->stop();
    controller_->resume();  // a paused run must wake up to see the stop
    thread_->quit();        // takes effect once start() has returned
    thread_->wait();
    delete controller_;  // its thread has ended: safe from here
    controller_ = nullptr;
    delete thread_;
    thread_ = nullptr;
}

}  // namespace mcdda::gui
