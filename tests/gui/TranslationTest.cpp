// The German translation is compiled and embedded under ":/i18n"; --language / $MCDDA_LANGUAGE
// pick it the way app/gui/main.cpp does (translations/Language.hpp). No display needed.

#include "Language.hpp"

#include <QCoreApplication>
#include <QFile>
#include <QKeySequence>
#include <QLocale>
#include <QObject>
#include <QTest>
#include <QTranslator>

#include <memory>

namespace {

QString tr_main_window(const char* source) { return QCoreApplication::translate("mcdda::gui::MainWindow", source); }
QString tr_editing(const char* source) { return QCoreApplication::translate("mcdda::gui::EditingTools", source); }
QString tr_run(const char* source) { return QCoreApplication::translate("mcdda::gui::RunMenu", source); }
QString tr_messages(const char* source, int n = -1)
{
    return QCoreApplication::translate("mcdda::gui::RunMessages", source, nullptr, n);
}

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
        QCOMPARE(tr_messages("... and %n more", 3), QStringLiteral("... und 3 weitere"));
        QCOMPARE(tr_messages("Not meshed: %n error(s)", 1),
                 QStringLiteral("Nicht vernetzt: 1 Fehler"));
        QCoreApplication::removeTranslator(&translator);
    }

    void loadsByLocaleLikeTheProgram() {
        // app/gui/main.cpp: load(locale, "mcdda", "_", ":/i18n").
        QTranslator translator;
        QVERIFY(translator.load(QLocale(QLocale::German, QLocale::Germany), QStringLiteral("mcdda"),
                                QStringLiteral("_"), QStringLiteral(":/i18n")));
        QCOMPARE(translator.translate("mcdda::gui::HelpMenu", "&Help"), QStringLiteral("&Hilfe"));
    }

    void languageOptionGivesGermanMenus() {
        mcdda::i18n::Installed installed;
        const auto owner = install(QStringLiteral("de"), &installed);
        QVERIFY(installed.mcdda);
        // Main window menus.
        QCOMPARE(tr_main_window("&File"), QStringLiteral("&Datei"));
        QCOMPARE(tr_main_window("&Edit"), QStringLiteral("&Bearbeiten"));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::ViewMenu", "&View"), QStringLiteral("&Ansicht"));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::HelpMenu", "&Help"), QStringLiteral("&Hilfe"));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::ExportMenu", "&Export"), QStringLiteral("&Exportieren"));
        QCOMPARE(tr_main_window("&Save"), QStringLiteral("&Speichern"));
        QCOMPARE(tr_editing("&Undo"), QStringLiteral("&Rückgängig"));
        QCOMPARE(tr_editing("Draw &Joint"), QStringLiteral("&Kluft zeichnen"));
        QCOMPARE(tr_editing("Draw &Water Table"), QStringLiteral("&Grundwasserspiegel zeichnen"));
        QCOMPARE(QCoreApplication::translate("mcdda::view", "pore pressure"), QStringLiteral("Porenwasserdruck"));
        // Earthquakes.
        QCOMPARE(tr_editing("&Absorbing Boundary"), QStringLiteral("Absorbi&erender Rand"));
        QCOMPARE(QCoreApplication::translate("mcdda::view", "Absorbing boundary"), QStringLiteral("Absorbierender Rand"));
        QCOMPARE(tr_main_window("Earthquake"), QStringLiteral("Erdbeben"));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::EarthquakePanel", "Seismic coefficient (pseudo-static)"),
                 QStringLiteral("Erdbebenbeiwert (pseudostatisch)"));
        QCOMPARE(QCoreApplication::translate("ModelFields", "Damping ratio"), QStringLiteral("Dämpfungsgrad"));
        // The Run menu.
        QCOMPARE(tr_run("&Run"), QStringLiteral("Be&rechnung"));
        QCOMPARE(tr_run("&Pause"), QStringLiteral("&Pause"));
        QCOMPARE(tr_run("Res&ume"), QStringLiteral("&Fortsetzen"));
        QCOMPARE(tr_run("&Stop"), QStringLiteral("&Abbrechen"));
        QCOMPARE(tr_run("Results &Folder..."), QStringLiteral("Ergebnis&ordner..."));
        // "Schritt" throughout (a static run's "Lastschritt"); "Zeitschritt" only where time steps are meant.
        QCOMPARE(tr_messages("Run completed: %n step(s).", 1), QStringLiteral("Berechnung abgeschlossen: 1 Schritt."));
        QCOMPARE(tr_messages("Run completed: %n step(s).", 40), QStringLiteral("Berechnung abgeschlossen: 40 Schritte."));
        QVERIFY(tr_messages("load step %1/%2  contacts open/sliding/locked %3/%4/%5  plastic iterations %6  yielding %7")
                    .startsWith(QStringLiteral("Lastschritt %1/%2")));
        QCOMPARE(QCoreApplication::translate("mcdda::view", "load step"), QStringLiteral("Lastschritt"));
        QCOMPARE(QCoreApplication::translate("mcdda::gui::StepSlider", "Step:"), QStringLiteral("Schritt:"));
        // Regions built and supports installed are different words, never both "baut ein".
        const QString builds = QCoreApplication::translate("mcdda::gui::StagesPanel", "Build regions (fill, liner)");
        const QString installs = QCoreApplication::translate("mcdda::gui::StagesPanel", "Install supports, loads, bolts");
        QVERIFY2(builds.startsWith(QStringLiteral("Einbau von Bereichen")), qPrintable(builds));
        QVERIFY2(installs.startsWith(QStringLiteral("Stützmittel")), qPrintable(installs));
        QVERIFY(!QCoreApplication::translate("mcdda::gui::ModelTree", "builds %1").contains(QStringLiteral("baut")));
        QVERIFY(QCoreApplication::translate("mcdda::gui::ModelTree", "builds %1") !=
                QCoreApplication::translate("mcdda::gui::ModelTree", "installs %1"));
        // Access keys stay unique in the menu bar and the Run menu.
        QVERIFY(distinct_mnemonics(QStringList{tr_main_window("&File"), tr_main_window("&Edit"),
                                               QCoreApplication::translate("mcdda::gui::ViewMenu", "&View"), tr_run("&Run"),
                                               QCoreApplication::translate("mcdda::gui::HelpMenu", "&Help")}));
        QVERIFY(distinct_mnemonics(QStringList{tr_run("&Mesh"), tr_run("&Run"), tr_run("&Pause"), tr_run("&Stop"),
                                               tr_run("Results &Folder...")}));
        // The Edit menu: undo/redo, the tools' entries.
        QStringList edit{tr_editing("&Undo"), tr_editing("&Redo")};
        for (const char* source : {"&Select", "Draw &Region", "Draw &Joint", "&Fixed Point", "R&oller", "Point &Load",
                                   "Edge &Pressure", "&Measurement Point", "&Bolt", "Draw &Water Table", "&Absorbing Boundary",
                                   "&Query Line",
                                   "&Delete", "Add Joint Se&t..."})
            edit << tr_editing(source);
        QVERIFY(distinct_mnemonics(edit));
        QVERIFY(distinct_mnemonics(QStringList{tr_run("&Run"), tr_run("Res&ume"), tr_run("&Stop"), tr_run("Results &Folder...")}));
        // The mesh statistics in Messages.
        QVERIFY(tr_messages("%1 blocks, %2 nodes, %3 triangles").contains(QStringLiteral("Blöcke")));
    }

    void germanShortcutsNumbersAndButtons() {
        // Qt's own German texts (Debian's qt6-translations-l10n) and the German locale: Strg and
        // Entf in shortcuts, Abbrechen on dialog buttons, a decimal comma.
        mcdda::i18n::Installed installed;
        const QLocale before;
        const auto owner = install(QStringLiteral("de"), &installed);
        QVERIFY2(installed.qt, "Qt's German translation (qtbase_de.qm) was not found");
        QCOMPARE(QKeySequence(Qt::CTRL | Qt::Key_Z).toString(QKeySequence::NativeText), QStringLiteral("Strg+Z"));
        QCOMPARE(QKeySequence(Qt::Key_Delete).toString(QKeySequence::NativeText), QStringLiteral("Entf"));
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), QStringLiteral("Abbrechen"));
        QCOMPARE(QLocale().toString(1.5), QStringLiteral("1,5"));
        QLocale::setDefault(before);
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
