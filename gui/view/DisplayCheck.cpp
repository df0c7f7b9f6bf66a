#include "view/DisplayCheck.hpp"

#include <X11/Xlib.h>  // kept out of other files: its macros (None, Status, Bool) clash

#include <chrono>
#include <cstdlib>
#include <thread>

namespace mcdda::view {

XConnection open_x_display(std::string& problem)
{
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0') {
        problem = "no X display (DISPLAY is not set); VTK renders through X here, "
                  "run under a virtual X server such as xvfb-run";
        return nullptr;
    }
    for (int attempt = 0; attempt < 50; ++attempt) {
        if (Display* connection = XOpenDisplay(nullptr))
            return XConnection(connection, [](void* d) { XCloseDisplay(static_cast<Display*>(d)); });
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    problem = "cannot connect to the X display \"" + std::string(display) +
              "\"; start an X server there or run under xvfb-run";
    return nullptr;
}

std::optional<std::string> x_display_problem()
{
    std::string problem;
    if (open_x_display(problem)) return std::nullopt;
    return problem;
}

}  // namespace mcdda::view
