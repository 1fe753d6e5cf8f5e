// Label segments of one (set, run, group) within a step range: read one segment, read a range,
// replace a range. The workspace builds undo and redo of label edits on these
// (docs/workflow.md#label-edits-and-undo).
#include <algorithm>
#include <string>
#include <vector>

#include "storage/database_impl.h"

namespace tactile::storage {

LabelSegment labelSegmentFromRow(db::Statement& s) {
  LabelSegment segment;
  segment.id = s.columnInt(0);
  segment.run = s.columnText(1);
  segment.runId = s.columnInt(2);
  const auto group = parseSensorGroup(s.columnTextView(3));
  const auto cls = parseContactClass(s.columnTextView(6));
  if (!group || !cls) throw db::DbError("malformed label segment " + std::to_string(segment.id));
  segment.group = *group;
  segment.firstStep = s.columnInt(4);
  segment.lastStep = s.columnInt(5);
  segment.cls = *cls;
  segment.annotator = s.columnText(7);
  return segment;
}

Result<LabelSegment> LabelStore::segment(std::int64_t setId, std::int64_t segmentId) {
  return guarded<LabelSegment>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT label_segments.id, runs.name, run_id, grp, first_step, last_step, class, "
        "annotator FROM label_segments JOIN runs ON runs.id = run_id "
        "WHERE label_segments.id = ? AND set_id = ?");
    s.bind(1, segmentId).bind(2, setId);
    if (!s.step()) {
      throw db::DbError("no label segment with id " + std::to_string(segmentId) + " in label set " +
                        std::to_string(setId));
    }
    LabelSegment out = labelSegmentFromRow(s);
    s.reset();
    return out;
  });
}

std::vector<LabelSegment> RunDatabase::Impl::overlappingSegments(std::int64_t setId,
                                                                 std::int64_t runId,
                                                                 SensorGroup group,
                                                                 std::int64_t firstStep,
                                                                 std::int64_t lastStep) {
  db::Statement& s = statement(
      "SELECT label_segments.id, runs.name, run_id, grp, first_step, last_step, class, "
      "annotator FROM label_segments JOIN runs ON runs.id = run_id "
      "WHERE set_id = ? AND run_id = ? AND grp = ? AND first_step <= ? AND last_step >= ? "
      "ORDER BY first_step");
  s.bind(1, setId)
      .bind(2, runId)
      .bind(3, groupInfo(group).shortName)
      .bind(4, lastStep)
      .bind(5, firstStep);
  std::vector<LabelSegment> out;
  while (s.step())
    out.push_back(labelSegmentFromRow(s));
  s.reset();
  return out;
}

Result<std::vector<LabelSegment>> LabelStore::segmentsInRange(std::int64_t setId,
                                                              std::int64_t runId, SensorGroup group,
                                                              std::int64_t firstStep,
                                                              std::int64_t lastStep) {
  return guarded<std::vector<LabelSegment>>(
      *impl_, [&] { return impl_->overlappingSegments(setId, runId, group, firstStep, lastStep); });
}

Status LabelStore::replaceSegmentsInRange(std::int64_t setId, std::int64_t runId, SensorGroup group,
                                          std::int64_t firstStep, std::int64_t lastStep,
                                          const std::vector<LabelSegment>& with,
                                          const EditOptions& options) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    const std::string_view groupName = groupInfo(group).shortName;
    // The steps this changes: the range, the whole of every segment it removes, and `with`.
    std::int64_t first = firstStep;
    std::int64_t last = lastStep;
    {
      db::Statement& s = impl_->statement(
          "SELECT MIN(first_step), MAX(last_step) FROM label_segments WHERE set_id = ? AND "
          "run_id = ? AND grp = ? AND first_step <= ? AND last_step >= ?");
      s.bind(1, setId).bind(2, runId).bind(3, groupName).bind(4, lastStep).bind(5, firstStep);
      if (s.step() && !s.columnIsNull(0)) {
        first = std::min(first, s.columnInt(0));
        last = std::max(last, s.columnInt(1));
      }
      s.reset();
    }
    for (const LabelSegment& s : with) {
      first = std::min(first, s.firstStep);
      last = std::max(last, s.lastStep);
    }
    impl_->checkExpectedRevision(setId, runId, group, first, last, options);
    const std::vector<LabelSegment> replaced =
        impl_->clippedSegments(setId, runId, group, first, last);
    impl_
        ->statement(
            "DELETE FROM label_segments WHERE set_id = ? AND run_id = ? AND grp = ? AND "
            "first_step <= ? AND last_step >= ?")
        .bind(1, setId)
        .bind(2, runId)
        .bind(3, groupName)
        .bind(4, lastStep)
        .bind(5, firstStep)
        .run();
    for (LabelSegment segment : with) {
      segment.runId = runId;
      segment.group = group;
      impl_->insertSegmentNewestWins(setId, segment, 0);
    }
    const bool one = with.size() == 1 && with[0].firstStep == first && with[0].lastStep == last;
    impl_->recordRevision(setId, runId, group, first, last,
                          one ? std::optional<ContactClass>(with[0].cls) : std::nullopt,
                          options.action.empty() ? "restore" : options.action, options.annotator,
                          replaced);
    transaction.commit();
  });
}

}  // namespace tactile::storage
