#pragma once
/// \file AccelerationRecord.hpp
/// Reads an earthquake acceleration record (one component) from a file: a two-column CSV table
/// of time and acceleration, or the PEER NGA `.AT2` format strong-motion records are downloaded
/// in (four header lines, "NPTS= n, DT= dt SEC", then the accelerations in g). Every problem is
/// a std::runtime_error naming the file and line.

#include <array>
#include <string>
#include <vector>

namespace mcdda {

struct AccelerationRecord {
    std::vector<std::array<double, 2>> points;  ///< (time s, acceleration as in the file), times increasing
    bool peer_at2 = false;                      ///< read as an .AT2 file (accelerations in g)
};

/// An `.AT2` file (by its extension, any case) or a CSV table: lines of two numbers separated by
/// a comma, semicolon, tab or spaces; blank lines, lines starting with '#' and one header line
/// before the numbers are skipped.
AccelerationRecord read_acceleration_record(const std::string& path);

/// The same from a file's text; `name` stands for the file in messages.
AccelerationRecord parse_acceleration_csv(const std::string& text, const std::string& name);
AccelerationRecord parse_acceleration_at2(const std::string& text, const std::string& name);

}  // namespace mcdda
