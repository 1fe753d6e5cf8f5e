// Every keyboard shortcut of the main window in one table: the window binds its actions from it
// and Help > Keyboard Shortcuts lists it, so the two cannot disagree.
#pragma once

#include <QKeySequence>
#include <QList>
#include <QString>

#include <vector>

namespace tactile::gui {

struct ShortcutEntry {
  QString id;       // the action's objectName
  QString section;  // menu the action sits in (translated)
  QString text;     // what the key does (translated)
  QList<QKeySequence> keys;
  // Keys that keep working while another widget has the focus; only a text field being typed in
  // keeps them (steps, class keys, undo and redo).
  bool global = false;
};

// The table, in menu order. Texts are translated when called, so call it after a translator is
// installed.
std::vector<ShortcutEntry> shortcutTable();
// The entry with this id (an empty entry when there is none).
ShortcutEntry shortcutEntry(const QString& id);
// The table as the Help dialog shows it: one HTML table, a row per entry.
QString shortcutTableHtml();

}  // namespace tactile::gui
