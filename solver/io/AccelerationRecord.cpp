#include "io/AccelerationRecord.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mcdda {

namespace {

/// A record longer than this is not an earthquake record (a 200 Hz record of 10 minutes has
/// 120,000 points): the reader stops before reading gigabytes.
constexpr std::uintmax_t max_record_bytes = 64u * 1024u * 1024u;

[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& what) {
    throw std::runtime_error(name + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what);
}

/// The number at the start of `s` (after blanks), or false; `s` moves past it.
bool take_number(const char*& s, double& value) {
    while (*s == ' ' || *s == '\t' || *s == '\r') ++s;
    if (*s == '\0') return false;
    char* end = nullptr;
    errno = 0;
    value = std::strtod(s, &end);
    if (end == s) return false;
    // strtod accepts "nan", "inf" and hexadecimal: none is an acceleration or a time.
    for (const char* c = s; c < end; ++c)
        if (std::isalpha(static_cast<unsigned char>(*c)) && *c != 'e' && *c != 'E') return false;
    s = end;
    return true;
}

std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

void check_times(const AccelerationRecord& r, const std::string& name, const std::vector<std::size_t>& lines) {
    if (r.points.size() < 2) fail(name, 0, "an acceleration record needs at least two points, found " +
                                               std::to_string(r.points.size()));
    for (std::size_t i = 1; i < r.points.size(); ++i)
        if (!(r.points[i][0] > r.points[i - 1][0])) {
            std::ostringstream what;
            what << "times must increase: " << r.points[i][0] << " s follows " << r.points[i - 1][0] << " s";
            fail(name, lines.empty() ? 0 : lines[i], what.str());
        }
}

}  // namespace

AccelerationRecord parse_acceleration_csv(const std::string& text, const std::string& name) {
    AccelerationRecord record;
    std::vector<std::size_t> lines;
    std::istringstream in(text);
    std::string line;
    std::size_t number = 0;
    bool header_allowed = true;
    while (std::getline(in, line)) {
        ++number;
        const std::string t = trimmed(line);
        if (t.empty() || t[0] == '#') continue;
        std::string fields = t;
        std::replace_if(fields.begin(), fields.end(), [](char c) { return c == ',' || c == ';' || c == '\t'; }, ' ');
        const char* s = fields.c_str();
        double time = 0.0, acceleration = 0.0;
        const bool numbers = take_number(s, time) && take_number(s, acceleration);
        while (numbers && (*s == ' ' || *s == '\r')) ++s;
        if (!numbers || *s != '\0') {
            if (header_allowed && !numbers) {  // a header line such as "time,acceleration"
                header_allowed = false;
                continue;
            }
            fail(name, number, "expected two numbers, time and acceleration, got \"" + t.substr(0, 60) + "\"");
        }
        header_allowed = false;
        if (!std::isfinite(time) || !std::isfinite(acceleration))
            fail(name, number, "time and acceleration must be finite numbers");
        record.points.push_back({time, acceleration});
        lines.push_back(number);
    }
    check_times(record, name, lines);
    return record;
}

AccelerationRecord parse_acceleration_at2(const std::string& text, const std::string& name) {
    AccelerationRecord record;
    record.peer_at2 = true;
    std::istringstream in(text);
    std::string line;
    for (int header = 1; header <= 3; ++header)
        if (!std::getline(in, line)) fail(name, header, "the file ends in its header (a PEER .AT2 file has four header lines)");
    if (!std::getline(in, line)) fail(name, 4, "the file ends before its NPTS and DT line");
    // "NPTS=  3901, DT=   .0100 SEC" (NGA-West2) or "3901   0.0100   NPTS, DT" (older files).
    std::string upper = line;
    std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
    double npts = -1.0, dt = -1.0;
    const auto at_npts = upper.find("NPTS="), at_dt = upper.find("DT=");
    if (at_npts != std::string::npos && at_dt != std::string::npos) {
        const char* s = line.c_str() + at_npts + 5;
        if (!take_number(s, npts)) npts = -1.0;
        s = line.c_str() + at_dt + 3;
        if (!take_number(s, dt)) dt = -1.0;
    } else {
        std::string fields = line;
        std::replace(fields.begin(), fields.end(), ',', ' ');
        const char* s = fields.c_str();
        if (!take_number(s, npts) || !take_number(s, dt)) npts = dt = -1.0;
    }
    if (!(npts >= 2.0) || npts != std::floor(npts) || !(dt > 0.0) || !std::isfinite(dt))
        fail(name, 4, "expected the number of points and the time step (\"NPTS= n, DT= dt SEC\"), got \"" +
                          trimmed(line).substr(0, 60) + "\"");
    std::size_t number = 4;
    while (std::getline(in, line)) {
        ++number;
        std::string fields = line;
        std::replace(fields.begin(), fields.end(), ',', ' ');
        const char* s = fields.c_str();
        double a = 0.0;
        while (take_number(s, a)) {
            if (!std::isfinite(a)) fail(name, number, "accelerations must be finite numbers");
            if (static_cast<double>(record.points.size()) >= npts)
                fail(name, number, "more accelerations than the " + std::to_string(static_cast<long long>(npts)) +
                                       " the header declares (NPTS)");
            record.points.push_back({static_cast<double>(record.points.size()) * dt, a});
        }
        while (*s == ' ' || *s == '\t' || *s == '\r') ++s;
        if (*s != '\0') fail(name, number, "not a number: \"" + trimmed(s).substr(0, 40) + "\"");
    }
    if (static_cast<double>(record.points.size()) != npts)
        fail(name, number, "the header declares " + std::to_string(static_cast<long long>(npts)) +
                               " accelerations (NPTS), the file holds " + std::to_string(record.points.size()));
    return record;
}

AccelerationRecord read_acceleration_record(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) fail(path, 0, "no such file");
    if (!fs::is_regular_file(status)) fail(path, 0, "not a regular file (an acceleration record is a CSV or .AT2 file)");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > max_record_bytes)
        fail(path, 0, "the file is " + std::to_string(size / (1024 * 1024)) +
                          " MB; an acceleration record is far smaller (limit 64 MB)");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, 0, "cannot open the file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return extension == ".at2" ? parse_acceleration_at2(buffer.str(), path) : parse_acceleration_csv(buffer.str(), path);
}

}  // namespace mcdda
