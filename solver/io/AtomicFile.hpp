#pragma once
/// \file AtomicFile.hpp
/// Writes a file so that a failure never leaves a half-written one where the user's file was:
/// the content goes to "<path>.tmp-<pid>" and is renamed over `path` only when complete.

#include <functional>
#include <ostream>
#include <string>

namespace mcdda {

/// Calls `write` with a stream to a temporary file beside `path`, then renames it to `path`.
/// Throws std::runtime_error naming the file on any failure; the temporary is removed.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace mcdda
