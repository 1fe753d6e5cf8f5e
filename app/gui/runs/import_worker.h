// Imports run files into a database on a worker thread, through the same core function as
// `tactile import` (workspace::importRunInputs). The worker opens its own connection (SQLite's WAL
// lets the GUI's connection keep reading meanwhile), reports progress through a ProgressBridge and
// stops between files when cancelled; every file is one transaction, so a cancelled import keeps
// the runs it finished and nothing half-written.
#pragma once

#include <QFuture>
#include <QObject>
#include <QStringList>

#include <vector>

#include "storage/run_database.h"

namespace tactile::gui {

class ProgressBridge;

struct ImportSummary {
  std::vector<storage::ImportOutcome> outcomes;
  QString error;         // the database could not be opened, or a folder not listed
  QStringList warnings;  // folders without run files
  int imported() const;
  int failed() const;
  // One line per failed or skipped file.
  QStringList problems() const;
};

// Run files and folders (a folder stands for its *.csv files, as for `tactile import`), and
// database files, among paths the user dropped or chose. Paths that are neither (other
// extensions, missing files) go to `ignored`.
struct DroppedPaths {
  QStringList databases;
  QStringList runInputs;
  QStringList mcapFiles;  // *.mcap: an export of this program, or a ROS 2 bag to map
  QStringList ignored;
};
DroppedPaths sortDroppedPaths(const QStringList& paths);
bool isDatabaseFile(const QString& path);

// Runs the import; `bridge` (owned by the caller, in the GUI thread) gets progress and cancel.
ImportSummary importRunFiles(const QString& databasePath, const QStringList& files,
                             ProgressBridge* bridge);

// The same on a pool thread.
QFuture<ImportSummary> startImport(const QString& databasePath, const QStringList& files,
                                   ProgressBridge* bridge);

}  // namespace tactile::gui
