/// \file Language.cpp
#include "Language.hpp"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QStringList>
#include <QTranslator>

namespace mcdda::i18n {

bool is_known_language(const QString& code)
{
    const QString trimmed = code.trimmed();
    if (trimmed.isEmpty()) return false;
    if (trimmed.compare(QStringLiteral("C"), Qt::CaseInsensitive) == 0) return true;
    return QLocale(trimmed).language() != QLocale::C;
}

QLocale choose_locale(const QString& requested)
{
    QString code = requested.trimmed();
    if (code.isEmpty()) code = qEnvironmentVariable(language_variable).trimmed();
    if (code.isEmpty()) return QLocale();
    return QLocale(code);
}

Installed install_translations(const QLocale& locale, QObject* owner)
{
    Installed installed;
    if (locale.language() == QLocale::C) return installed;

    auto* qt = new QTranslator(owner);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        installed.qt = QCoreApplication::installTranslator(qt);
    else
        delete qt;

    auto* own = new QTranslator(owner);
    const QString program_dir = QCoreApplication::applicationDirPath();
    const QStringList folders{QStringLiteral(":/i18n"),
                              program_dir + QStringLiteral("/../share/mcdda/translations"),
                              program_dir + QStringLiteral("/translations")};
    for (const QString& folder : folders)
        if (own->load(locale, QStringLiteral("mcdda"), QStringLiteral("_"), folder)) {
            installed.mcdda = QCoreApplication::installTranslator(own);
            break;
        }
    if (!installed.mcdda) delete own;
    // Numbers in forms and messages as the language writes them (a decimal comma in German).
    if (installed.mcdda) QLocale::setDefault(locale);
    return installed;
}

}  // namespace mcdda::i18n
