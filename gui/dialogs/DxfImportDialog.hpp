#pragma once
/// \file DxfImportDialog.hpp
/// File ▸ Import DXF: asks for a drawing (and its units when it does not say them), makes a model
/// of it (io/DxfImport.hpp) and gives it to the document as a new, untitled model; what was
/// skipped or assumed goes to the message log.

#include <QString>

#include <functional>

class QWidget;

namespace mcdda::gui {

class ModelDocument;

/// Imports `path` (asks for one when empty) into `document`. `may_discard` asks whether the
/// current model may go (unsaved changes); `log` takes the import's messages. False when
/// nothing was imported (cancelled, or the drawing cannot be used: a message box says why).
bool import_dxf_into(QWidget* parent, ModelDocument* document, const std::function<bool()>& may_discard,
                     const std::function<void(const QString&)>& log, QString path = QString());

}  // namespace mcdda::gui
