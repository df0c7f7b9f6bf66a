#pragma once
/// \file DisplayCheck.hpp
/// Debian's VTK renders through X only and aborts the process when it cannot reach the X
/// server. Off-screen rendering therefore opens the X connection itself — retrying briefly,
/// because a busy Xvfb can refuse a connection now and then (seen under CPU load: VTK's own
/// single XOpenDisplay then aborts) — and hands it to VTK.

#include <memory>
#include <optional>
#include <string>

namespace mcdda::view {

/// An open X display connection, closed when the last owner lets go. `get()` is the Xlib
/// `Display*` as `void*` (for vtkRenderWindow::SetDisplayId), so Xlib headers stay in one file.
using XConnection = std::shared_ptr<void>;

/// Opens the X display named by DISPLAY, trying for up to about five seconds. On failure returns
/// null and sets `problem` to a readable reason (DISPLAY unset, or nobody answers there).
XConnection open_x_display(std::string& problem);

/// Why no X server can be used; nothing when one accepts a connection.
std::optional<std::string> x_display_problem();

}  // namespace mcdda::view
