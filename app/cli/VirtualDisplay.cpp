#include "VirtualDisplay.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace mcdda::cli {

namespace {

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::string dirs(path);
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = dirs.find(':', start);
        const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return false;
}

}  // namespace

bool ensure_display(const std::vector<std::string>& args, std::string& error) {
    const char* display = std::getenv("DISPLAY");
    if (display && *display) return true;
    if (std::getenv("MCDDA_UNDER_XVFB")) {
        error = "no X display even under xvfb-run";
        return false;
    }
    if (!on_path("xvfb-run")) {
        error = "no X display (DISPLAY is unset) and xvfb-run is not installed; install the xvfb package "
                "(scripts/install-dependencies.sh) or set DISPLAY";
        return false;
    }
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof(self) - 1);
    if (n <= 0) {
        error = "cannot find this program's path to re-run it under xvfb-run";
        return false;
    }
    self[n] = '\0';
    ::setenv("MCDDA_UNDER_XVFB", "1", 1);
    std::vector<std::string> command{"xvfb-run", "-a", "-s", "-screen 0 1920x1200x24", self};
    command.insert(command.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& s : command) argv.push_back(s.data());
    argv.push_back(nullptr);
    ::execvp("xvfb-run", argv.data());
    error = std::string("cannot start xvfb-run: ") + std::strerror(errno);
    return false;
}

}  // namespace mcdda::cli
