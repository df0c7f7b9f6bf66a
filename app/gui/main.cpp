/// \file main.cpp
/// mcdda-gui [MODEL.json]: the desktop program.

#include "MainWindow.hpp"
#include "Version.hpp"

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QIcon>
#include <QLibraryInfo>
#include <QLocale>
#include <QStringList>
#include <QTranslator>

#include <cstring>

namespace {

void describe_options(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QCoreApplication::translate(
        "main", "Pre- and post-processor for elastic-plastic discontinuous deformation analysis."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("model"),
                                 QCoreApplication::translate("main", "Model file (*.json) to open."),
                                 QStringLiteral("[MODEL.json]"));
}

void set_identity()
{
    QCoreApplication::setOrganizationName(QStringLiteral("mcdda"));
    QCoreApplication::setApplicationName(QStringLiteral("mcdda-gui"));
    QCoreApplication::setApplicationVersion(QString::fromLatin1(mcdda::version_string));
}

/// Whether the command line only asks for help or the version, which must work without a
/// display (QApplication needs one).
bool wants_text_only(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        for (const char* option : {"-h", "--help", "--help-all", "-v", "--version", "-?"})
            if (std::strcmp(argv[i], option) == 0) return true;
    return false;
}

void install_translations(QApplication& app)
{
    const QLocale locale;
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    auto* own = new QTranslator(&app);
    const QStringList folders{QStringLiteral(":/i18n"),
                              QCoreApplication::applicationDirPath() + QStringLiteral("/../share/mcdda/translations"),
                              QCoreApplication::applicationDirPath() + QStringLiteral("/translations")};
    for (const QString& folder : folders)
        if (own->load(locale, QStringLiteral("mcdda"), QStringLiteral("_"), folder)) {
            QCoreApplication::installTranslator(own);
            break;
        }
}

}  // namespace

int main(int argc, char** argv)
{
    if (wants_text_only(argc, argv)) {
        QCoreApplication app(argc, argv);
        set_identity();
        QCommandLineParser parser;
        describe_options(parser);
        parser.process(app);  // prints and exits
        return 0;
    }

    // Debian's VTK draws through X11 only; under Wayland use XWayland unless told otherwise.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "xcb");

    QApplication app(argc, argv);
    set_identity();
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/mcdda.svg")));
    install_translations(app);

    QCommandLineParser parser;
    describe_options(parser);
    parser.process(app);
    const QStringList models = parser.positionalArguments();
    if (models.size() > 1) {
        qWarning("mcdda-gui: give at most one model file");
        return 2;
    }

    mcdda::gui::MainWindow window;
    window.show();
    if (!models.isEmpty()) window.openModel(QDir::current().absoluteFilePath(models.front()));
    return QApplication::exec();
}
