#pragma once
/// \file PreprocessScheduler.hpp
/// Cutting and meshing in the background for the desktop program (Qt Core only, tested without
/// a screen). After each edit the window asks for a new picture of the model; one computation
/// runs at a time on the thread pool, and a newer request supersedes the one waiting, so a
/// burst of edits costs at most two meshings and the last edit is always the one shown.

#include "Preprocess.hpp"

#include <QObject>
#include <QString>

#include <memory>

template <typename T>
class QFutureWatcher;

namespace mcdda::gui {

class PreprocessScheduler : public QObject {
    Q_OBJECT

public:
    explicit PreprocessScheduler(QObject* parent = nullptr);
    /// Waits for a computation still running (its result is dropped).
    ~PreprocessScheduler() override;

    /// Asks for `model` cut and meshed; ready() follows unless a newer request or drop() comes
    /// first.
    void request(const Model& model);
    /// Forgets the request waiting (the window shows a model it got elsewhere).
    void drop();
    /// Whether a picture is awaited.
    bool isBusy() const { return wanted_ != 0; }
    /// Blocks until no computation runs (for tests and shutdown).
    void waitForFinished();

    /// Reads, checks, cuts and meshes the model file at `path` on the thread pool while this
    /// thread's event loop keeps the window painted (user input waits, as under a progress
    /// dialog). Errors come as diagnostics; the result is never null.
    static std::shared_ptr<Preprocessed> readFile(const QString& path);

signals:
    /// The picture of the latest request (superseded ones are never reported).
    void ready(std::shared_ptr<const mcdda::Preprocessed> preprocessed);
    /// A computation started (true) or the awaited picture came or was dropped (false).
    void busyChanged(bool busy);

private:
    void startNext();
    void onFinished();

    QFutureWatcher<std::shared_ptr<Preprocessed>>* watcher_ = nullptr;
    Model next_;                    ///< the latest model asked for
    unsigned long requests_ = 0;    ///< counts requests
    unsigned long wanted_ = 0;      ///< request waiting for its picture; 0 = none
    unsigned long computing_ = 0;   ///< request being computed
};

}  // namespace mcdda::gui
