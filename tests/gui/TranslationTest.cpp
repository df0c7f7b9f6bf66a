// The German translation is compiled and embedded under ":/i18n". No display needed.

#include <QCoreApplication>
#include <QFile>
#include <QTest>
#include <QTranslator>

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
};

QTEST_GUILESS_MAIN(TranslationTest)
#include "TranslationTest.moc"
