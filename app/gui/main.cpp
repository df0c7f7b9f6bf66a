/// \file main.cpp
/// mcdda-gui [--language CODE] [MODEL.json]: the desktop program.

#include "Language.hpp"
#include "MainWindow.hpp"
#include "Version.hpp"
#include "linalg/FreedMemoryReuse.hpp"
#include "run/RunOutput.hpp"

#include <QApplication>
#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QIcon>
#include <QStringList>

#include <cstring>

namespace {

QCommandLineOption language_option()
{
    return QCommandLineOption(
        {QStringLiteral("l"), QStringLiteral("language")},
        QCoreApplication::translate("main",
                                    "Language of the program, e.g. \"de\" or \"en\" (default: $%1, "
                                    "else the system's).")
            .arg(QString::fromLatin1(mcdda::i18n::language_variable)),
        QStringLiteral("CODE"));
}

void describe_options(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QCoreApplication::translate(
        "main", "Pre- and post-processor for elastic-plastic discontinuous deformation analysis."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption(language_option());
    parser.addOption(QCommandLineOption(
        QStringLiteral("run"), QCoreApplication::translate("main", "Start the analysis once the model is open.")));
    parser.addOption(QCommandLineOption(
        QStringLiteral("quit-after-run"),
        QCoreApplication::translate("main", "Close the program when the run ends, with the exit status of mcdda run "
                                            "(for demonstrations and benchmarks).")));
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

/// Installs the translations for --language (else $MCDDA_LANGUAGE, else the system locale)
/// before the options are described, so that --help speaks the chosen language too.
void install_translations(QCoreApplication& app)
{
    QCommandLineParser early;
    early.addOption(language_option());
    // Unknown options make parse() fail but keep the known values; the full parse reports them.
    early.parse(QCoreApplication::arguments());
    const QString requested = early.value(QStringLiteral("language"));
    if (!requested.isEmpty() && !mcdda::i18n::is_known_language(requested))
        qWarning("mcdda-gui: unknown language \"%s\"; the texts stay in English", qUtf8Printable(requested));
    mcdda::i18n::install_translations(mcdda::i18n::choose_locale(requested), &app);
}

}  // namespace

int main(int argc, char** argv)
{
    mcdda::reuse_freed_memory();  // before any thread starts: the solver's thread shares the heap
    if (wants_text_only(argc, argv)) {
        QCoreApplication app(argc, argv);
        set_identity();
        install_translations(app);
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

    const bool run = parser.isSet(QStringLiteral("run"));
    const bool quit_after_run = parser.isSet(QStringLiteral("quit-after-run"));
    if ((run || quit_after_run) && models.isEmpty()) {
        qWarning("mcdda-gui: --run and --quit-after-run need a model file");
        return 2;
    }

    mcdda::gui::MainWindow window;
    window.show();
    if (quit_after_run)
        QObject::connect(&window, &mcdda::gui::MainWindow::runFinished, &app,
                         [](mcdda::RunStatus status, const QString&) { QApplication::exit(mcdda::exit_status(status)); });
    if (!models.isEmpty()) {
        const bool opened = window.openModel(QDir::current().absoluteFilePath(models.front()));
        if (run && !window.startRun()) {
            qWarning("mcdda-gui: the model could not be run%s", opened ? "" : " (it has errors)");
            if (quit_after_run) return 1;
        }
    }
    return QApplication::exec();
}
