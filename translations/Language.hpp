/// \file Language.hpp
/// Choosing the language of the desktop program and loading its translations (Qt's own and
/// mcdda's, embedded under ":/i18n"). Part of the `mcdda_translations` object library.
#pragma once

#include <QLocale>
#include <QString>

class QObject;

namespace mcdda::i18n {

/// Name of the environment variable that picks the language when no --language is given.
inline constexpr const char* language_variable = "MCDDA_LANGUAGE";

/// The locale whose translations to load: `requested` (a code such as "de", "de_DE" or "en")
/// when not empty, else $MCDDA_LANGUAGE when set, else the system locale. An unknown code
/// gives the "C" locale, i.e. the untranslated English texts.
QLocale choose_locale(const QString& requested = {});

/// Whether `code` names a language QLocale knows ("C" and "en" count).
bool is_known_language(const QString& code);

/// What install_translations() found.
struct Installed {
    bool mcdda = false;  ///< mcdda's own texts (none exist for English)
    bool qt = false;     ///< Qt's texts (qtbase_<lang>.qm), when installed on the system
};

/// Loads Qt's and mcdda's translations for `locale` and installs them in the running
/// QCoreApplication; the translators become children of `owner` (usually the application).
/// mcdda's are looked for in ":/i18n", then next to the program (../share/mcdda/translations,
/// translations/).
Installed install_translations(const QLocale& locale, QObject* owner);

}  // namespace mcdda::i18n
