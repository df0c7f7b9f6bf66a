#pragma once
/// \file StepSlider.hpp
/// Replays the saved steps of a results folder: a slider over the entries of the run's .pvd
/// and a label with the step's time. Choosing a position emits the step's .vtu.

#include "results/PvdFile.hpp"

#include <QString>
#include <QWidget>

#include <vector>

class QLabel;
class QSlider;

namespace mcdda::gui {

class StepSlider : public QWidget {
    Q_OBJECT

public:
    explicit StepSlider(QWidget* parent = nullptr);

    /// Reads the .pvd at `path` (again) and moves to its last step, or with `keep_current` stays
    /// on the step shown, without emitting stepChosen. An unreadable or missing file leaves no
    /// steps. Returns the step count.
    int load(const QString& pvd_path, bool keep_current = false);
    /// Forgets the steps.
    void clear();

    /// Number of saved steps (slider positions).
    int count() const { return static_cast<int>(entries_.size()); }
    const std::vector<PvdEntry>& entries() const { return entries_; }
    int currentIndex() const;
    /// A static run's steps: the label says "load step 10 (2 of 3)", without a time.
    void setLoadSteps(bool load_steps)
    {
        load_steps_ = load_steps;
        showLabel();
    }
    /// Moves to saved step `index` (0 = the first saved) and emits stepChosen.
    void setCurrentIndex(int index);
    QSlider* slider() const { return slider_; }

signals:
    /// The user (or setCurrentIndex) chose a saved step.
    void stepChosen(const QString& vtu_path, double time);

private:
    void showLabel();

    QSlider* slider_ = nullptr;
    QLabel* label_ = nullptr;
    std::vector<PvdEntry> entries_;
    bool load_steps_ = false;
};

}  // namespace mcdda::gui
