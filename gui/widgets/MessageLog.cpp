#include "widgets/MessageLog.hpp"

#include <QFontDatabase>
#include <QScrollBar>

namespace mcdda::gui {

MessageLog::MessageLog(QWidget* parent) : QPlainTextEdit(parent)
{
    setReadOnly(true);
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setPlaceholderText(tr("Messages about the model appear here."));
}

void MessageLog::log(const QString& line)
{
    appendPlainText(line);
    verticalScrollBar()->setValue(verticalScrollBar()->maximum());
}

int MessageLog::preferredHeight() const { return 10 * fontMetrics().lineSpacing() + 24; }

}  // namespace mcdda::gui
