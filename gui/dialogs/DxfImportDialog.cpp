#include "dialogs/DxfImportDialog.hpp"

#include "document/ModelDocument.hpp"
#include "io/DxfImport.hpp"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>

namespace mcdda::gui {

namespace {

/// The texts' translation context.
struct DxfImportDialog {
    Q_DECLARE_TR_FUNCTIONS(mcdda::gui::DxfImportDialog)

public:
    static bool run(QWidget* parent, ModelDocument* document, const std::function<bool()>& may_discard,
                    const std::function<void(const QString&)>& log, QString path);
};

bool DxfImportDialog::run(QWidget* parent, ModelDocument* document, const std::function<bool()>& may_discard,
                          const std::function<void(const QString&)>& log, QString path)
{
    const bool interactive = path.isEmpty();
    if (interactive) path = QFileDialog::getOpenFileName(parent, tr("Import DXF"), QString(), tr("DXF drawings (*.dxf *.DXF)"));
    if (path.isEmpty() || !may_discard()) return false;
    DxfImportResult imported = import_dxf_file(path.toStdString());
    if (interactive && imported.model && imported.summary.find("(assumed)") != std::string::npos) {
        // The drawing does not say its units: ask rather than guess.
        const QStringList units{QStringLiteral("m"), QStringLiteral("mm"), QStringLiteral("cm"), QStringLiteral("ft"),
                                QStringLiteral("in")};
        bool ok = false;
        const QString unit = QInputDialog::getItem(parent, tr("Import DXF"),
                                                   tr("The drawing does not say its units. One drawing unit is:"),
                                                   units, 0, false, &ok);
        if (!ok) return false;
        DxfImportOptions options;
        options.metres_per_unit = metres_per_unit_named(unit.toStdString());
        imported = import_dxf_file(path.toStdString(), options);
    }
    QStringList lines;
    for (const Diagnostic& d : imported.diagnostics) lines << QString::fromStdString(format_diagnostic(d));
    const QString name = QFileInfo(path).fileName();
    if (!imported.model) {
        // Not modal: the program (and its tests) go on.
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Import DXF"), tr("%1 cannot be imported:").arg(name),
                                    QMessageBox::Ok, parent);
        box->setInformativeText(lines.join(QLatin1Char('\n')));
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        for (const QString& line : lines) log(line);
        return false;
    }
    document->setModel(*imported.model);  // untitled: Save asks where it goes
    log(tr("Imported %1: %2").arg(name, QString::fromStdString(imported.summary)));
    for (const QString& line : lines) log(line);
    log(tr("Set the materials' properties (they carry defaults) and draw the supports before running."));
    return true;
}

}  // namespace

bool import_dxf_into(QWidget* parent, ModelDocument* document, const std::function<bool()>& may_discard,
                     const std::function<void(const QString&)>& log, QString path)
{
    return DxfImportDialog::run(parent, document, may_discard, log, std::move(path));
}

}  // namespace mcdda::gui
