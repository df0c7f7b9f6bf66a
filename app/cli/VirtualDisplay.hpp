#pragma once
/// \file VirtualDisplay.hpp
/// Debian's VTK renders through X only (docs/architecture.md, platform facts): without DISPLAY it aborts. Commands that
/// render re-run themselves under `xvfb-run -a` instead.

#include <string>
#include <vector>

namespace mcdda::cli {

/// What ensure_display found or did.
enum class DisplayOutcome {
    present,      ///< a display exists (or we already run under xvfb-run): go on rendering
    rerun,        ///< the command ran to its end under xvfb-run; exit with `status`
    unavailable,  ///< no display can be had; `error` says why
};

/// When DISPLAY is unset, runs `xvfb-run -a <this program> args…` as a child, waits for it and
/// hands back its exit status. xvfb-run gets an authority file of ours (-f): with its own
/// temporary folder it exits 5, not with the program's status, whenever removing that folder fails.
DisplayOutcome ensure_display(const std::vector<std::string>& args, int& status, std::string& error);

}  // namespace mcdda::cli
