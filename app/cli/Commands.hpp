#pragma once
/// \file Commands.hpp
/// The sub-commands of `mcdda`. Each returns the process exit status.

#include "CommandLine.hpp"

namespace mcdda::cli {

enum ExitStatus {
    exit_ok = 0, exit_model_error = 1, exit_usage = 2, exit_output_error = 3,
    exit_run_failed = 4, exit_collapsed = 5, exit_cancelled = 130
};

int run_check(const Request& r);
int run_mesh(const Request& r);
int run_render(const Request& r);
int run_run(const Request& r);

}  // namespace mcdda::cli
