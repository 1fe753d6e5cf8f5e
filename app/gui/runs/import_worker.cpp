#include "app/gui/runs/import_worker.h"

#include <QtConcurrent/QtConcurrentRun>

#include <filesystem>

#include "app/gui/common/progress_bridge.h"
#include "sim/scene_source.h"

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
  std::vector<std::filesystem::path> paths;
  for (const QString& f : files)
    paths.emplace_back(f.toStdString());
  storage::ImportOptions options;
  options.sceneResolver = sim::proceduralSceneJson;
  summary.outcomes =
      db.value()->importFiles(paths, options, bridge ? bridge->callback() : ProgressFn{});
  return summary;
}

QFuture<ImportSummary> startImport(const QString& databasePath, const QStringList& files,
                                   ProgressBridge* bridge) {
  return QtConcurrent::run(
      [databasePath, files, bridge] { return importRunFiles(databasePath, files, bridge); });
}

}  // namespace tactile::gui
