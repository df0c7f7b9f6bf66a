#include "VirtualDisplay.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace mcdda::cli {

namespace {

/// The child's exit status when xvfb-run cannot be executed (the shell's "command not found").
constexpr int cannot_exec = 127;

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

DisplayOutcome ensure_display(const std::vector<std::string>& args, int& status, std::string& error) {
    const char* display = std::getenv("DISPLAY");
    if (display && *display) return DisplayOutcome::present;
    if (std::getenv("MCDDA_UNDER_XVFB")) {
        error = "no X display even under xvfb-run";
        return DisplayOutcome::unavailable;
    }
    if (!on_path("xvfb-run")) {
        error = "no X display (DISPLAY is unset) and xvfb-run is not installed; install the xvfb package "
                "(scripts/install-dependencies.sh) or set DISPLAY";
        return DisplayOutcome::unavailable;
    }
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof(self) - 1);
    if (n <= 0) {
        error = "cannot find this program's path to re-run it under xvfb-run";
        return DisplayOutcome::unavailable;
    }
    self[n] = '\0';

    std::string authority = (std::filesystem::temp_directory_path() / "mcdda-xauth-XXXXXX").string();
    const int fd = ::mkstemp(authority.data());
    if (fd < 0) {
        error = std::string("cannot create an X authority file for xvfb-run: ") + std::strerror(errno);
        return DisplayOutcome::unavailable;
    }
    ::close(fd);

    std::vector<std::string> command{"xvfb-run", "-a", "-f", authority, "-s", "-screen 0 1920x1200x24", self};
    command.insert(command.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& s : command) argv.push_back(s.data());
    argv.push_back(nullptr);

    ::setenv("MCDDA_UNDER_XVFB", "1", 1);
    const pid_t child = ::fork();
    if (child == 0) {
        ::execvp("xvfb-run", argv.data());
        ::_exit(cannot_exec);
    }
    const int fork_errno = errno;
    int wait_status = 0;
    const bool waited = child > 0 && ::waitpid(child, &wait_status, 0) == child;
    ::unlink(authority.c_str());
    if (child < 0 || !waited) {
        error = std::string("cannot start xvfb-run: ") + std::strerror(child < 0 ? fork_errno : errno);
        return DisplayOutcome::unavailable;
    }
    if (WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == cannot_exec) {
        error = "cannot start xvfb-run";
        return DisplayOutcome::unavailable;
    }
    status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : 128 + WTERMSIG(wait_status);
    return DisplayOutcome::rerun;
}

}  // namespace mcdda::cli
