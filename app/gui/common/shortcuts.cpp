#include "app/gui/common/shortcuts.h"

#include <QCoreApplication>

#include "app/gui/common/plot_style.h"
#include "run/contact_class.h"

namespace tactile::gui {
namespace {

// The translation context of the table's texts.
class Shortcuts {
  Q_DECLARE_TR_FUNCTIONS(Shortcuts)
};

// The platform's keys for a standard action, or `fallback` where the platform has none (some
// themes bind no key to Quit). Function keys past F12 (X11 lists F14 for Undo, a key of old Sun
// keyboards) are left out: no keyboard a user has carries them, and the list would name them.
QList<QKeySequence> standard(QKeySequence::StandardKey key, QKeyCombination fallback) {
  QList<QKeySequence> keys;
  for (const QKeySequence& k : QKeySequence::keyBindings(key)) {
    const int code = k[0].key();
    if (code >= Qt::Key_F13 && code <= Qt::Key_F35) continue;
    keys << k;
  }
  if (keys.isEmpty()) keys << QKeySequence(fallback);
  return keys;
}

QList<QKeySequence> keys(std::initializer_list<QKeyCombination> list) {
  QList<QKeySequence> out;
  for (QKeyCombination k : list)
    out << QKeySequence(k);
  return out;
}

}  // namespace

std::vector<ShortcutEntry> shortcutTable() {
  const QString file = Shortcuts::tr("File");
  const QString edit = Shortcuts::tr("Edit");
  const QString go = Shortcuts::tr("Go");
  const QString view = Shortcuts::tr("View");
  const QString learn = Shortcuts::tr("Learn");
  const QString help = Shortcuts::tr("Help");
  // Redo under both conventions, whatever the platform theme lists first.
  QList<QKeySequence> redo = standard(QKeySequence::Redo, Qt::CTRL | Qt::Key_Y);
  for (const QKeySequence& k :
       {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)})
    if (!redo.contains(k)) redo << k;

  std::vector<ShortcutEntry> t{
      {QStringLiteral("openDatabase"), file, Shortcuts::tr("Open a database"),
       standard(QKeySequence::Open, Qt::CTRL | Qt::Key_O), false},
      {QStringLiteral("importRuns"), file, Shortcuts::tr("Import run files"),
       keys({Qt::CTRL | Qt::Key_I}), false},
      {QStringLiteral("newSimulation"), file, Shortcuts::tr("New simulation window"),
       keys({Qt::CTRL | Qt::SHIFT | Qt::Key_N}), false},
      {QStringLiteral("preferences"), file, Shortcuts::tr("Preferences"),
       keys({Qt::CTRL | Qt::Key_Comma}), false},
      {QStringLiteral("quit"), file, Shortcuts::tr("Quit"),
       standard(QKeySequence::Quit, Qt::CTRL | Qt::Key_Q), false},
      {QStringLiteral("undo"), edit, Shortcuts::tr("Undo the last label edit"),
       standard(QKeySequence::Undo, Qt::CTRL | Qt::Key_Z), true},
      {QStringLiteral("redo"), edit, Shortcuts::tr("Redo"), redo, true},
  };
  for (int i = 0; i < kContactClassCount; ++i) {
    t.push_back({QStringLiteral("labelAs%1").arg(i + 1), edit,
                 Shortcuts::tr("Label as %1").arg(className(static_cast<ContactClass>(i))),
                 keys({QKeyCombination(static_cast<Qt::Key>(Qt::Key_1 + i))}), true});
  }
  const std::vector<ShortcutEntry> rest{
      {QStringLiteral("deleteSegment"), edit, Shortcuts::tr("Delete the segments under the cursor"),
       standard(QKeySequence::Delete, QKeyCombination(Qt::Key_Delete)), false},
      {QStringLiteral("moveStartLeft"), edit,
       Shortcuts::tr("Move the segment's start one step left"),
       keys({Qt::ALT | Qt::SHIFT | Qt::Key_Left}), false},
      {QStringLiteral("moveStartRight"), edit,
       Shortcuts::tr("Move the segment's start one step right"),
       keys({Qt::ALT | Qt::SHIFT | Qt::Key_Right}), false},
      {QStringLiteral("moveEndLeft"), edit, Shortcuts::tr("Move the segment's end one step left"),
       keys({Qt::ALT | Qt::Key_Left}), false},
      {QStringLiteral("moveEndRight"), edit, Shortcuts::tr("Move the segment's end one step right"),
       keys({Qt::ALT | Qt::Key_Right}), false},
      {QStringLiteral("clearSelection"), edit,
       Shortcuts::tr("Clear the selection (in a text field: leave the field)"),
       keys({Qt::Key_Escape}), false},
      {QStringLiteral("nextStep"), go, Shortcuts::tr("Next step"), keys({Qt::Key_Right}), true},
      {QStringLiteral("previousStep"), go, Shortcuts::tr("Previous step"), keys({Qt::Key_Left}),
       true},
      {QStringLiteral("forward10"), go, Shortcuts::tr("Forward 10 steps"),
       keys({Qt::SHIFT | Qt::Key_Right}), true},
      {QStringLiteral("back10"), go, Shortcuts::tr("Back 10 steps"),
       keys({Qt::SHIFT | Qt::Key_Left}), true},
      {QStringLiteral("forward100"), go, Shortcuts::tr("Forward 100 steps"),
       keys({Qt::CTRL | Qt::Key_Right}), true},
      {QStringLiteral("back100"), go, Shortcuts::tr("Back 100 steps"),
       keys({Qt::CTRL | Qt::Key_Left}), true},
      {QStringLiteral("forwardScreen"), go, Shortcuts::tr("Forward one screen"),
       keys({Qt::Key_PageDown}), true},
      {QStringLiteral("backScreen"), go, Shortcuts::tr("Back one screen"), keys({Qt::Key_PageUp}),
       true},
      {QStringLiteral("firstStep"), go, Shortcuts::tr("First step"), keys({Qt::Key_Home}), true},
      {QStringLiteral("lastStep"), go, Shortcuts::tr("Last step"), keys({Qt::Key_End}), true},
      {QStringLiteral("playPause"), go, Shortcuts::tr("Play or pause"), keys({Qt::Key_Space}),
       false},
      {QStringLiteral("closeUp"), view, Shortcuts::tr("Route: robot close-up or whole scene"),
       keys({Qt::Key_M}), false},
      {QStringLiteral("zoomWholeRun"), view,
       Shortcuts::tr("Zoom the timelines out to the whole run"), keys({Qt::CTRL | Qt::Key_0}),
       false},
      {QStringLiteral("trainAndSweep"), learn, Shortcuts::tr("Train and sweep"),
       keys({Qt::CTRL | Qt::Key_T}), false},
      {QStringLiteral("showPredictions"), learn, Shortcuts::tr("Show a model's predictions"),
       keys({Qt::CTRL | Qt::Key_P}), false},
      {QStringLiteral("nextDisagreement"), learn,
       Shortcuts::tr("Next stretch where the model disagrees with the labels"), keys({Qt::Key_N}),
       false},
      {QStringLiteral("previousDisagreement"), learn,
       Shortcuts::tr("Previous stretch where the model disagrees with the labels"),
       keys({Qt::SHIFT | Qt::Key_N}), false},
      {QStringLiteral("nextDoubt"), learn,
       Shortcuts::tr("Next stretch where the model is unsure (below the threshold in "
                     "Preferences)"),
       keys({Qt::Key_D}), false},
      {QStringLiteral("labelFromModel"), learn,
       Shortcuts::tr("Label the selection (or the visible steps) from the predictions' model"),
       keys({Qt::CTRL | Qt::Key_L}), false},
      {QStringLiteral("keyboardShortcuts"), help, Shortcuts::tr("This list of keyboard shortcuts"),
       keys({Qt::Key_F1}), false},
  };
  t.insert(t.end(), rest.begin(), rest.end());
  return t;
}

ShortcutEntry shortcutEntry(const QString& id) {
  for (ShortcutEntry& e : shortcutTable())
    if (e.id == id) return e;
  return {};
}

QString shortcutTableHtml() {
  QString html = QStringLiteral("<table cellspacing=\"0\" cellpadding=\"3\">");
  QString section;
  for (const ShortcutEntry& e : shortcutTable()) {
    if (e.section != section) {
      section = e.section;
      html +=
          QStringLiteral("<tr><td colspan=\"2\"><b>%1</b></td></tr>").arg(section.toHtmlEscaped());
    }
    QStringList keys;
    for (const QKeySequence& k : e.keys)
      keys << k.toString(QKeySequence::NativeText).toHtmlEscaped();
    // The keys never wrap and keep a gap before the text ("Strg+Umschalt+Z, Strg+Y" is long).
    html += QStringLiteral(
                "<tr><td nowrap style=\"padding-right:18px\"><tt>%1</tt></td><td>%2</td></tr>")
                .arg(keys.join(QStringLiteral(", ")), e.text.toHtmlEscaped());
  }
  html += QStringLiteral("</table>");
  return html;
}

}  // namespace tactile::gui
