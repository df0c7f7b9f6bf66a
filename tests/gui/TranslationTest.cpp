// The German translation is compiled and embedded under ":/i18n"; --language / $MCDDA_LANGUAGE
// pick it the way app/gui/main.cpp does (translations/Language.hpp). No display needed.

#include "Language.hpp"

#include <QCoreApplication>
#include <QFile>
#include <QObject>
#include <QTest>
#include <QTranslator>

#include <memory>

namespace {

QString tr_main_window(const char* source) { return QCoreApplication::translate("mcdda::gui::MainWindow", source); }
QString tr_editing(const char* source) { return QCoreApplication::translate("mcdda::gui::EditingTools", source); }

/// The access key of a menu text ("Be&rechnung" -> 'r').
QChar mnemonic(const QString& text)
{
    for (qsizetype i = 0; i + 1 < text.size(); ++i)
        if (text[i] == QLatin1Char('&')) {
            if (text[i + 1] != QLatin1Char('&')) return text[i + 1].toLower();
            ++i;
        }
    return {};
}

/// Whether the translated texts have distinct access keys.
bool distinct_mnemonics(const QStringList& texts)
{
    QList<QChar> seen;
    for (const QString& text : texts) {
        const QChar key = mnemonic(text);
        if (key.isNull() || seen.contains(key)) {
            qWarning("access key of \"%s\" missing or taken", qUtf8Printable(text));
            return false;
        }
        seen.append(key);
    }
    return true;
}

/// The same for texts of MainWindow.
bool distinct_mnemonics(std::initializer_list<const char*> sources)
{
    QStringList texts;
    for (const char* source : sources) texts << tr_main_window(source);
    return distinct_mnemonics(texts);
}

/// Installs the translations for `code` as `mcdda-gui --language code` does; they go when the
/// returned owner does.
std::unique_ptr<QObject> install(const QString& code, mcdda::i18n::Installed* installed = nullptr)
{
    auto owner = std::make_unique<QObject>();
    const auto found = mcdda::i18n::install_translations(mcdda::i18n::choose_locale(code), owner.get());
    if (installed) *installed = found;
    return owner;
}

}  // namespace

class TranslationTest : public QObject {
    Q_OBJECT

private slots:
    void germanIsEmbedded() {
        QVERIFY(QFile::exists(QStringLiteral(":/i18n/mcdda_de.qm")));
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/mcdda_de.qm")));
        QVERIFY(!translator.isEmpty());
        QCOMPARE(translator.language(), QStringLiteral("de_DE"));
        QCOMPARE(translator.translate("mcdda::gui::MainWindow", "&File"), QStringLiteral("&Datei"));
        QCOMPARE(translator.translate("main", "Model file (*.json) to open."),
                 QStringLiteral("Zu öffnende Modelldatei (*.json)."));
        QCOMPARE(translator.translate("mcdda::gui::AddRegionCommand", "Add region \"%1\""),
                 QStringLiteral("Bereich „%1“ hinzufügen"));
    }

    void pluralsFollowTheCount() {
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/mcdda_de.qm")));
        QCoreApplication::installTranslator(&translator);
        QCOMPARE(QCoreApplication::translate("mcdda::gui::MainWindow", "... and %n more", nullptr, 3),
                 QStringLiteral("... und 3 weitere"));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::MainWindow", "Not meshed: %n error(s)", nullptr, 1),
                 QStringLiteral("Nicht vernetzt: 1 Fehler"));
        QCoreApplication::removeTranslator(&translator);
    }

    void loadsByLocaleLikeTheProgram() {
        // app/gui/main.cpp: load(locale, "mcdda", "_", ":/i18n").
        QTranslator translator;
        QVERIFY(translator.load(QLocale(QLocale::German, QLocale::Germany), QStringLiteral("mcdda"),
                                QStringLiteral("_"), QStringLiteral(":/i18n")));
        QCOMPARE(translator.translate("mcdda::gui::MainWindow", "&Help"), QStringLiteral("&Hilfe"));
    }

    void languageOptionGivesGermanMenus() {
        mcdda::i18n::Installed installed;
        const auto owner = install(QStringLiteral("de"), &installed);
        QVERIFY(installed.mcdda);
        // Main window menus.
        QCOMPARE(tr_main_window("&File"), QStringLiteral("&Datei"));
        QCOMPARE(tr_main_window("&Edit"), QStringLiteral("&Bearbeiten"));
        QCOMPARE(tr_main_window("&View"), QStringLiteral("&Ansicht"));
        QCOMPARE(tr_main_window("&Help"), QStringLiteral("&Hilfe"));
        QCOMPARE(tr_main_window("&Export"), QStringLiteral("&Exportieren"));
        QCOMPARE(tr_main_window("&Save"), QStringLiteral("&Speichern"));
        QCOMPARE(tr_main_window("&Undo"), QStringLiteral("&Rückgängig"));
        QCOMPARE(tr_editing("Draw &Joint"), QStringLiteral("&Kluft zeichnen"));
        // The Run menu.
        QCOMPARE(tr_main_window("&Run"), QStringLiteral("Be&rechnung"));
        QCOMPARE(tr_main_window("&Pause"), QStringLiteral("&Pause"));
        QCOMPARE(tr_main_window("Res&ume"), QStringLiteral("&Fortsetzen"));
        QCOMPARE(tr_main_window("&Stop"), QStringLiteral("&Abbrechen"));
        QCOMPARE(tr_main_window("Results &Folder..."), QStringLiteral("Ergebnis&ordner..."));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::MainWindow", "Run completed: %n step(s).", nullptr, 1),
                 QStringLiteral("Berechnung abgeschlossen: 1 Zeitschritt."));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::MainWindow", "Run completed: %n step(s).", nullptr, 40),
                 QStringLiteral("Berechnung abgeschlossen: 40 Zeitschritte."));
        // Access keys stay unique in the menu bar and the Run menu.
        QVERIFY(distinct_mnemonics({"&File", "&Edit", "&View", "&Run", "&Help"}));
        QVERIFY(distinct_mnemonics({"&Mesh", "&Run", "&Pause", "&Stop", "Results &Folder..."}));
        // The Edit menu: undo/redo of the window, the tools' entries.
        QStringList edit{tr_main_window("&Undo"), tr_main_window("&Redo")};
        for (const char* source : {"&Select", "Draw &Region", "Draw &Joint", "&Fixed Point", "R&oller", "Point &Load",
                                   "Edge &Pressure", "&Measurement Point", "&Delete", "Add Joint Se&t..."})
            edit << tr_editing(source);
        QVERIFY(distinct_mnemonics(edit));
        QVERIFY(distinct_mnemonics({"&Run", "Res&ume", "&Stop", "Results &Folder..."}));
    }

    void englishNeedsNoTranslation() {
        mcdda::i18n::Installed installed;
        const auto owner = install(QStringLiteral("en"), &installed);
        QVERIFY(!installed.mcdda);
        QCOMPARE(tr_main_window("&Run"), QStringLiteral("&Run"));
    }

    void translationsGoWithTheirOwner() {
        { const auto owner = install(QStringLiteral("de_DE")); QCOMPARE(tr_main_window("&File"), QStringLiteral("&Datei")); }
        QCOMPARE(tr_main_window("&File"), QStringLiteral("&File"));
    }

    void environmentPicksTheLanguageUnlessTheOptionDoes() {
        qputenv(mcdda::i18n::language_variable, "de");
        QCOMPARE(mcdda::i18n::choose_locale().language(), QLocale::German);
        QCOMPARE(mcdda::i18n::choose_locale(QStringLiteral("en")).language(), QLocale::English);
        qputenv(mcdda::i18n::language_variable, "");
        QCOMPARE(mcdda::i18n::choose_locale(), QLocale());
        qunsetenv(mcdda::i18n::language_variable);
        QVERIFY(mcdda::i18n::is_known_language(QStringLiteral("de")));
        QVERIFY(mcdda::i18n::is_known_language(QStringLiteral("en")));
        QVERIFY(!mcdda::i18n::is_known_language(QStringLiteral("")));
        QVERIFY(!mcdda::i18n::is_known_language(QStringLiteral("xx")));
    }

#ifdef MCDDA_TS_FILE
    void everyMessageIsTranslated() {
        QFile ts(QStringLiteral(MCDDA_TS_FILE));
        QVERIFY(ts.open(QIODevice::ReadOnly));
        const QByteArray text = ts.readAll();
        QVERIFY(text.contains("<message"));
        QVERIFY2(!text.contains("type=\"unfinished\""), "translations/mcdda_de.ts has unfinished messages");
        QVERIFY2(!text.contains("type=\"vanished\"") && !text.contains("type=\"obsolete\""),
                 "translations/mcdda_de.ts keeps obsolete messages (lupdate -no-obsolete)");
    }
#endif
};

QTEST_GUILESS_MAIN(TranslationTest)
#include "TranslationTest.moc"
