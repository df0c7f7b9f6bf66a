#include "session/RunController.hpp"

#include "run/RunLoop.hpp"
#include "run/Simulation.hpp"
#include "run/StrengthReduction.hpp"

#include <QElapsedTimer>

#include <chrono>
#include <exception>
#include <optional>
#include <string>

namespace mcdda::gui {

void register_run_types()
{
    qRegisterMetaType<mcdda::gui::RunProgress>();
    qRegisterMetaType<std::shared_ptr<const mcdda::ResultSnapshot>>();
    qRegisterMetaType<mcdda::RunStatus>();
    qRegisterMetaType<mcdda::IterationInfo>();
    qRegisterMetaType<mcdda::StrengthTrial>();
    qRegisterMetaType<mcdda::FactorOfSafety>();
}

RunController::RunController(const Preprocessed& model, QString output_folder, QString stem, QObject* parent)
    : QObject(parent),
      model_(std::make_shared<const Preprocessed>(model)),
      output_folder_(std::move(output_folder)),
      stem_(stem.isEmpty() ? QStringLiteral("model") : std::move(stem))
{
    register_run_types();
}

RunController::~RunController() = default;

void RunController::setThrottle(int progress_ms, int snapshot_ms)
{
    progress_ms_ = progress_ms;
    snapshot_ms_ = snapshot_ms;
}

void RunController::pause()
{
    paused_ = true;
}

void RunController::resume()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        paused_ = false;
    }
    wake_.notify_all();
}

void RunController::stop()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
}

bool RunController::waitWhilePaused()
{
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait(lock, [this] { return !paused_ || stop_; });
    return !stop_;
}

void RunController::start()
{
    const Preprocessed& p = *model_;
    std::unique_ptr<RunOutput> output;
    std::unique_ptr<Simulation> plain;
    std::unique_ptr<StrengthReductionSearch> search;
    try {
        if (!p.ok) throw std::runtime_error("the model has errors: it cannot be run");
        // Set up before the output folder is touched: a run refused here leaves earlier
        // results in the folder as they were.
        if (is_strength_reduction(p.model)) search = std::make_unique<StrengthReductionSearch>(p);
        else plain = std::make_unique<Simulation>(p);
        if (!output_folder_.isEmpty())
            output = std::make_unique<RunOutput>(output_folder_.toStdString(), stem_.toStdString());
    } catch (const std::exception& e) {
        emit finished(RunStatus::Failed, QString::fromStdString(e.what()));
        return;
    }
    // The simulation in use: a search replaces its own with every trial of a whole model.
    auto simulation = [&]() -> const Simulation& { return search ? search->simulation() : *plain; };

    const int steps = simulation().planned_steps();
    RunStatus status = RunStatus::Completed;
    std::string message;
    QElapsedTimer progress_clock, snapshot_clock;
    std::optional<RunProgress> unsent;  // the latest progress not sent yet (throttled)
    bool snapshot_unsent = false;
    auto send_snapshot = [&] {
        emit snapshot(std::make_shared<const ResultSnapshot>(ResultSnapshot::of(simulation())));
        snapshot_clock.restart();
        snapshot_unsent = false;
    };
    QElapsedTimer iteration_clock;
    auto on_iteration = [&](const IterationInfo& info) {
        if (iteration_clock.isValid() && iteration_clock.elapsed() < progress_ms_) return;
        iteration_clock.restart();
        emit iterating(info);
    };
    auto on_step = [&](const StepReport& report) {
        RunProgress info;
        info.step = report.step;
        info.total_steps = steps;
        info.time = report.time;
        info.time_step = report.time_step;
        info.open = report.open;
        info.sliding = report.sliding;
        info.locked = report.locked;
        info.plastic_iterations = report.plastic_iterations;
        info.yielding = report.yielding;
        info.load_steps = !has_dynamic_stage(p.model);
        unsent = info;
        snapshot_unsent = true;
        if (!progress_clock.isValid() || progress_clock.elapsed() >= progress_ms_) {
            emit progress(*unsent);
            unsent.reset();
            progress_clock.restart();
        }
        if (snapshot_clock.elapsed() >= snapshot_ms_) send_snapshot();
    };
    auto should_stop = [this] { return stop_ || (paused_ && !waitWhilePaused()); };
    try {
        send_snapshot();
        RunEnd end;
        if (search) {
            StrengthReductionSearch::Callbacks callbacks;
            callbacks.should_stop = should_stop;
            callbacks.on_step = on_step;
            callbacks.on_iteration = on_iteration;
            callbacks.on_trial_start = [this](double factor) { emit trialStarted(factor); };
            callbacks.on_trial = [&](const StrengthTrial& trial) {
                if (unsent) emit progress(*unsent);  // the construction stages' last step
                unsent.reset();
                send_snapshot();  // every trial's end state, whatever the throttle: one per trial
                emit trialFinished(trial);
            };
            end = search->run(output.get(), callbacks);
        } else {
            plain->set_iteration_observer(on_iteration);
            end = run_steps(*plain, output.get(), should_stop, on_step);
        }
        status = end.status;
        // finished() carries no message for a completed run.
        if (status != RunStatus::Completed) message = end.message;
        else if (search) message = end.message;  // the factor of safety, in words
    } catch (const std::exception& e) {  // writing the results failed
        status = RunStatus::Failed;
        message = std::string("cannot write the results: ") + e.what();
    }
    if (unsent) emit progress(*unsent);
    if (snapshot_unsent) send_snapshot();
    if (output) {
        try {
            output->write_summary(&simulation(), status, message.empty() ? "completed" : message,
                                  search ? &search->factor() : nullptr);
        } catch (const std::exception& e) {
            if (status == RunStatus::Completed) status = RunStatus::Failed;
            message += (message.empty() ? "" : "; ") + std::string("cannot write the summary: ") + e.what();
        }
    }
    if (output && status != RunStatus::Completed && status != RunStatus::Collapsed && !output->kept_results().empty())
        message += (message.empty() ? "" : "; ") + std::string("the earlier results are kept in ") + output->kept_results();
    if (search) emit factorOfSafety(search->factor());
    emit finished(status, QString::fromStdString(message));
}

}  // namespace mcdda::gui
