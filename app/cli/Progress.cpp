#include "Progress.hpp"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace mcdda::cli {

Progress::Progress(int total_steps, bool enabled)
    : total_(total_steps), enabled_(enabled), terminal_(::isatty(STDERR_FILENO) != 0),
      last_draw_(std::chrono::steady_clock::now() - std::chrono::seconds(1)) {}

void Progress::update(const StepReport& r) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    step_start_ = now;  // the next step starts now
    // Stage changes and broken bolts are always told, on their own lines.
    if (!r.events.empty()) {
        if (terminal_ && drawn_) std::fprintf(stderr, "\r\033[K");
        for (const std::string& e : r.events) std::fprintf(stderr, "%s\n", e.c_str());
    }
    char line[400];
    // Static DDA: the increments that relaxed the step to equilibrium at its loads.
    const std::string relaxed =
        r.relaxation_increments > 0 ? " + " + std::to_string(r.relaxation_increments) + " relaxing" : std::string();
    // A static step that started in equilibrium under loads it does not change had nothing to do.
    char work[120];
    if (r.load_increments == 0)
        std::snprintf(work, sizeof work, "in equilibrium, loads unchanged: nothing to solve");
    else
        std::snprintf(work, sizeof work, "equilibrium iterations %d in %d load increment%s%s", r.plastic_iterations,
                      r.load_increments, r.load_increments == 1 ? "" : "s", relaxed.c_str());
    const int width = 24;
    const int filled = total_ > 0 ? width * r.step / total_ : width;
    char bar[width + 1];
    for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
    bar[width] = '\0';
    std::snprintf(line, sizeof line,
                  "[%s] step %d/%d  t=%.4g s  dt=%.3g s  contacts open/sliding/locked %d/%d/%d  open-close %d  "
                  "%s  yielding %d  unbalanced %.2e",
                  bar, r.step, total_, r.time, r.time_step, r.open, r.sliding, r.locked, r.open_close_iterations, work,
                  r.yielding, r.unbalanced_ratio);
    if (terminal_) {
        if (now - last_draw_ < std::chrono::milliseconds(100) && r.step != total_) return;
        std::fprintf(stderr, "\r%s\033[K", line);
        drawn_ = true;
    } else {
        if (r.step < next_line_step_ && r.step != total_) return;
        std::fprintf(stderr, "%s\n", line);
        next_line_step_ = r.step + std::max(1, total_ / 10);
    }
    std::fflush(stderr);
    last_draw_ = now;
}

void Progress::iteration(const IterationInfo& info) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    // Only steps that take a while: a quick step's iterations would just flicker.
    if (now - step_start_ < std::chrono::seconds(1)) return;
    const auto every = terminal_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(10000);
    if (now - last_iteration_line_ < every) return;
    last_iteration_line_ = now;
    const double seconds = std::chrono::duration<double>(now - step_start_).count();
    char line[240];
    std::snprintf(line, sizeof line,
                  "step %d/%d: %.0f s, equilibrium iteration %d at %.0f %% of the step's load, out-of-balance %.2e "
                  "(tolerance %.0e), %d points yielding",
                  info.step, total_, seconds, info.iteration, 100.0 * info.load_fraction, info.out_of_balance,
                  info.tolerance, info.yielding);
    if (terminal_) {
        std::fprintf(stderr, "\r%s\033[K", line);
        drawn_ = true;
    } else {
        std::fprintf(stderr, "%s\n", line);
    }
    std::fflush(stderr);
}

void Progress::finish() {
    if (enabled_ && terminal_ && drawn_) std::fprintf(stderr, "\n");
}

}  // namespace mcdda::cli
