#pragma once
/// \file Commands.hpp
/// The sub-commands of `mcdda`. Each returns the process exit status.

#include "CommandLine.hpp"

namespace mcdda::cli {

/// Exit statuses before a run starts; a run's own (4 failed, 5 collapsed, 130 cancelled) come
/// from exit_status(RunStatus) in run/RunOutput.hpp, which the desktop program shares.
enum ExitStatus { exit_ok = 0, exit_model_error = 1, exit_usage = 2, exit_output_error = 6 };

int run_check(const Request& r);
int run_mesh(const Request& r);
int run_render(const Request& r);
int run_run(const Request& r);
int run_study(const Request& r);
int run_import_dxf(const Request& r);

}  // namespace mcdda::cli
