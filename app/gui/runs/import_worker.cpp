#include "app/gui/runs/import_worker.h"

#include <QFileInfo>
#include <QtConcurrent/QtConcurrentRun>

#include <filesystem>

#include "app/gui/common/progress_bridge.h"
#include "sim/scene_source.h"
#include "workspace/run_inputs.h"

namespace tactile::gui {

int ImportSummary::imported() const {
  int n = 0;
  for (const auto& o : outcomes)
    n += o.status == storage::ImportStatus::Imported ? 1 : 0;
  return n;
}

int ImportSummary::failed() const {
  int n = 0;
  for (const auto& o : outcomes)
    n += o.status == storage::ImportStatus::Failed ? 1 : 0;
  return n;
}

QStringList ImportSummary::problems() const {
  QStringList out;
  for (const auto& o : outcomes) {
    if (o.status != storage::ImportStatus::Imported)
      out << QString::fromStdString(o.message.empty() ? o.file : o.message);
  }
  return out;
}

bool isDatabaseFile(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  return suffix == "db" || suffix == "sqlite" || suffix == "sqlite3" || suffix == "tactile";
}

DroppedPaths sortDroppedPaths(const QStringList& paths) {
  DroppedPaths out;
  for (const QString& path : paths) {
    const QFileInfo info(path);
    if (info.isDir())
      out.runInputs << path;
    else if (!info.isFile())
      out.ignored << path;
    else if (isDatabaseFile(path))
      out.databases << path;
    else if (info.suffix().compare(QLatin1String("csv"), Qt::CaseInsensitive) == 0)
      out.runInputs << path;
    else if (info.suffix().compare(QLatin1String("mcap"), Qt::CaseInsensitive) == 0)
      out.mcapFiles << path;
    else
      out.ignored << path;
  }
  return out;
}

ImportSummary importRunFiles(const QString& databasePath, const QStringList& files,
                             ProgressBridge* bridge) {
  ImportSummary summary;
  storage::OpenOptions open;
  open.mode = storage::OpenMode::ReadWrite;
  auto db = storage::RunDatabase::open(databasePath.toStdString(), open);
  if (!db) {
    summary.error = QString::fromStdString(db.errorText());
    return summary;
  }
  std::vector<std::filesystem::path> inputs;
  for (const QString& f : files)
    inputs.emplace_back(f.toStdString());
  storage::ImportOptions options;
  options.sceneResolver = sim::proceduralSceneJson;
  auto imported = workspace::importRunInputs(*db.value(), inputs, options,
                                             bridge ? bridge->callback() : ProgressFn{});
  if (!imported) {
    summary.error = QString::fromStdString(imported.errorText());
    return summary;
  }
  for (const std::string& w : imported->warnings)
    summary.warnings << QString::fromStdString(w);
  summary.outcomes = std::move(imported->outcomes);
  return summary;
}

QFuture<ImportSummary> startImport(const QString& databasePath, const QStringList& files,
                                   ProgressBridge* bridge) {
  return QtConcurrent::run(
      [databasePath, files, bridge] { return importRunFiles(databasePath, files, bridge); });
}

}  // namespace tactile::gui
