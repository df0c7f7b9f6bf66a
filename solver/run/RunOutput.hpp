#pragma once
/// \file RunOutput.hpp
/// The files of a run, kept valid at every moment so that a run that stops (finished, collapsed,
/// failed or cancelled) leaves readable results up to its last good step:
///   DIR/<model>.pvd            ParaView collection of the saved steps (rewritten atomically)
///   DIR/<model>_NNNNNN.vtu     point data displacement, velocity; cell data stress, block, material,
///                              plastic_state (0 never, 1 earlier, 2 now yielding), plastic_strain
///   DIR/<model>_contacts.pvd   ParaView collection of the contacts of the saved steps:
///   DIR/<model>_contacts_NNNNNN.vtp  one vertex per contact (at its vertex node) with point data
///                              normal_force, shear_force (N/m), force (vector on the vertex's
///                              block), normal, opening, slip (m), state (0 open, 1 sliding,
///                              2 locked), and a line per bolt with cell data bolt_force
///   DIR/history.csv            one row per step: step, time, stage, unbalanced_ratio,
///                              load:<name>, <point>:ux, <point>:uy, <bolt>:force
///   DIR/summary.json           status, message, steps, time, stages, timing breakdown
/// A run into a folder that holds an earlier run's files first moves them into DIR/previous/
/// (replacing what was kept there, unless the earlier run itself ended without results:
/// killed, failed or cancelled, when the kept ones stay). They are deleted when the new run
/// completes or collapses, and stay when it fails, is cancelled or killed: a rerun never loses
/// the last good results.

#include "io/VtuWriter.hpp"
#include "run/FactorOfSafety.hpp"
#include "run/Simulation.hpp"

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace mcdda {

/// Unbalanced: every step ran, but the last stage ended with an unbalanced-force ratio above
/// its analysis.equilibrium_ratio (a block still sliding, a slope still moving).
enum class RunStatus { Running, Completed, Unbalanced, Collapsed, Failed, Cancelled };

const char* status_name(RunStatus s);

/// The exit status of a program whose run ended with `s` (docs/running.md): 0 completed,
/// 3 not in equilibrium, 4 failed (or still running), 5 collapsed, 130 cancelled.
int exit_status(RunStatus s);

class RunOutput {
public:
    /// Creates DIR (and parents) and moves an earlier run's files aside (see the file comment);
    /// throws std::runtime_error, with nothing changed, when it cannot.
    RunOutput(std::string directory, std::string model_stem);

    /// Writes the state as a saved step and adds it to the .pvd collection.
    void save_step(const Simulation& simulation);
    /// Writes `state` (of `simulation`'s mesh) as saved step `number`, at `time` in the .pvd
    /// (a strength reduction search saves its critical trials at their factors), with `extra`
    /// fields added.
    void save_state(const Simulation& simulation, const SimulationState& state, int number, double time,
                    const VtuFields& extra = {});

    /// Strength reduction: appends the history row of a trial (the history then has one row per
    /// trial: trial, factor, status, stands, steps, iterations, max_displacement, and the
    /// measurement points' ux, uy at the trial's end). `state` is the trial's last state.
    void record_trial(const Simulation& simulation, const StrengthTrial& trial, const SimulationState& state);

    /// Appends the history row of the current step (writes the header first), unless step rows
    /// are off (a staged strength reduction run keeps the history for its trials).
    void record_history(const Simulation& simulation);
    void set_step_history(bool on) { step_history_ = on; }

    /// Writes summary.json; a completed or collapsed run then deletes DIR/previous/.
    /// With `factor` (a strength reduction analysis) also its factor_of_safety and trials.
    void write_summary(const Simulation* simulation, RunStatus status, const std::string& message,
                       const FactorOfSafety* factor = nullptr);

    /// The folder holding an earlier run's results while they are kept ("" when none).
    std::string kept_results() const;

    const std::string& directory() const { return directory_; }
    int saved_steps() const { return static_cast<int>(saved_.size()); }

private:
    /// The contacts and bolts of the saved step
    void save_contacts(const Simulation& simulation, const SimulationState& state, int number, double time);

    std::string directory_;
    std::string stem_;
    std::vector<std::pair<double, std::string>> saved_;  ///< (time, file name)
    std::vector<std::pair<double, std::string>> saved_contacts_;
    std::ofstream history_;
    bool header_written_ = false;
    bool step_history_ = true;
};

}  // namespace mcdda
