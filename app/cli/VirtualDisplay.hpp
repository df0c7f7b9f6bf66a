#pragma once
/// \file VirtualDisplay.hpp
/// Debian's VTK renders through X only (docs/architecture.md): without DISPLAY it aborts. Commands that
/// render re-run themselves under `xvfb-run -a` instead.

#include <string>
#include <vector>

namespace mcdda::cli {

/// When DISPLAY is unset, replaces this process with `xvfb-run -a <this program> args…` and
/// does not return. Returns normally when a display exists or we already run under xvfb-run;
/// returns false (with `error` set) when no display can be had.
bool ensure_display(const std::vector<std::string>& args, std::string& error);

}  // namespace mcdda::cli
