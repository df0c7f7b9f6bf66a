#pragma once
/// \file NumberText.hpp
/// Numbers written as text in files other programs make (DXF values, CSV cells), read strictly:
/// decimal notation only. strtod and iostreams also take "inf", "nan" and hexadecimal, or stop
/// at the first bad character and give 0; a value read that way would pass a typo as a number.

#include <optional>
#include <string_view>

namespace mcdda {

/// The number `text` writes in decimal notation ("-1.5", "2.", ".5", "3e-4"), with `,` taken as
/// the decimal point when `comma` is set (DXF files from some locales). nullopt when it is
/// anything else: empty, a word, "nan", "inf", "0x10", "1e", trailing characters. A number
/// beyond the range of a double comes back infinite: the caller says so.
std::optional<double> decimal_number(std::string_view text, bool comma = false);

/// A whole number ("42", "-7") that fits a long long; nullopt otherwise.
std::optional<long long> whole_number(std::string_view text);

}  // namespace mcdda
