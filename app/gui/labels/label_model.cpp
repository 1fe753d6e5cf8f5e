#include "app/gui/labels/label_model.h"

#include <QStringList>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>

#include "app/gui/common/plot_style.h"
#include "app/gui/labels/label_commands.h"
#include "workspace/workspace.h"

namespace tactile::gui {

LabelModel::LabelModel(QObject* parent)
    : QObject(parent), undo_(new QUndoStack(this)), poll_(new QTimer(this)) {
  poll_->setInterval(500);
  connect(poll_, &QTimer::timeout, this, &LabelModel::pollChanges);
}
LabelModel::~LabelModel() = default;

void LabelModel::setWorkspace(workspace::Workspace* workspace) {
  undo_->clear();
  workspace_ = workspace;
  setId_ = 0;
  setName_.clear();
  runId_ = 0;
  runName_.clear();
  stepCount_ = 0;
  for (auto& group : segments_)
    group.clear();
  seenRevision_ = 0;
  if (workspace_ != nullptr) {
    static_cast<void>(workspace_->labelStore().pollChanges());  // starts watching
    poll_->start();
  } else {
    poll_->stop();
  }
  emit labelSetChanged();
  emit labelsChanged();
}

storage::EditOptions LabelModel::editOptions() const {
  storage::EditOptions options;
  options.annotator = annotator_;
  options.expectRevision = seenRevision_;
  return options;
}

void LabelModel::reportFailure(const Error& error) {
  if (storage::isLabelConflict(error)) {
    emit errorOccurred(QString::fromStdString(error.message) +
                       tr(" The run's labels are reloaded."));
  }
}

void LabelModel::pollChanges() {
  if (workspace_ == nullptr) return;
  auto changed = workspace_->labelStore().pollChanges();
  if (!changed) {
    poll_->stop();
    emit connectionLost(QString::fromStdString(changed.errorText()));
    return;
  }
  if (!changed.value() || setId_ == 0 || runId_ == 0) return;
  auto newer = workspace_->labelStore().history(setId_, runId_, seenRevision_);
  if (!newer || newer->empty()) return;
  QStringList lines;
  for (const storage::LabelRevision& r : newer.value()) {
    lines << tr("%1 changed %2 steps %3-%4 (%5)")
                 .arg(r.annotator.empty() ? tr("someone") : QString::fromStdString(r.annotator))
                 .arg(QString::fromUtf8(groupInfo(r.group).shortName.data(),
                                        static_cast<int>(groupInfo(r.group).shortName.size())))
                 .arg(r.firstStep)
                 .arg(r.lastStep)
                 .arg(QString::fromStdString(r.time));
  }
  if (Status s = reload(); !s) {
    emit errorOccurred(QString::fromStdString(s.errorText()));
    return;
  }
  emit changedElsewhere(lines.join('\n'));
}

Status LabelModel::setCurrentSet(std::int64_t id, const std::string& name) {
  setId_ = id;
  setName_ = name;
  emit labelSetChanged();
  return reload();
}

Status LabelModel::openSet(const std::string& name) {
  if (workspace_ == nullptr) return Error("no database is open");
  auto set = workspace_->labelStore().find(name);
  if (!set) return set.error();
  return setCurrentSet(set->id, set->name);
}

Status LabelModel::createSet(const std::string& name) {
  if (workspace_ == nullptr) return Error("no database is open");
  auto id = workspace_->labelStore().create(name, annotator_);
  if (!id) return id.error();
  return setCurrentSet(id.value(), name);
}

Status LabelModel::saveSetAs(const std::string& name) {
  if (workspace_ == nullptr || setId_ == 0) return Error("no label set is open");
  auto id = workspace_->labelStore().copy(setId_, name);
  if (!id) return id.error();
  return setCurrentSet(id.value(), name);
}

Result<std::int64_t> LabelModel::importFile(const std::string& path) {
  if (workspace_ == nullptr || setId_ == 0) return Error("no label set is open");
  auto read = workspace_->labelStore().importFile(setName_, path);
  if (!read) return read.error();
  // Imported segments bypass the undo stack; its records of older edits would no longer restore
  // what is stored, so the history ends here.
  undo_->clear();
  if (Status s = reload(); !s) return s.error();
  return read;
}

Status LabelModel::exportFile(const std::string& path) {
  if (workspace_ == nullptr || setId_ == 0) return Error("no label set is open");
  return workspace_->labelStore().exportFile(setName_, path);
}

void LabelModel::setRun(std::int64_t runId, const std::string& runName, std::int64_t stepCount) {
  runId_ = runId;
  runName_ = runName;
  stepCount_ = stepCount;
  if (Status s = reload(); !s) emit errorOccurred(QString::fromStdString(s.errorText()));
}

const std::vector<storage::LabelSegment>& LabelModel::segments(SensorGroup group) const {
  return segments_[static_cast<std::size_t>(groupIndex(group))];
}

const storage::LabelSegment* LabelModel::segmentAt(SensorGroup group, std::int64_t step) const {
  const auto& list = segments(group);
  auto it = std::upper_bound(
      list.begin(), list.end(), step,
      [](std::int64_t s, const storage::LabelSegment& seg) { return s < seg.firstStep; });
  if (it == list.begin()) return nullptr;
  --it;
  return step <= it->lastStep ? &*it : nullptr;
}

std::optional<ContactClass> LabelModel::classAt(SensorGroup group, std::int64_t step) const {
  const storage::LabelSegment* s = segmentAt(group, step);
  if (s == nullptr) return std::nullopt;
  return s->cls;
}

Status LabelModel::label(const std::vector<SensorGroup>& groups, std::int64_t first,
                         std::int64_t last, ContactClass cls) {
  if (workspace_ == nullptr || setId_ == 0) return Error("no label set is open");
  if (runId_ == 0) return Error("no run is open");
  if (groups.empty()) return Error("no sensor group is chosen");
  if (first > last) std::swap(first, last);
  first = std::max<std::int64_t>(0, first);
  last = std::min(stepCount_ - 1, last);
  if (first > last) return Error("the range lies outside the run");
  const QString text = tr("Label steps %1-%2 as %3").arg(first).arg(last).arg(className(cls));
  auto failed = std::make_shared<std::optional<Error>>();
  undo_->beginMacro(text);
  for (SensorGroup group : groups) {
    storage::LabelSegment segment;
    segment.runId = runId_;
    segment.run = runName_;
    segment.group = group;
    segment.firstStep = first;
    segment.lastStep = last;
    segment.cls = cls;
    segment.annotator = annotator_;
    const std::int64_t set = setId_;
    workspace::Workspace* ws = workspace_;
    const storage::EditOptions options = editOptions();
    auto* command = new LabelEditCommand(this, text, [ws, set, segment, options, failed] {
      auto edit = ws->addSegment(set, segment, options);
      if (!edit && !*failed) *failed = edit.error();
      return edit;
    });
    undo_->push(command);  // runs the edit; a failed one is dropped by the stack
  }
  undo_->endMacro();
  Status reloaded = reload();
  if (*failed) {
    reportFailure(**failed);
    return **failed;
  }
  return reloaded;
}

Status LabelModel::moveSegment(std::int64_t segmentId, std::int64_t first, std::int64_t last) {
  if (workspace_ == nullptr || setId_ == 0) return Error("no label set is open");
  const storage::LabelSegment* found = nullptr;
  for (const auto& group : segments_) {
    for (const auto& s : group)
      if (s.id == segmentId) found = &s;
  }
  if (found == nullptr) return Error("no such segment in the open run");
  if (first > last) std::swap(first, last);
  first = std::max<std::int64_t>(0, first);
  last = std::min(stepCount_ - 1, last);
  storage::LabelSegment moved = *found;
  moved.firstStep = first;
  moved.lastStep = last;
  moved.annotator = annotator_;  // whoever moved an edge vouches for the segment now
  const std::int64_t set = setId_;
  workspace::Workspace* ws = workspace_;
  auto failed = std::make_shared<std::optional<Error>>();
  const storage::EditOptions options = editOptions();
  auto* command = new LabelEditCommand(
      this, tr("Move %1 segment to steps %2-%3").arg(className(moved.cls)).arg(first).arg(last),
      [ws, set, segmentId, moved, options, failed] {
        auto edit = ws->changeSegment(set, segmentId, moved, options);
        if (!edit) *failed = edit.error();
        return edit;
      });
  undo_->push(command);
  Status reloaded = reload();
  if (*failed) {
    reportFailure(**failed);
    return **failed;
  }
  return reloaded;
}

Status LabelModel::removeSegment(std::int64_t segmentId) {
  if (workspace_ == nullptr || setId_ == 0) return Error("no label set is open");
  const std::int64_t set = setId_;
  workspace::Workspace* ws = workspace_;
  auto failed = std::make_shared<std::optional<Error>>();
  const storage::EditOptions options = editOptions();
  auto* command =
      new LabelEditCommand(this, tr("Delete segment"), [ws, set, segmentId, options, failed] {
        auto edit = ws->removeSegment(set, segmentId, options);
        if (!edit) *failed = edit.error();
        return edit;
      });
  undo_->push(command);
  Status reloaded = reload();
  if (*failed) {
    reportFailure(**failed);
    return **failed;
  }
  return reloaded;
}

Status LabelModel::labelFromModels(const std::array<std::string, kGroupCount>& models,
                                   const std::vector<SensorGroup>& groups, std::int64_t first,
                                   std::int64_t last) {
  if (workspace_ == nullptr || setId_ == 0) return Error("no label set is open");
  if (runId_ == 0) return Error("no run is open");
  if (first > last) std::swap(first, last);
  first = std::max<std::int64_t>(0, first);
  last = std::min(stepCount_ - 1, last);
  if (first > last) return Error("the range lies outside the run");
  // Each model classifies the run once, with the offline decision.
  std::map<std::string, workspace::Workspace::Classified> classified;
  analysis::ClassifyOptions offline;
  offline.decision = analysis::DecisionMode::Offline;
  for (const SensorGroup g : groups) {
    const std::string& model = models[static_cast<std::size_t>(groupIndex(g))];
    if (model.empty() || classified.count(model) != 0) continue;
    auto result = workspace_->classify(model, runName_, offline);
    if (!result) return result.error();
    classified.emplace(model, std::move(result.value()));
  }
  if (classified.empty()) return Error("no model is chosen for these groups");
  // What each group takes, before anything is written: groups without a model are named.
  struct Planned {
    SensorGroup group;
    std::vector<storage::LabelSegment> segments;
    storage::EditOptions options;
  };
  std::vector<Planned> planned;
  QStringList uncovered;
  for (const SensorGroup g : groups) {
    const std::string& model = models[static_cast<std::size_t>(groupIndex(g))];
    const auto it = classified.find(model);
    const auto* gc = it == classified.end()
                         ? nullptr
                         : &it->second.result.groups[static_cast<std::size_t>(groupIndex(g))];
    if (gc == nullptr || gc->model == nullptr) {
      const std::string_view name = groupInfo(g).shortName;
      uncovered << QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
      continue;
    }
    storage::EditOptions options = editOptions();
    options.annotator = workspace::modelAnnotator(model);
    planned.push_back(
        {g, workspace::decisionSegments(*gc, g, first, last, options.annotator), options});
  }
  if (planned.empty()) {
    return Error(tr("no chosen model covers %1: choose the group of a model (Learn > Show "
                    "Predictions shows which groups each covers)")
                     .arg(uncovered.join(QStringLiteral(", ")))
                     .toStdString());
  }
  const QString text = tr("Label steps %1-%2 from the model").arg(first).arg(last);
  auto failed = std::make_shared<std::optional<Error>>();
  undo_->beginMacro(text);
  for (const Planned& p : planned) {
    const std::int64_t set = setId_;
    const std::int64_t run = runId_;
    workspace::Workspace* ws = workspace_;
    const SensorGroup g = p.group;
    const std::vector<storage::LabelSegment> segments = p.segments;
    const storage::EditOptions options = p.options;
    undo_->push(new LabelEditCommand(this, text, [=] {
      auto edit = ws->replaceLabels(set, run, g, first, last, segments, options);
      if (!edit && !*failed) *failed = edit.error();
      return edit;
    }));
  }
  undo_->endMacro();
  Status reloaded = reload();
  if (*failed) {
    reportFailure(**failed);
    return **failed;
  }
  return reloaded;
}

Status LabelModel::redoEdit(workspace::LabelEdit& edit) {
  return replay(edit, true);
}

Status LabelModel::undoEdit(workspace::LabelEdit& edit) {
  return replay(edit, false);
}

Status LabelModel::replay(workspace::LabelEdit& edit, bool forward) {
  if (workspace_ == nullptr) return Error("no database is open");
  // Undo and redo take back or put again this annotator's own edit: refused when someone else
  // changed its steps since, whatever this annotator did meanwhile.
  storage::EditOptions options = editOptions();
  options.expectRevision = edit.revision;
  options.othersOnly = true;
  Status s = forward ? workspace_->redo(edit, options) : workspace_->undo(edit, options);
  if (!s) {
    emit errorOccurred(
        QString::fromStdString(s.errorText()) +
        (storage::isLabelConflict(s.error()) ? tr(" The run's labels are reloaded.") : QString()));
  }
  if (Status r = reload(); !r) return r;
  return s;
}

Status LabelModel::reload() {
  for (auto& group : segments_)
    group.clear();
  seenRevision_ = 0;
  if (workspace_ != nullptr && setId_ != 0 && runId_ != 0) {
    // The revision first: an edit committed between the two reads shows as newer than it, so it
    // is never overwritten unseen.
    auto latest = workspace_->labelStore().latestRevision(setId_, runId_);
    if (!latest) {
      emit labelsChanged();
      return latest.error();
    }
    seenRevision_ = latest.value();
    auto all = workspace_->labelStore().segments(setId_, runId_);
    if (!all) {
      emit labelsChanged();
      return all.error();
    }
    for (storage::LabelSegment& s : all.value())
      segments_[static_cast<std::size_t>(groupIndex(s.group))].push_back(std::move(s));
  }
  emit labelsChanged();
  return Status::success();
}

}  // namespace tactile::gui
