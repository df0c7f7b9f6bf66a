#include "session/PreprocessScheduler.hpp"

#include <QEventLoop>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>

namespace mcdda::gui {

namespace {

/// Bad input comes back as diagnostics; this turns anything unforeseen into one as well.
std::shared_ptr<Preprocessed> failed(const std::exception& e, const Model* model)
{
    auto p = std::make_shared<Preprocessed>();
    Diagnostic d;
    d.message = e.what();
    p->diagnostics.push_back(d);
    if (model) p->model = *model;
    p->ok = false;
    return p;
}

}  // namespace

PreprocessScheduler::PreprocessScheduler(QObject* parent)
    : QObject(parent), watcher_(new QFutureWatcher<std::shared_ptr<Preprocessed>>(this))
{
    connect(watcher_, &QFutureWatcherBase::finished, this, &PreprocessScheduler::onFinished);
}

PreprocessScheduler::~PreprocessScheduler()
{
    wanted_ = 0;
    watcher_->waitForFinished();
}

void PreprocessScheduler::request(const Model& model)
{
    next_ = model;
    const bool was_busy = isBusy();
    wanted_ = ++requests_;
    // One computation at a time: a newer request waits for the running one and supersedes it.
    if (!watcher_->isRunning()) startNext();
    if (!was_busy) emit busyChanged(true);
}

void PreprocessScheduler::drop()
{
    const bool was_busy = isBusy();
    wanted_ = 0;
    if (was_busy) emit busyChanged(false);
}

void PreprocessScheduler::waitForFinished() { watcher_->waitForFinished(); }

void PreprocessScheduler::startNext()
{
    computing_ = wanted_;
    watcher_->setFuture(QtConcurrent::run([model = next_] {
        try {
            return std::make_shared<Preprocessed>(preprocess_model(model, PreprocessStage::Mesh));
        } catch (const std::exception& e) {
            return failed(e, &model);
        }
    }));
}

void PreprocessScheduler::onFinished()
{
    if (wanted_ == 0) return;  // dropped
    if (computing_ != wanted_) {  // superseded by a newer request
        startNext();
        return;
    }
    wanted_ = 0;
    emit ready(watcher_->result());
    emit busyChanged(false);
}

std::shared_ptr<Preprocessed> PreprocessScheduler::readFile(const QString& path)
{
    QFutureWatcher<std::shared_ptr<Preprocessed>> watcher;
    QEventLoop loop;
    QObject::connect(&watcher, &QFutureWatcherBase::finished, &loop, &QEventLoop::quit);
    watcher.setFuture(QtConcurrent::run([file = path.toStdString()] {
        try {
            return std::make_shared<Preprocessed>(preprocess_file(file, {}, PreprocessStage::Mesh));
        } catch (const std::exception& e) {
            return failed(e, nullptr);
        }
    }));
    if (!watcher.isFinished()) loop.exec(QEventLoop::ExcludeUserInputEvents);
    return watcher.result();
}

}  // namespace mcdda::gui
