#pragma once
/// \file HelpMenu.hpp
/// The Help menu: the user guide (F1), the file format and running documents, What's This and
/// About. The documents are compiled in (resources/mcdda.qrc): they match the program and need
/// no network or installed files; each opens in a window of its own beside the main window.

class QMenu;
class QWidget;

namespace mcdda::gui {

/// Creates the Help menu with `parent` as the documents' and About box's parent window.
QMenu* create_help_menu(QWidget* parent);

}  // namespace mcdda::gui
