#include "io/TextEncoding.hpp"

namespace mcdda {

namespace {

/// Windows-1252 at 0x80–0x9F; the five bytes it leaves undefined keep their Latin-1 meaning.
constexpr char32_t cp1252_high[32] = {
    0x20AC, 0x0081, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0x008D, 0x017D, 0x008F, 0x0090, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0x009D, 0x017E, 0x0178};

void append_utf8(std::string& out, char32_t c)
{
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

}  // namespace

bool is_utf8(std::string_view text)
{
    std::size_t i = 0;
    while (i < text.size()) {
        const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
        const unsigned char b = byte(i);
        std::size_t length = 0;
        char32_t c = 0, least = 0;
        if (b < 0x80) length = 1, c = b;
        else if ((b & 0xE0) == 0xC0) length = 2, c = b & 0x1F, least = 0x80;
        else if ((b & 0xF0) == 0xE0) length = 3, c = b & 0x0F, least = 0x800;
        else if ((b & 0xF8) == 0xF0) length = 4, c = b & 0x07, least = 0x10000;
        else return false;
        if (i + length > text.size()) return false;
        for (std::size_t k = 1; k < length; ++k) {
            if ((byte(i + k) & 0xC0) != 0x80) return false;
            c = (c << 6) | (byte(i + k) & 0x3F);
        }
        if (c < least || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return false;
        i += length;
    }
    return true;
}

std::string as_utf8(std::string_view text)
{
    if (is_utf8(text)) return std::string(text);
    std::string out;
    for (char ch : text) {
        const auto b = static_cast<unsigned char>(ch);
        append_utf8(out, b >= 0x80 && b < 0xA0 ? cp1252_high[b - 0x80] : char32_t(b));
    }
    return out;
}

}  // namespace mcdda
