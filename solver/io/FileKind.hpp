#pragma once
/// \file FileKind.hpp
/// What a path names, so that input that is not a file (a directory, /dev/zero, a socket) is
/// refused by what it is before anything reads it: reading /dev/zero as a model never ends.

#include <string>

namespace mcdda {

/// "" for a regular file (symbolic links followed); else what the path is, to follow the path in
/// a message: "does not exist", "is a directory", "is a character device", "is a block device",
/// "is a named pipe (FIFO)", "is a socket", "cannot be examined: <reason>".
std::string not_a_regular_file(const std::string& path);

/// Whether `path` is a named pipe: a FIFO or process substitution, which can be read (once).
bool is_named_pipe(const std::string& path);

}  // namespace mcdda
