// The history of label edits: one revision per edit and group, conflicts between annotators who
// edit the same steps, change polling, and assignments (docs/team.md#annotators-side-by-side).
#include <algorithm>
#include <nlohmann/json.hpp>

#include "storage/database_impl.h"

namespace tactile::storage {
namespace {

constexpr std::string_view kConflictStart = "not stored: steps ";
constexpr std::string_view kConflictEnd = "that this edit is based on";

std::string replacedJson(const std::vector<LabelSegment>& replaced) {
  nlohmann::json out = nlohmann::json::array();
  for (const LabelSegment& s : replaced) {
    out.push_back({s.firstStep, s.lastStep, contactClassName(s.cls), s.annotator});
  }
  return out.dump();
}

std::vector<LabelSegment> parseReplaced(std::string_view text, const LabelRevision& revision) {
  std::vector<LabelSegment> out;
  const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
  if (!parsed.is_array()) {
    throw db::DbError("malformed label revision " + std::to_string(revision.revision));
  }
  for (const nlohmann::json& item : parsed) {
    const auto cls = item.is_array() && item.size() == 4 && item[2].is_string()
                         ? parseContactClass(item[2].get<std::string>())
                         : std::nullopt;
    if (!cls || !item[0].is_number_integer() || !item[1].is_number_integer() ||
        !item[3].is_string()) {
      throw db::DbError("malformed label revision " + std::to_string(revision.revision));
    }
    LabelSegment segment;
    segment.run = revision.run;
    segment.runId = revision.runId;
    segment.group = revision.group;
    segment.firstStep = item[0].get<std::int64_t>();
    segment.lastStep = item[1].get<std::int64_t>();
    segment.cls = *cls;
    segment.annotator = item[3].get<std::string>();
    out.push_back(std::move(segment));
  }
  return out;
}

std::string stepsText(std::int64_t first, std::int64_t last) {
  return first == last ? std::to_string(first) : std::to_string(first) + "-" + std::to_string(last);
}

}  // namespace

bool isLabelConflict(const Error& error) {
  return error.message.starts_with(kConflictStart) &&
         error.message.find(kConflictEnd) != std::string::npos;
}

void RunDatabase::Impl::checkExpectedRevision(std::int64_t setId, std::int64_t runId,
                                              SensorGroup group, std::int64_t firstStep,
                                              std::int64_t lastStep, const EditOptions& options) {
  const std::optional<std::int64_t>& expected = options.expectRevision;
  if (!expected) return;
  db::Statement& s = statement(
      "SELECT id, annotator, created_at, first_step, last_step FROM label_revisions "
      "WHERE set_id = ? AND run_id = ? AND grp = ? AND id > ? AND first_step <= ? AND "
      "last_step >= ? AND (? = 0 OR annotator <> ?) ORDER BY id DESC LIMIT 1");
  s.bind(1, setId)
      .bind(2, runId)
      .bind(3, groupInfo(group).shortName)
      .bind(4, *expected)
      .bind(5, lastStep)
      .bind(6, firstStep)
      .bind(7, options.othersOnly ? 1 : 0)
      .bind(8, std::string_view(options.annotator));
  if (!s.step()) return;
  const std::int64_t revision = s.columnInt(0);
  const std::string annotator = s.columnText(1);
  const std::string time = s.columnText(2);
  const std::int64_t first = std::max(firstStep, s.columnInt(3));
  const std::int64_t last = std::min(lastStep, s.columnInt(4));
  s.reset();
  db::Statement& name = statement("SELECT name FROM runs WHERE id = ?");
  name.bind(1, runId);
  const std::string run = name.step() ? name.columnText(0) : std::to_string(runId);
  name.reset();
  throw db::DbError(std::string(kConflictStart) + stepsText(first, last) + " of " +
                    std::string(groupInfo(group).shortName) + " in run '" + run +
                    "' were changed by " + (annotator.empty() ? "someone" : annotator) + " at " +
                    time + " (revision " + std::to_string(revision) + "), after revision " +
                    std::to_string(*expected) + " " + std::string(kConflictEnd) +
                    "; reload them and edit again");
}

std::vector<LabelSegment> RunDatabase::Impl::clippedSegments(std::int64_t setId, std::int64_t runId,
                                                             SensorGroup group,
                                                             std::int64_t firstStep,
                                                             std::int64_t lastStep) {
  std::vector<LabelSegment> out = overlappingSegments(setId, runId, group, firstStep, lastStep);
  for (LabelSegment& segment : out) {
    segment.firstStep = std::max(segment.firstStep, firstStep);
    segment.lastStep = std::min(segment.lastStep, lastStep);
  }
  return out;
}

std::int64_t RunDatabase::Impl::recordRevision(std::int64_t setId, std::int64_t runId,
                                               SensorGroup group, std::int64_t firstStep,
                                               std::int64_t lastStep,
                                               std::optional<ContactClass> cls,
                                               std::string_view action, std::string_view annotator,
                                               const std::vector<LabelSegment>& replaced) {
  db::Statement& insert = statement(
      "INSERT INTO label_revisions(set_id, run_id, grp, first_step, last_step, class, action, "
      "annotator, created_at, replaced) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id");
  insert.bind(1, setId)
      .bind(2, runId)
      .bind(3, groupInfo(group).shortName)
      .bind(4, firstStep)
      .bind(5, lastStep);
  if (cls) {
    insert.bind(6, contactClassName(*cls));
  } else {
    insert.bindNull(6);
  }
  const std::string now = utcNow();
  const std::string json = replacedJson(replaced);
  lastRevision =
      insert.bind(7, action).bind(8, annotator).bind(9, now).bind(10, json).runReturningId();
  return lastRevision;
}

Result<std::int64_t> LabelStore::setRange(std::int64_t setId, std::int64_t runId,
                                          const std::vector<SensorGroup>& groups,
                                          std::int64_t firstStep, std::int64_t lastStep,
                                          ContactClass cls, const EditOptions& options) {
  return guarded<std::int64_t>(*impl_, [&] {
    if (groups.empty()) throw db::DbError("no group to label");
    db::Transaction transaction(impl_->connection);
    db::Statement& set = impl_->statement("SELECT 1 FROM label_sets WHERE id = ?");
    set.bind(1, setId);
    if (!set.step()) throw db::DbError("no label set with id " + std::to_string(setId));
    set.reset();
    // Every group is checked before anything is written: the edit stands or fails as a whole.
    for (const SensorGroup group : groups) {
      impl_->checkExpectedRevision(setId, runId, group, firstStep, lastStep, options);
    }
    for (const SensorGroup group : groups) {
      LabelSegment segment;
      segment.runId = runId;
      segment.group = group;
      segment.firstStep = firstStep;
      segment.lastStep = lastStep;
      segment.cls = cls;
      segment.annotator = options.annotator;
      const std::vector<LabelSegment> replaced =
          impl_->clippedSegments(setId, runId, group, firstStep, lastStep);
      impl_->insertSegmentNewestWins(setId, segment, 0);
      impl_->recordRevision(setId, runId, group, firstStep, lastStep, cls,
                            options.action.empty() ? "set" : options.action, options.annotator,
                            replaced);
    }
    transaction.commit();
    return impl_->lastRevision;
  });
}

Result<std::vector<LabelRevision>> LabelStore::history(std::int64_t setId, std::int64_t runId,
                                                       std::int64_t afterRevision) {
  return guarded<std::vector<LabelRevision>>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT label_revisions.id, runs.name, grp, first_step, last_step, class, action, "
        "annotator, label_revisions.created_at, replaced FROM label_revisions "
        "JOIN runs ON runs.id = run_id WHERE set_id = ? AND run_id = ? AND label_revisions.id > ? "
        "ORDER BY label_revisions.id");
    s.bind(1, setId).bind(2, runId).bind(3, afterRevision);
    std::vector<LabelRevision> out;
    while (s.step()) {
      LabelRevision r;
      r.revision = s.columnInt(0);
      r.setId = setId;
      r.run = s.columnText(1);
      r.runId = runId;
      const auto group = parseSensorGroup(s.columnTextView(2));
      if (!group) throw db::DbError("malformed label revision " + std::to_string(r.revision));
      r.group = *group;
      r.firstStep = s.columnInt(3);
      r.lastStep = s.columnInt(4);
      if (!s.columnIsNull(5)) {
        r.cls = parseContactClass(s.columnTextView(5));
        if (!r.cls) throw db::DbError("malformed label revision " + std::to_string(r.revision));
      }
      r.action = s.columnText(6);
      r.annotator = s.columnText(7);
      r.time = s.columnText(8);
      r.replaced = parseReplaced(s.columnTextView(9), r);
      out.push_back(std::move(r));
    }
    return out;
  });
}

Result<std::int64_t> LabelStore::latestRevision(std::int64_t setId, std::int64_t runId) {
  return guarded<std::int64_t>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT COALESCE(MAX(id), 0) FROM label_revisions WHERE set_id = ? AND run_id = ?");
    s.bind(1, setId).bind(2, runId);
    const std::int64_t latest = s.step() ? s.columnInt(0) : 0;
    s.reset();
    return latest;
  });
}

std::int64_t LabelStore::lastRevision() const {
  return impl_->lastRevision;
}

Result<bool> LabelStore::pollChanges() {
  return guarded<bool>(
      *impl_, [&] { return impl_->connection.backend().changedSinceLastPoll("tactile_labels"); });
}

// ---- assignments
// ---------------------------------------------------------------------------------

std::string_view assignmentStateName(AssignmentState state) {
  switch (state) {
    case AssignmentState::Todo:
      return "todo";
    case AssignmentState::Labelled:
      return "labelled";
    case AssignmentState::Reviewed:
      return "reviewed";
  }
  return "todo";
}

std::optional<AssignmentState> parseAssignmentState(std::string_view text) {
  for (const AssignmentState state :
       {AssignmentState::Todo, AssignmentState::Labelled, AssignmentState::Reviewed}) {
    if (text == assignmentStateName(state)) return state;
  }
  return std::nullopt;
}

Status LabelStore::assign(const std::vector<std::string>& runs, std::optional<SensorGroup> group,
                          const std::string& annotator, const std::string& labelSet,
                          AssignmentState state, const std::string& by) {
  return guardedStatus(*impl_, [&] {
    requireName(annotator, "annotator");
    if (!labelSet.empty()) requireName(labelSet, "label set");
    if (runs.empty()) throw db::DbError("no run to assign");
    const std::string grp = group ? std::string(groupInfo(*group).shortName) : std::string();
    const std::string now = utcNow();
    db::Transaction transaction(impl_->connection);
    for (const std::string& run : runs) {
      const std::int64_t runId = impl_->runIdByName(run);
      db::Statement& find = impl_->statement(
          "SELECT id FROM assignments WHERE run_id = ? AND grp = ? AND annotator = ?");
      find.bind(1, runId).bind(2, grp).bind(3, annotator);
      const std::int64_t existing = find.step() ? find.columnInt(0) : 0;
      find.reset();
      if (existing != 0) {
        impl_
            ->statement(
                "UPDATE assignments SET state = ?, updated_by = ?, updated_at = ?, label_set = "
                "CASE WHEN ? = '' THEN label_set ELSE ? END WHERE id = ?")
            .bind(1, assignmentStateName(state))
            .bind(2, by)
            .bind(3, now)
            .bind(4, labelSet)
            .bind(5, labelSet)
            .bind(6, existing)
            .run();
      } else {
        impl_
            ->statement(
                "INSERT INTO assignments(run_id, grp, annotator, label_set, state, updated_by, "
                "updated_at) VALUES(?, ?, ?, ?, ?, ?, ?)")
            .bind(1, runId)
            .bind(2, grp)
            .bind(3, annotator)
            .bind(4, labelSet)
            .bind(5, assignmentStateName(state))
            .bind(6, by)
            .bind(7, now)
            .run();
      }
    }
    transaction.commit();
  });
}

Status LabelStore::unassign(const std::vector<std::string>& runs, std::optional<SensorGroup> group,
                            const std::string& annotator) {
  return guardedStatus(*impl_, [&] {
    const std::string grp = group ? std::string(groupInfo(*group).shortName) : std::string();
    db::Transaction transaction(impl_->connection);
    for (const std::string& run : runs) {
      const std::int64_t runId = impl_->runIdByName(run);
      impl_->statement("DELETE FROM assignments WHERE run_id = ? AND grp = ? AND annotator = ?")
          .bind(1, runId)
          .bind(2, grp)
          .bind(3, annotator)
          .run();
      if (impl_->connection.changes() == 0) {
        throw db::DbError("run '" + run + "'" + (grp.empty() ? "" : " group " + grp) +
                          " is not assigned to " + annotator);
      }
    }
    transaction.commit();
  });
}

Result<std::vector<Assignment>> LabelStore::assignments(const std::string& annotator) {
  return guarded<std::vector<Assignment>>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT assignments.id, runs.name, run_id, grp, annotator, label_set, state, updated_by, "
        "updated_at FROM assignments JOIN runs ON runs.id = run_id "
        "WHERE ?1 = '' OR annotator = ?1 ORDER BY runs.name, grp, annotator");
    s.bind(1, annotator);
    std::vector<Assignment> out;
    while (s.step()) {
      Assignment a;
      a.id = s.columnInt(0);
      a.run = s.columnText(1);
      a.runId = s.columnInt(2);
      if (const std::string_view grp = s.columnTextView(3); !grp.empty()) {
        a.group = parseSensorGroup(grp);
        if (!a.group) throw db::DbError("malformed assignment " + std::to_string(a.id));
      }
      a.annotator = s.columnText(4);
      a.labelSet = s.columnText(5);
      const auto state = parseAssignmentState(s.columnTextView(6));
      if (!state) throw db::DbError("malformed assignment " + std::to_string(a.id));
      a.state = *state;
      a.updatedBy = s.columnText(7);
      a.updatedAt = s.columnText(8);
      out.push_back(std::move(a));
    }
    return out;
  });
}

}  // namespace tactile::storage
