// File dialogs that start where the user last was: each purpose (importing runs, exporting a
// model, saving a report, ...) remembers the folder of the last file chosen for it (QSettings),
// and a new dialog starts there instead of in the current directory.
#pragma once

#include <QString>

namespace tactile::gui {

// The start path for a file dialog of this purpose: the remembered folder joined with
// `suggestedName` (a file name, or empty), or the user's home folder before the first choice.
QString startPath(const QString& purpose, const QString& suggestedName = QString());
// Remembers the folder of `chosen` (a file or a folder, as the dialog returned it; empty: nothing).
void rememberPath(const QString& purpose, const QString& chosen);

}  // namespace tactile::gui
