#include "dialogs/HelpMenu.hpp"

#include "Version.hpp"

#include <QAction>
#include <QCoreApplication>
#include <QDialog>
#include <QFile>
#include <QKeySequence>
#include <QMenu>
#include <QMessageBox>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <QWhatsThis>

namespace mcdda::gui {

namespace {

/// Shows the Markdown document `resource` (":/docs/…md") in a window of its own: not modal,
/// so that it can be read while working.
void show_document(QWidget* parent, const QString& title, const QString& resource)
{
    QFile file(resource);
    if (!file.open(QIODevice::ReadOnly)) {
        QMessageBox::critical(parent, QCoreApplication::translate("mcdda::gui::HelpMenu", "Help"), QCoreApplication::translate("mcdda::gui::HelpMenu", "The document %1 is missing from this build.").arg(resource));
        return;
    }
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(QStringLiteral("helpDialog"));
    dialog->setWindowTitle(QCoreApplication::translate("mcdda::gui::HelpMenu", "mcdda — %1").arg(title));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* browser = new QTextBrowser(dialog);
    browser->setObjectName(QStringLiteral("helpBrowser"));
    browser->setOpenExternalLinks(true);
    browser->setMarkdown(QString::fromUtf8(file.readAll()));
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(browser);
    dialog->resize(760, 640);
    dialog->show();
}

}  // namespace

QMenu* create_help_menu(QWidget* parent)
{
    auto* help = new QMenu(QCoreApplication::translate("mcdda::gui::HelpMenu", "&Help"), parent);
    QAction* guide = help->addAction(QCoreApplication::translate("mcdda::gui::HelpMenu", "&User Guide"), parent, [parent] {
        show_document(parent, QCoreApplication::translate("mcdda::gui::HelpMenu", "User Guide"), QStringLiteral(":/docs/desktop.md"));
    });
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence::HelpContents);
    help->addAction(QCoreApplication::translate("mcdda::gui::HelpMenu", "Model &File Format"), parent, [parent] {
        show_document(parent, QCoreApplication::translate("mcdda::gui::HelpMenu", "Model File Format"), QStringLiteral(":/docs/model-format.md"));
    })->setObjectName(QStringLiteral("modelFormatHelpAction"));
    help->addAction(QCoreApplication::translate("mcdda::gui::HelpMenu", "&Running and Results"), parent, [parent] {
        show_document(parent, QCoreApplication::translate("mcdda::gui::HelpMenu", "Running and Results"), QStringLiteral(":/docs/running.md"));
    })->setObjectName(QStringLiteral("runningHelpAction"));
    QAction* whats_this = QWhatsThis::createAction(parent);
    whats_this->setObjectName(QStringLiteral("whatsThisAction"));
    help->addAction(whats_this);
    help->addSeparator();
    help->addAction(QCoreApplication::translate("mcdda::gui::HelpMenu", "&About mcdda"), parent, [parent] {
        QMessageBox::about(parent, QCoreApplication::translate("mcdda::gui::HelpMenu", "About mcdda"),
                           QCoreApplication::translate("mcdda::gui::HelpMenu", "<b>mcdda %1</b><p>Pre- and post-processor for elastic-plastic "
                              "discontinuous deformation analysis.</p>"
                              "<p>Drag with the left or middle mouse button to pan, turn the wheel "
                              "to zoom, press F to fit.</p>")
                               .arg(QString::fromLatin1(mcdda::version_string)));
    });
    return help;
}

}  // namespace mcdda::gui
