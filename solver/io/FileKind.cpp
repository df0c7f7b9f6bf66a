#include "io/FileKind.hpp"

#include <filesystem>

namespace mcdda {

namespace fs = std::filesystem;

std::string not_a_regular_file(const std::string& path)
{
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    switch (status.type()) {
    case fs::file_type::regular: return "";
    case fs::file_type::not_found: return "does not exist";
    case fs::file_type::directory: return "is a directory";
    case fs::file_type::character: return "is a character device";
    case fs::file_type::block: return "is a block device";
    case fs::file_type::fifo: return "is a named pipe (FIFO)";
    case fs::file_type::socket: return "is a socket";
    default: break;
    }
    return "cannot be examined" + (ec ? ": " + ec.message() : std::string(": not a regular file"));
}

bool is_named_pipe(const std::string& path)
{
    std::error_code ec;
    return fs::is_fifo(path, ec);
}

}  // namespace mcdda
