#include "app/gui/common/file_dialog_memory.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

#include "app/gui/common/settings_keys.h"

namespace tactile::gui {

QString startPath(const QString& purpose, const QString& suggestedName) {
  const QString key = QString(settings_keys::kFileDialogs) + purpose;
  QString folder = QSettings().value(key).toString();
  if (folder.isEmpty() || !QFileInfo(folder).isDir()) folder = QDir::homePath();
  return suggestedName.isEmpty() ? folder : QDir(folder).filePath(suggestedName);
}

void rememberPath(const QString& purpose, const QString& chosen) {
  if (chosen.isEmpty()) return;
  const QFileInfo info(chosen);
  const QString folder = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
  QSettings().setValue(QString(settings_keys::kFileDialogs) + purpose, folder);
}

}  // namespace tactile::gui
