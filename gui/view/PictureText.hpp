#pragma once
/// \file PictureText.hpp
/// Texts drawn into pictures (legend rows, titles). They are English here, so headless
/// `mcdda render` needs no Qt; the desktop program installs a translator that looks them up in
/// its Qt translations (context "mcdda::view"), and the decimal separator of its language (a
/// comma in German) for the numbers in pictures. The literals are marked with
/// QT_TRANSLATE_NOOP so that lupdate collects them; without Qt the macro is the bare text.

#include <functional>
#include <string>

#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(scope, x) x
#endif

namespace mcdda::view {

/// `english` as the installed translator gives it (unchanged without one).
std::string picture_text(const char* english);

/// Installs (or, with an empty function, removes) the translator picture_text() uses. Called on
/// the thread that builds the pictures.
void set_picture_translator(std::function<std::string(const char*)> translator);

/// The decimal separator of the numbers drawn into pictures ('.' until set).
void set_picture_decimal_point(char point);

/// `value` formatted by `printf_format` (one floating-point conversion, e.g. "%.3g"), with the
/// pictures' decimal separator.
std::string picture_number(const char* printf_format, double value);

/// `text` (numbers formatted with '.') with the pictures' decimal separator: a '.' between two
/// digits, or after a digit and before an exponent, is replaced.
std::string with_picture_decimals(std::string text);

}  // namespace mcdda::view
