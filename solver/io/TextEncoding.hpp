#pragma once
/// \file TextEncoding.hpp
/// Names read from files that do not say their encoding (DXF layers before AutoCAD 2007, file
/// names) become UTF-8, the only encoding the model file (JSON) holds.

#include <string>
#include <string_view>

namespace mcdda {

/// Whether `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past U+10FFFF).
bool is_utf8(std::string_view text);

/// `text` itself when it is UTF-8, else read as Windows-1252 (Latin-1 with the printable
/// characters at 0x80–0x9F) and written in UTF-8: the encoding of Western European CAD drawings.
std::string as_utf8(std::string_view text);

}  // namespace mcdda
