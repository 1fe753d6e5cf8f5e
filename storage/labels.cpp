// Label sets and segments. Every public call that changes something is one committed
// transaction, so a killed process loses at most the edit in flight.
#include <algorithm>
#include <array>
#include <map>

#include "base/file_text.h"
#include "run/label_file.h"
#include "run/run_csv.h"
#include "storage/database_impl.h"
#include "storage/run_codec.h"

namespace tactile::storage {
namespace {

bool isJsonPath(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".json";
}

}  // namespace

std::int64_t RunDatabase::Impl::labelSetIdByName(std::string_view name) {
  db::Statement& s = statement("SELECT id FROM label_sets WHERE name = ?");
  s.bind(1, name);
  const std::int64_t id = s.step() ? s.columnInt(0) : 0;
  s.reset();
  return id;
}

std::int64_t RunDatabase::Impl::ensureLabelSet(const std::string& name) {
  requireName(name, "label set");
  if (const std::int64_t id = labelSetIdByName(name); id != 0) return id;
  const std::string now = utcNow();
  return statement("INSERT INTO label_sets(name, created_at) VALUES(?, ?) RETURNING id")
      .bind(1, name)
      .bind(2, now)
      .runReturningId();
}

std::int64_t RunDatabase::Impl::insertSegmentNewestWins(std::int64_t setId,
                                                        const LabelSegment& segment,
                                                        std::int64_t keepId) {
  if (!segment.annotator.empty()) requireName(segment.annotator, "annotator");
  std::int64_t runId = segment.runId;
  if (runId == 0) runId = runIdByName(segment.run);
  const std::int64_t steps = runStepCount(runId);
  if (segment.firstStep < 0 || segment.lastStep < segment.firstStep || segment.lastStep >= steps) {
    throw db::DbError("segment " + std::to_string(segment.firstStep) + ".." +
                      std::to_string(segment.lastStep) + " is not within the run's steps 0.." +
                      std::to_string(steps - 1));
  }
  const std::string_view group = groupInfo(segment.group).shortName;
  const std::int64_t a = segment.firstStep;
  const std::int64_t b = segment.lastStep;

  struct Old {
    std::int64_t id, first, last;
    std::string cls, annotator, created;
  };
  std::vector<Old> overlapping;
  {
    db::Statement& s = statement(
        "SELECT id, first_step, last_step, class, annotator, created_at FROM label_segments "
        "WHERE set_id = ? AND run_id = ? AND grp = ? AND first_step <= ? AND last_step >= ?");
    s.bind(1, setId).bind(2, runId).bind(3, group).bind(4, b).bind(5, a);
    while (s.step()) {
      overlapping.push_back({s.columnInt(0), s.columnInt(1), s.columnInt(2), s.columnText(3),
                             s.columnText(4), s.columnText(5)});
    }
    s.reset();
  }
  for (const Old& old : overlapping) {
    if (old.first >= a && old.last <= b) {
      statement("DELETE FROM label_segments WHERE id = ?").bind(1, old.id).run();
      continue;
    }
    if (old.first < a) {
      statement("UPDATE label_segments SET last_step = ? WHERE id = ?")
          .bind(1, a - 1)
          .bind(2, old.id)
          .run();
      if (old.last > b) {  // the new segment splits the old one: keep its right part too
        statement(
            "INSERT INTO label_segments(set_id, run_id, grp, first_step, last_step, class, "
            "annotator, created_at) VALUES(?, ?, ?, ?, ?, ?, ?, ?)")
            .bind(1, setId)
            .bind(2, runId)
            .bind(3, group)
            .bind(4, b + 1)
            .bind(5, old.last)
            .bind(6, old.cls)
            .bind(7, old.annotator)
            .bind(8, old.created)
            .run();
      }
    } else {
      statement("UPDATE label_segments SET first_step = ? WHERE id = ?")
          .bind(1, b + 1)
          .bind(2, old.id)
          .run();
    }
  }
  const std::string now = utcNow();
  // A new segment takes its id from the database (a sequence on PostgreSQL), a kept one its own.
  db::Statement& insert =
      keepId != 0 ? statement(
                        "INSERT INTO label_segments(set_id, run_id, grp, first_step, last_step, "
                        "class, annotator, created_at, id) "
                        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id")
                  : statement(
                        "INSERT INTO label_segments(set_id, run_id, grp, first_step, last_step, "
                        "class, annotator, created_at) "
                        "VALUES(?, ?, ?, ?, ?, ?, ?, ?) RETURNING id");
  if (keepId != 0) insert.bind(9, keepId);
  return insert.bind(1, setId)
      .bind(2, runId)
      .bind(3, group)
      .bind(4, a)
      .bind(5, b)
      .bind(6, contactClassName(segment.cls))
      .bind(7, segment.annotator)
      .bind(8, now)
      .runReturningId();
}

Result<std::vector<LabelSetInfo>> LabelStore::list() {
  return guarded<std::vector<LabelSetInfo>>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT id, name, annotator, created_at, "
        "(SELECT count(*) FROM label_segments WHERE set_id = label_sets.id) "
        "FROM label_sets ORDER BY name");
    std::vector<LabelSetInfo> sets;
    while (s.step()) {
      sets.push_back(
          {s.columnInt(0), s.columnText(1), s.columnText(2), s.columnText(3), s.columnInt(4)});
    }
    return sets;
  });
}

Result<LabelSetInfo> LabelStore::find(std::string_view name) {
  const ResetStatements reset{*impl_};
  Result<std::vector<LabelSetInfo>> sets = list();
  if (!sets) return sets.error();
  for (LabelSetInfo& info : sets.value()) {
    if (info.name == name) return info;
  }
  return Result<LabelSetInfo>::failure("no label set named '" + std::string(name) + "'");
}

Result<std::int64_t> LabelStore::create(const std::string& name, const std::string& annotator) {
  return guarded<std::int64_t>(*impl_, [&] {
    requireName(name, "label set");
    if (!annotator.empty()) requireName(annotator, "annotator");
    db::Transaction transaction(impl_->connection);
    if (impl_->labelSetIdByName(name) != 0) {
      throw db::DbError("a label set named '" + name + "' already exists");
    }
    const std::string now = utcNow();
    const std::int64_t id =
        impl_
            ->statement(
                "INSERT INTO label_sets(name, annotator, created_at) VALUES(?, ?, ?) RETURNING id")
            .bind(1, name)
            .bind(2, annotator)
            .bind(3, now)
            .runReturningId();
    transaction.commit();
    return id;
  });
}

Result<std::int64_t> LabelStore::copy(std::int64_t setId, const std::string& newName) {
  return guarded<std::int64_t>(*impl_, [&] {
    requireName(newName, "label set");
    db::Transaction transaction(impl_->connection);
    if (impl_->labelSetIdByName(newName) != 0) {
      throw db::DbError("a label set named '" + newName + "' already exists");
    }
    const std::string now = utcNow();
    db::Statement& copy = impl_->statement(
        "INSERT INTO label_sets(name, annotator, created_at) "
        "SELECT ?, annotator, ? FROM label_sets WHERE id = ? RETURNING id");
    copy.bind(1, newName).bind(2, now).bind(3, setId);
    if (!copy.step()) throw db::DbError("no label set with id " + std::to_string(setId));
    const std::int64_t id = copy.columnInt(0);
    copy.reset();
    impl_
        ->statement(
            "INSERT INTO label_segments(set_id, run_id, grp, first_step, last_step, class, "
            "annotator, created_at) SELECT ?, run_id, grp, first_step, last_step, class, "
            "annotator, created_at FROM label_segments WHERE set_id = ? ORDER BY id")
        .bind(1, id)
        .bind(2, setId)
        .run();
    impl_
        ->statement(
            "INSERT INTO label_revisions(set_id, run_id, grp, first_step, last_step, class, "
            "action, annotator, created_at, replaced) SELECT ?, run_id, grp, first_step, "
            "last_step, class, action, annotator, created_at, replaced FROM label_revisions "
            "WHERE set_id = ? ORDER BY id")
        .bind(1, id)
        .bind(2, setId)
        .run();
    transaction.commit();
    return id;
  });
}

namespace {

// The annotator an edit is recorded under, and writes into its segments.
std::string editor(const EditOptions& options, const LabelSegment& segment) {
  return options.annotator.empty() ? segment.annotator : options.annotator;
}

}  // namespace

Result<std::int64_t> LabelStore::addSegment(std::int64_t setId, const LabelSegment& segment,
                                            const EditOptions& options) {
  return guarded<std::int64_t>(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    db::Statement& set = impl_->statement("SELECT 1 FROM label_sets WHERE id = ?");
    set.bind(1, setId);
    if (!set.step()) throw db::DbError("no label set with id " + std::to_string(setId));
    set.reset();
    LabelSegment added = segment;
    added.annotator = editor(options, segment);
    if (added.runId == 0) added.runId = impl_->runIdByName(segment.run);
    impl_->checkExpectedRevision(setId, added.runId, added.group, added.firstStep, added.lastStep,
                                 options);
    const std::vector<LabelSegment> replaced =
        impl_->clippedSegments(setId, added.runId, added.group, added.firstStep, added.lastStep);
    const std::int64_t id = impl_->insertSegmentNewestWins(setId, added, 0);
    impl_->recordRevision(setId, added.runId, added.group, added.firstStep, added.lastStep,
                          added.cls, options.action.empty() ? "set" : options.action,
                          added.annotator, replaced);
    transaction.commit();
    return id;
  });
}

Status LabelStore::changeSegment(std::int64_t segmentId, const LabelSegment& segment,
                                 const EditOptions& options) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    db::Statement& s = impl_->statement(
        "SELECT set_id, run_id, grp, first_step, last_step FROM label_segments WHERE id = ?");
    s.bind(1, segmentId);
    if (!s.step()) throw db::DbError("no label segment with id " + std::to_string(segmentId));
    const std::int64_t setId = s.columnInt(0);
    const std::int64_t oldRun = s.columnInt(1);
    const auto oldGroup = parseSensorGroup(s.columnTextView(2));
    const std::int64_t oldFirst = s.columnInt(3);
    const std::int64_t oldLast = s.columnInt(4);
    s.reset();
    if (!oldGroup) throw db::DbError("malformed label segment " + std::to_string(segmentId));
    LabelSegment changed = segment;
    changed.annotator = editor(options, segment);
    if (changed.runId == 0 && changed.run.empty()) changed.runId = oldRun;
    if (changed.runId == 0) changed.runId = impl_->runIdByName(changed.run);
    // The steps it leaves and the steps it takes, in its old and new group.
    const bool moves = changed.runId != oldRun || changed.group != *oldGroup;
    const std::int64_t first = moves ? changed.firstStep : std::min(oldFirst, changed.firstStep);
    const std::int64_t last = moves ? changed.lastStep : std::max(oldLast, changed.lastStep);
    impl_->checkExpectedRevision(setId, oldRun, *oldGroup, oldFirst, oldLast, options);
    impl_->checkExpectedRevision(setId, changed.runId, changed.group, first, last, options);
    const std::vector<LabelSegment> leftBehind =
        moves ? impl_->clippedSegments(setId, oldRun, *oldGroup, oldFirst, oldLast)
              : std::vector<LabelSegment>{};
    const std::vector<LabelSegment> replaced =
        impl_->clippedSegments(setId, changed.runId, changed.group, first, last);
    impl_->statement("DELETE FROM label_segments WHERE id = ?").bind(1, segmentId).run();
    impl_->insertSegmentNewestWins(setId, changed, segmentId);
    const std::string action = options.action.empty() ? "change" : options.action;
    if (moves) {
      impl_->recordRevision(setId, oldRun, *oldGroup, oldFirst, oldLast, std::nullopt, action,
                            changed.annotator, leftBehind);
    }
    const bool whole = changed.firstStep == first && changed.lastStep == last;
    impl_->recordRevision(setId, changed.runId, changed.group, first, last,
                          whole ? std::optional<ContactClass>(changed.cls) : std::nullopt, action,
                          changed.annotator, replaced);
    transaction.commit();
  });
}

Status LabelStore::removeSegment(std::int64_t segmentId, const EditOptions& options) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    db::Statement& s = impl_->statement(
        "SELECT set_id, run_id, grp, first_step, last_step, annotator FROM label_segments "
        "WHERE id = ?");
    s.bind(1, segmentId);
    if (!s.step()) throw db::DbError("no label segment with id " + std::to_string(segmentId));
    const std::int64_t setId = s.columnInt(0);
    const std::int64_t runId = s.columnInt(1);
    const auto group = parseSensorGroup(s.columnTextView(2));
    const std::int64_t first = s.columnInt(3);
    const std::int64_t last = s.columnInt(4);
    s.reset();
    if (!group) throw db::DbError("malformed label segment " + std::to_string(segmentId));
    impl_->checkExpectedRevision(setId, runId, *group, first, last, options);
    const std::vector<LabelSegment> replaced =
        impl_->clippedSegments(setId, runId, *group, first, last);
    impl_->statement("DELETE FROM label_segments WHERE id = ?").bind(1, segmentId).run();
    impl_->recordRevision(setId, runId, *group, first, last, std::nullopt,
                          options.action.empty() ? "delete" : options.action, options.annotator,
                          replaced);
    transaction.commit();
  });
}

Result<std::vector<std::pair<std::int64_t, std::int64_t>>> LabelStore::labelledSteps(
    std::int64_t setId) {
  return guarded<std::vector<std::pair<std::int64_t, std::int64_t>>>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT run_id, CAST(SUM(last_step - first_step + 1) AS BIGINT) FROM label_segments WHERE "
        "set_id = ? "
        "GROUP BY run_id ORDER BY run_id");
    s.bind(1, setId);
    std::vector<std::pair<std::int64_t, std::int64_t>> out;
    while (s.step())
      out.emplace_back(s.columnInt(0), s.columnInt(1));
    return out;
  });
}

Result<std::vector<std::pair<std::int64_t, std::int64_t>>> LabelStore::modelLabelledSteps(
    std::int64_t setId) {
  return guarded<std::vector<std::pair<std::int64_t, std::int64_t>>>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT run_id, CAST(SUM(last_step - first_step + 1) AS BIGINT) FROM label_segments WHERE "
        "set_id = ? AND annotator LIKE 'model:%' GROUP BY run_id ORDER BY run_id");
    s.bind(1, setId);
    std::vector<std::pair<std::int64_t, std::int64_t>> out;
    while (s.step())
      out.emplace_back(s.columnInt(0), s.columnInt(1));
    return out;
  });
}

Result<std::vector<LabelSegment>> LabelStore::segments(std::int64_t setId, std::int64_t runId) {
  return guarded<std::vector<LabelSegment>>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT label_segments.id, runs.name, run_id, grp, first_step, last_step, class, "
        "annotator FROM label_segments JOIN runs ON runs.id = run_id "
        "WHERE set_id = ?1 AND (?2 = 0 OR run_id = ?2)");
    s.bind(1, setId).bind(2, runId);
    std::vector<LabelSegment> out;
    while (s.step())
      out.push_back(labelSegmentFromRow(s));
    std::sort(out.begin(), out.end(), [](const LabelSegment& l, const LabelSegment& r) {
      return std::tie(l.run, l.group, l.firstStep) < std::tie(r.run, r.group, r.firstStep);
    });
    return out;
  });
}

Result<std::int64_t> LabelStore::importFile(const std::string& setName,
                                            const std::filesystem::path& file) {
  return guarded<std::int64_t>(*impl_, [&] {
    Result<std::string> content = readFileText(file);
    if (!content) throw db::DbError(content.errorText());
    const std::string& text = content.value();
    Result<LabelFile> read =
        isJsonPath(file) ? parseLabelJson(text, file.string()) : parseLabelCsv(text, file.string());
    if (!read) throw db::DbError(read.errorText());
    const LabelFile& parsed = read.value();
    db::Transaction transaction(impl_->connection);
    // Provenance: the file was made for runs of this step count and checksum; a stored run of
    // the same name with other content is not the run the labels are about.
    for (const LabelRunProvenance& p : parsed.runs) {
      db::Statement& s = impl_->statement("SELECT step_count, checksum FROM runs WHERE name = ?");
      s.bind(1, p.name);
      if (!s.step()) continue;  // a row naming this run fails below as an unknown run
      const std::int64_t steps = s.columnInt(0);
      const std::string checksum = s.columnText(1);
      s.reset();
      if (steps != p.steps || checksum != p.checksum) {
        throw db::DbError(file.string() + ":" + std::to_string(p.line) + ": run '" + p.name +
                          "': the label file was made for " + std::to_string(p.steps) +
                          " steps, checksum " + p.checksum + ", but the database's run '" + p.name +
                          "' has " + std::to_string(steps) + " steps, checksum " + checksum +
                          " (a different run of the same name)");
      }
    }
    const std::int64_t setId = impl_->ensureLabelSet(setName);
    std::map<std::string, std::int64_t> runIds;
    for (const LabelRecord& record : parsed.records) {
      const std::string where = file.string() + ":" + std::to_string(record.line) + ": ";
      auto it = runIds.find(record.run);
      if (it == runIds.end()) {
        db::Statement& s = impl_->statement("SELECT id FROM runs WHERE name = ?");
        s.bind(1, record.run);
        if (!s.step())
          throw db::DbError(where + "no run named '" + record.run + "' in the database");
        it = runIds.emplace(record.run, s.columnInt(0)).first;
        s.reset();
      }
      LabelSegment segment;
      segment.runId = it->second;
      segment.group = record.group;
      segment.firstStep = record.firstStep;
      segment.lastStep = record.lastStep;
      segment.cls = record.cls;
      segment.annotator = record.annotator;
      try {
        const std::vector<LabelSegment> replaced = impl_->clippedSegments(
            setId, segment.runId, segment.group, segment.firstStep, segment.lastStep);
        impl_->insertSegmentNewestWins(setId, segment, 0);
        impl_->recordRevision(setId, segment.runId, segment.group, segment.firstStep,
                              segment.lastStep, segment.cls, "import", segment.annotator, replaced);
      } catch (const db::DbError& e) {
        throw db::DbError(where + e.what());
      }
    }
    transaction.commit();
    return static_cast<std::int64_t>(parsed.records.size());
  });
}

Status LabelStore::exportFile(const std::string& setName, const std::filesystem::path& file) {
  const ResetStatements reset{*impl_};
  Result<LabelSetInfo> set = find(setName);
  if (!set) return set.error();
  Result<std::vector<LabelSegment>> all = segments(set->id);
  if (!all) return all.error();
  std::vector<LabelRecord> records;
  records.reserve(all->size());
  std::vector<LabelRunProvenance> runs;  // every run of the set, in the segments' (name) order
  for (const LabelSegment& s : all.value()) {
    records.push_back({s.run, s.group, s.firstStep, s.lastStep, s.cls, s.annotator, 0});
    if (runs.empty() || runs.back().name != s.run) {
      Result<RunInfo> info = RunStore(*impl_).info(s.runId);
      if (!info) return info.error();
      runs.push_back({info->name, info->stepCount, info->checksum, 0});
    }
  }
  const std::string text = isJsonPath(file)
                               ? formatLabelJson(records, set->name, set->annotator, runs)
                               : formatLabelCsv(records, runs);
  return writeFileAtomically(file, text);
}

Result<std::int64_t> LabelStore::autolabel(std::int64_t runId, const std::string& setName) {
  return guarded<std::int64_t>(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    db::Statement& s = impl_->statement("SELECT name, has_truth FROM runs WHERE id = ?");
    s.bind(1, runId);
    if (!s.step()) throw db::DbError("no run with id " + std::to_string(runId));
    const std::string runName = s.columnText(0);
    const bool hasTruth = s.columnInt(1) != 0;
    s.reset();
    if (!hasTruth) throw db::DbError("run '" + runName + "' has no truth columns to label from");
    const std::int64_t setId = impl_->ensureLabelSet(setName);
    const std::int64_t runSteps = impl_->runStepCount(runId);
    std::vector<std::vector<LabelSegment>> replaced;
    for (const GroupInfo& group : kSensorGroups) {
      replaced.push_back(runSteps > 0
                             ? impl_->clippedSegments(setId, runId, group.group, 0, runSteps - 1)
                             : std::vector<LabelSegment>{});
    }
    impl_->statement("DELETE FROM label_segments WHERE set_id = ? AND run_id = ?")
        .bind(1, setId)
        .bind(2, runId)
        .run();
    std::vector<ContactClass> truth;
    truth.reserve(static_cast<std::size_t>(impl_->runStepCount(runId)) * kGroupCount);
    db::Statement& steps =
        impl_->statement("SELECT step, truth FROM steps WHERE run_id = ? ORDER BY step");
    steps.bind(1, runId);
    std::array<ContactClass, kGroupCount> classes{};
    std::int64_t expected = 0;
    while (steps.step()) {
      if (steps.columnInt(0) != expected || steps.columnIsNull(1) ||
          !unpackTruth(steps.columnInt(1), classes.data())) {
        throw db::DbError("run '" + runName + "' has missing or malformed truth at step " +
                          std::to_string(expected));
      }
      truth.insert(truth.end(), classes.begin(), classes.end());
      ++expected;
    }
    const std::string now = utcNow();
    db::Statement& insert = impl_->statement(
        "INSERT INTO label_segments(set_id, run_id, grp, first_step, last_step, class, annotator, "
        "created_at) VALUES(?, ?, ?, ?, ?, ?, 'truth', ?)");
    insert.bind(1, setId).bind(2, runId).bind(7, now);
    std::int64_t written = 0;
    for (const TruthSegment& segment : truthSegments(truth.data(), truth.size() / kGroupCount)) {
      insert.bind(3, groupInfo(segment.group).shortName)
          .bind(4, segment.firstStep)
          .bind(5, segment.lastStep)
          .bind(6, contactClassName(segment.cls))
          .run();
      ++written;
    }
    if (runSteps > 0) {
      for (std::size_t g = 0; g < kSensorGroups.size(); ++g) {
        impl_->recordRevision(setId, runId, kSensorGroups[g].group, 0, runSteps - 1, std::nullopt,
                              "truth", "truth", replaced[g]);
      }
    }
    transaction.commit();
    return written;
  });
}

}  // namespace tactile::storage
