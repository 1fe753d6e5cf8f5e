// The labels of the open run in the current label set, and every edit of them. Each edit is one
// undoable command on the model's QUndoStack and is written to the database at once through the
// workspace; undo writes back exactly the segments the edit trimmed, split or removed.
#pragma once

#include <QObject>
#include <QString>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"
#include "storage/run_database.h"

class QTimer;
class QUndoStack;

namespace tactile::workspace {
class Workspace;
struct LabelEdit;
}  // namespace tactile::workspace

namespace tactile::gui {

class LabelModel : public QObject {
  Q_OBJECT

 public:
  explicit LabelModel(QObject* parent = nullptr);
  ~LabelModel() override;

  // Not owned. Changing it clears the undo history and the current set.
  void setWorkspace(workspace::Workspace* workspace);
  workspace::Workspace* workspace() const { return workspace_; }

  // ---- the current label set ----
  bool hasSet() const { return setId_ != 0; }
  std::int64_t setId() const { return setId_; }
  const std::string& setName() const { return setName_; }
  // Opens an existing set by name.
  Status openSet(const std::string& name);
  // The annotator's name (Preferences) stored on every segment written from here on, and on a
  // set created here; empty for none.
  void setAnnotator(const std::string& name) { annotator_ = name; }
  const std::string& annotator() const { return annotator_; }
  // Creates an empty set and opens it.
  Status createSet(const std::string& name);
  // Copies the current set under a new name and opens the copy ("Save As").
  Status saveSetAs(const std::string& name);
  // Imports a label file (CSV or JSON) into the current set, as one database transaction.
  Result<std::int64_t> importFile(const std::string& path);
  // Exports the current set to CSV or JSON (by extension).
  Status exportFile(const std::string& path);

  // ---- the run whose segments are held ----
  void setRun(std::int64_t runId, const std::string& runName, std::int64_t stepCount);
  std::int64_t runId() const { return runId_; }
  // Segments of one group of the current run, by first step, not overlapping.
  const std::vector<storage::LabelSegment>& segments(SensorGroup group) const;
  // The segment covering a step, if any.
  const storage::LabelSegment* segmentAt(SensorGroup group, std::int64_t step) const;
  std::optional<ContactClass> classAt(SensorGroup group, std::int64_t step) const;

  // ---- edits (each pushed on the undo stack; several groups make one undo step) ----
  // Labels [first, last] with `cls` in every group given.
  Status label(const std::vector<SensorGroup>& groups, std::int64_t first, std::int64_t last,
               ContactClass cls);
  // Gives a segment a new range (e.g. an edge dragged or nudged).
  Status moveSegment(std::int64_t segmentId, std::int64_t first, std::int64_t last);
  Status removeSegment(std::int64_t segmentId);
  // Steps [first, last] of each group take the offline decision of the stored model named for it
  // (models[group index]; groups without one are skipped), as one undoable edit whose revisions
  // carry the annotator "model:NAME". Labels outside the range stay.
  Status labelFromModels(const std::array<std::string, kGroupCount>& models,
                         const std::vector<SensorGroup>& groups, std::int64_t first,
                         std::int64_t last);

  QUndoStack* undoStack() const { return undo_; }

  // Used by the undo commands: applies a stored edit again or takes it back, then reloads.
  Status redoEdit(workspace::LabelEdit& edit);
  Status undoEdit(workspace::LabelEdit& edit);
  // Re-reads the current run's segments from the database and emits labelsChanged.
  Status reload();
  // The newest revision of the current set's labels on the current run this model has shown;
  // every edit from here is based on it (a step someone changed after it is not overwritten).
  std::int64_t seenRevision() const { return seenRevision_; }
  // Looks for others' edits (a timer calls it twice a second): when the current run's labels have
  // a newer revision, reloads and emits changedElsewhere with who changed what.
  void pollChanges();

 signals:
  void labelSetChanged();
  void labelsChanged();
  void errorOccurred(const QString& message);
  // Someone else's edits of the open run arrived (one line per edit, newest last).
  void changedElsewhere(const QString& message);
  // The database cannot be reached any more (a server stopped or the network cut); polling stops.
  void connectionLost(const QString& message);

 private:
  Status setCurrentSet(std::int64_t id, const std::string& name);
  // Writes an edit's segments after (forward) or before it back, then reloads.
  Status replay(workspace::LabelEdit& edit, bool forward);

  workspace::Workspace* workspace_ = nullptr;
  std::int64_t setId_ = 0;
  std::string setName_;
  std::int64_t runId_ = 0;
  std::string runName_;
  std::string annotator_;
  std::int64_t stepCount_ = 0;
  std::array<std::vector<storage::LabelSegment>, kGroupCount> segments_;
  std::int64_t seenRevision_ = 0;
  QUndoStack* undo_ = nullptr;
  QTimer* poll_ = nullptr;

  // What an edit from here is made with: the annotator and the revision it is based on.
  storage::EditOptions editOptions() const;
  // After a failed edit: a conflict is reported and the stretch reloaded.
  void reportFailure(const Error& error);
};

}  // namespace tactile::gui
