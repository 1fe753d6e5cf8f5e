// Copies between two databases of either backend (docs/team.md#copies): runs row by row with their
// stored bytes (so nothing is decoded and encoded again and every checksum stays), label sets by
// name, models and sweeps by name and content. A second copy adds nothing.
#include <map>
#include <set>

#include "storage/database_impl.h"
#include "storage/step_checksum.h"

namespace tactile::storage {
namespace {

bool selected(const std::vector<std::string>& names, const std::string& name) {
  return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
}

// The unknown names of `wanted` among `known`, as "'a', 'b'".
std::string unknownNames(const std::vector<std::string>& wanted,
                         const std::set<std::string>& known) {
  std::string out;
  for (const std::string& name : wanted) {
    if (known.count(name) != 0) continue;
    out += (out.empty() ? "'" : ", '") + name + "'";
  }
  return out;
}

struct SourceRun {
  std::int64_t id = 0;
  std::string name, sourceFile, checksum, scene, subject, outcome, importedAt;
  bool hasScene = false, hasSubject = false, hasDt = false;
  std::int64_t sceneId = 0;
  double dt = 0.0;
  std::int64_t steps = 0;
  bool hasTruth = false;
  std::string metadata, extraColumns;
  std::int64_t crc = 0;
  bool hasCrc = false;
};

// Copies one run's rows inside the target's open transaction; returns the new run id. The source
// rows are checked against their checksums on the way (a damaged source is not spread), and the
// target's checksums are computed for the new run id.
std::int64_t copyRunRows(RunDatabase::Impl& from, RunDatabase::Impl& to, const SourceRun& run) {
  const auto fail = [&](const std::string& what) {
    throw db::DbError(from.path.string(), "run '" + run.name + "': " + what + "; nothing copied");
  };
  if (!run.hasCrc || run.crc != runChecksum(run.id, run.name, run.steps, run.hasTruth,
                                            run.metadata.data(), run.metadata.size(),
                                            run.extraColumns.data(), run.extraColumns.size())) {
    fail("its row does not match its checksum (`tactile db check` on the source)");
  }
  std::int64_t sceneId = 0;
  if (run.sceneId != 0) {
    db::Statement& scene = from.statement("SELECT name, checksum, json FROM scenes WHERE id = ?");
    scene.bind(1, run.sceneId);
    if (scene.step()) {
      const std::string name = scene.columnText(0);
      const std::string checksum = scene.columnText(1);
      const std::string json = scene.columnText(2);
      scene.reset();
      to.statement(
            "INSERT INTO scenes(name, checksum, json) VALUES(?, ?, ?) ON CONFLICT DO NOTHING")
          .bind(1, name)
          .bind(2, checksum)
          .bind(3, json)
          .run();
      db::Statement& id = to.statement("SELECT id FROM scenes WHERE checksum = ?");
      id.bind(1, checksum);
      if (id.step()) sceneId = id.columnInt(0);
      id.reset();
    } else {
      scene.reset();
    }
  }
  db::Statement& insert = to.statement(
      "INSERT INTO runs(name, source_file, checksum, scene, scene_id, subject, outcome, dt, "
      "step_count, has_truth, metadata, extra_columns, imported_at) "
      "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id");
  insert.bind(1, run.name).bind(2, run.sourceFile).bind(3, run.checksum);
  if (run.hasScene) {
    insert.bind(4, run.scene);
  } else {
    insert.bindNull(4);
  }
  if (sceneId != 0) {
    insert.bind(5, sceneId);
  } else {
    insert.bindNull(5);
  }
  if (run.hasSubject) {
    insert.bind(6, run.subject);
  } else {
    insert.bindNull(6);
  }
  insert.bind(7, run.outcome);
  if (run.hasDt) {
    insert.bind(8, run.dt);
  } else {
    insert.bindNull(8);
  }
  insert.bind(9, run.steps)
      .bind(10, run.hasTruth ? 1 : 0)
      .bindBlob(11, run.metadata.data(), run.metadata.size())
      .bindBlob(12, run.extraColumns.data(), run.extraColumns.size())
      .bind(13, run.importedAt);
  const std::int64_t newId = insert.runReturningId();
  to.statement("UPDATE runs SET crc = ? WHERE id = ?")
      .bind(1, static_cast<std::int64_t>(runChecksum(
                   newId, run.name, run.steps, run.hasTruth, run.metadata.data(),
                   run.metadata.size(), run.extraColumns.data(), run.extraColumns.size())))
      .bind(2, newId)
      .run();

  db::Statement steps(from.connection,
                      "SELECT step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc "
                      "FROM steps WHERE run_id = ? ORDER BY step",
                      db::Statement::Streamed{});
  steps.bind(1, run.id);
  db::RowWriter stepRows(to.connection, "steps",
                         "run_id, step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc",
                         12);
  std::int64_t expected = 0;
  while (steps.step()) {
    StepRow row = stepRowAt(steps, run.id);
    const bool hasExtra = !steps.columnIsNull(8);
    if (row.step != expected || steps.columnIsNull(10) ||
        steps.columnInt(10) != stepChecksum(row)) {
      fail("step " + std::to_string(row.step) +
           " does not match its checksum (`tactile db check` on the source)");
    }
    ++expected;
    row.runId = newId;
    stepRows.bind(1, newId)
        .bind(2, row.step)
        .bind(3, row.x)
        .bind(4, row.y)
        .bind(5, row.theta)
        .bind(6, row.v)
        .bind(7, row.omega)
        .bind(8, row.blocked)
        .bindBlob(9, row.sensors, row.sensorBytes);
    if (hasExtra) {
      stepRows.bindBlob(10, row.extra, row.extraBytes);
    } else {
      stepRows.bindNull(10);
    }
    if (row.hasTruth) {
      stepRows.bind(11, row.truth);
    } else {
      stepRows.bindNull(11);
    }
    stepRows.bind(12, static_cast<std::int64_t>(stepChecksum(row)));
    stepRows.add();
  }
  steps.reset();
  stepRows.finish();
  if (expected != run.steps) {
    fail("holds " + std::to_string(expected) + " steps where its row says " +
         std::to_string(run.steps));
  }

  db::Statement blocks(from.connection,
                       "SELECT level, block, minmax, crc FROM step_blocks WHERE run_id = ? "
                       "ORDER BY level, block");
  blocks.bind(1, run.id);
  db::RowWriter blockRows(to.connection, "step_blocks", "run_id, level, block, minmax, crc", 5);
  while (blocks.step()) {
    const std::int64_t level = blocks.columnInt(0);
    const std::int64_t block = blocks.columnInt(1);
    if (blocks.columnIsNull(3) ||
        blocks.columnInt(3) !=
            blockChecksum(run.id, level, block, blocks.columnBlob(2), blocks.columnBytes(2))) {
      fail("summary block " + std::to_string(block) + " of level " + std::to_string(level) +
           " does not match its checksum");
    }
    blockRows.bind(1, newId)
        .bind(2, level)
        .bind(3, block)
        .bindBlob(4, blocks.columnBlob(2), blocks.columnBytes(2))
        .bind(5, static_cast<std::int64_t>(blockChecksum(newId, level, block, blocks.columnBlob(2),
                                                         blocks.columnBytes(2))));
    blockRows.add();
  }
  blocks.reset();
  blockRows.finish();
  return newId;
}

// Every row of the copied run read back from the target and checked against its checksum.
void verifyCopiedRun(RunDatabase::Impl& to, std::int64_t runId, const std::string& name,
                     std::int64_t stepCount) {
  db::Statement s(to.connection,
                  "SELECT step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc "
                  "FROM steps WHERE run_id = ? ORDER BY step",
                  db::Statement::Streamed{});
  s.bind(1, runId);
  std::int64_t count = 0;
  while (s.step()) {
    const StepRow row = stepRowAt(s, runId);
    if (s.columnIsNull(10) || s.columnInt(10) != stepChecksum(row)) {
      throw db::DbError(to.path.string(), "run '" + name + "' step " + std::to_string(row.step) +
                                              ": the copy does not match its checksum");
    }
    ++count;
  }
  if (count != stepCount) {
    throw db::DbError(to.path.string(), "run '" + name + "': the copy holds " +
                                            std::to_string(count) + " of " +
                                            std::to_string(stepCount) + " steps");
  }
}

}  // namespace

Result<CopyReport> RunDatabase::copyFrom(RunDatabase& source, const CopyOptions& options,
                                         const ProgressFn& progress) {
  Impl& from = *source.impl_;
  Impl& to = *impl_;
  const ResetStatements resetTo{to};
  const ResetStatements resetFrom{from};
  try {
    CopyReport report;
    // ---- runs
    std::vector<SourceRun> runs;
    std::set<std::string> runNames;
    {
      db::Statement s(from.connection,
                      "SELECT id, name, source_file, checksum, scene, scene_id, subject, outcome, "
                      "dt, step_count, has_truth, metadata, extra_columns, imported_at, crc "
                      "FROM runs ORDER BY name");
      while (s.step()) {
        SourceRun r;
        r.id = s.columnInt(0);
        r.name = s.columnText(1);
        runNames.insert(r.name);
        if (!selected(options.runs, r.name)) continue;
        r.sourceFile = s.columnText(2);
        r.checksum = s.columnText(3);
        r.hasScene = !s.columnIsNull(4);
        r.scene = s.columnText(4);
        r.sceneId = s.columnIsNull(5) ? 0 : s.columnInt(5);
        r.hasSubject = !s.columnIsNull(6);
        r.subject = s.columnText(6);
        r.outcome = s.columnText(7);
        r.hasDt = !s.columnIsNull(8);
        r.dt = s.columnDouble(8);
        r.steps = s.columnInt(9);
        r.hasTruth = s.columnInt(10) != 0;
        r.metadata.assign(static_cast<const char*>(s.columnBlob(11)), s.columnBytes(11));
        r.extraColumns.assign(static_cast<const char*>(s.columnBlob(12)), s.columnBytes(12));
        r.importedAt = s.columnText(13);
        r.hasCrc = !s.columnIsNull(14);
        r.crc = s.columnInt(14);
        runs.push_back(std::move(r));
      }
    }
    if (const std::string unknown = unknownNames(options.runs, runNames); !unknown.empty()) {
      return Error(from.path.string(), "no run named " + unknown + "; nothing copied");
    }
    std::size_t done = 0;
    const std::size_t total = runs.size();
    for (const SourceRun& run : runs) {
      if (progress && !progress(done, total)) return Error(to.path.string(), "cancelled");
      ++done;
      db::Transaction transaction(to.connection);
      db::Statement& existing = to.statement("SELECT checksum FROM runs WHERE name = ?");
      existing.bind(1, run.name);
      if (existing.step()) {
        const std::string checksum = existing.columnText(0);
        existing.reset();
        if (checksum == run.checksum) {
          ++report.runsPresent;
          continue;
        }
        throw db::DbError(to.path.string(),
                          "a run named '" + run.name + "' holds other content (checksum " +
                              checksum + ", the source's " + run.checksum +
                              "); rename one of them first (`tactile runs rename`)");
      }
      existing.reset();
      const std::int64_t newId = copyRunRows(from, to, run);
      verifyCopiedRun(to, newId, run.name, run.steps);
      transaction.commit();
      ++report.runsCopied;
      report.stepsCopied += run.steps;
    }

    // ---- label sets: segments on runs that exist in the target (by name)
    std::map<std::string, std::int64_t> targetRuns;
    {
      db::Statement s(to.connection, "SELECT name, id FROM runs");
      while (s.step())
        targetRuns[s.columnText(0)] = s.columnInt(1);
    }
    std::vector<std::pair<std::int64_t, LabelSetInfo>> sets;
    std::set<std::string> setNames;
    {
      db::Statement s(from.connection,
                      "SELECT id, name, annotator, created_at FROM label_sets ORDER BY name");
      while (s.step()) {
        LabelSetInfo info;
        info.id = s.columnInt(0);
        info.name = s.columnText(1);
        info.annotator = s.columnText(2);
        info.createdAt = s.columnText(3);
        setNames.insert(info.name);
        if (selected(options.sets, info.name)) sets.emplace_back(info.id, info);
      }
    }
    if (const std::string unknown = unknownNames(options.sets, setNames); !unknown.empty()) {
      return Error(from.path.string(), "no label set named " + unknown + "; nothing copied");
    }
    for (const auto& [sourceId, info] : sets) {
      std::vector<LabelSegment> segments;
      {
        db::Statement s(from.connection,
                        "SELECT label_segments.id, runs.name, run_id, grp, first_step, last_step, "
                        "class, annotator FROM label_segments JOIN runs ON runs.id = run_id "
                        "WHERE set_id = ? ORDER BY label_segments.id");
        s.bind(1, sourceId);
        while (s.step())
          segments.push_back(labelSegmentFromRow(s));
      }
      db::Transaction transaction(to.connection);
      std::int64_t setId = to.labelSetIdByName(info.name);
      if (setId == 0) {
        setId = to.statement(
                      "INSERT INTO label_sets(name, annotator, created_at) VALUES(?, ?, ?) "
                      "RETURNING id")
                    .bind(1, info.name)
                    .bind(2, info.annotator)
                    .bind(3, info.createdAt)
                    .runReturningId();
        ++report.setsCreated;
      }
      // Runs on which the target's set holds no segment take the source's segments as they are
      // (they do not overlap: newest-wins was applied in the source) in one bulk insert; on the
      // others each segment not already there is added, newest winning, in the source's order.
      std::set<std::int64_t> emptyRuns;
      {
        std::set<std::int64_t> used;
        db::Statement& runsWithSegments =
            to.statement("SELECT DISTINCT run_id FROM label_segments WHERE set_id = ?");
        runsWithSegments.bind(1, setId);
        while (runsWithSegments.step())
          used.insert(runsWithSegments.columnInt(0));
        runsWithSegments.reset();
        for (const auto& [name, id] : targetRuns) {
          if (used.count(id) == 0) emptyRuns.insert(id);
        }
      }
      std::vector<LabelSegment> bulk;
      db::Statement& same = to.statement(
          "SELECT 1 FROM label_segments WHERE set_id = ? AND run_id = ? AND grp = ? AND "
          "first_step = ? AND last_step = ? AND class = ? AND annotator = ?");
      for (LabelSegment segment : segments) {
        const auto run = targetRuns.find(segment.run);
        if (run == targetRuns.end()) {
          ++report.segmentsWithoutRun;
          continue;
        }
        segment.runId = run->second;
        if (emptyRuns.count(segment.runId) != 0) {
          bulk.push_back(segment);
          continue;
        }
        const std::string group(groupInfo(segment.group).shortName);
        const std::string cls(contactClassName(segment.cls));
        same.bind(1, setId)
            .bind(2, segment.runId)
            .bind(3, group)
            .bind(4, segment.firstStep)
            .bind(5, segment.lastStep)
            .bind(6, cls)
            .bind(7, segment.annotator);
        const bool present = same.step();
        same.reset();
        if (present) continue;
        to.insertSegmentNewestWins(setId, segment, 0);
        ++report.segmentsCopied;
      }
      if (!bulk.empty()) {
        const std::string now = utcNow();
        db::RowWriter rows(to.connection, "label_segments",
                           "set_id, run_id, grp, first_step, last_step, class, annotator, "
                           "created_at",
                           8);
        for (const LabelSegment& segment : bulk) {
          const std::string_view group = groupInfo(segment.group).shortName;
          const std::string_view cls = contactClassName(segment.cls);
          rows.bind(1, setId)
              .bind(2, segment.runId)
              .bindText(3, group)
              .bind(4, segment.firstStep)
              .bind(5, segment.lastStep)
              .bindText(6, cls)
              .bindText(7, segment.annotator)
              .bindText(8, now);
          rows.add();
        }
        rows.finish();
        report.segmentsCopied += static_cast<std::int64_t>(bulk.size());
      }
      // The set's history on the runs both hold, in its order; a revision already here (the same
      // edit, time and what it replaced) is not added again.
      {
        db::Statement s(from.connection,
                        "SELECT runs.name, grp, first_step, last_step, class, action, "
                        "label_revisions.annotator, label_revisions.created_at, replaced "
                        "FROM label_revisions JOIN runs ON runs.id = run_id WHERE set_id = ? "
                        "ORDER BY label_revisions.id");
        s.bind(1, sourceId);
        db::Statement& present = to.statement(
            "SELECT 1 FROM label_revisions WHERE set_id = ? AND run_id = ? AND grp = ? AND "
            "first_step = ? AND last_step = ? AND action = ? AND annotator = ? AND created_at = ? "
            "AND replaced = ? AND (class = ? OR (class IS NULL AND ? = ''))");
        db::Statement& insert = to.statement(
            "INSERT INTO label_revisions(set_id, run_id, grp, first_step, last_step, class, "
            "action, annotator, created_at, replaced) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
        while (s.step()) {
          const auto run = targetRuns.find(s.columnText(0));
          if (run == targetRuns.end()) continue;
          const std::string grp = s.columnText(1);
          const std::string cls = s.columnIsNull(4) ? std::string() : s.columnText(4);
          const std::string action = s.columnText(5);
          const std::string annotator = s.columnText(6);
          const std::string time = s.columnText(7);
          const std::string replaced = s.columnText(8);
          present.bind(1, setId)
              .bind(2, run->second)
              .bind(3, grp)
              .bind(4, s.columnInt(2))
              .bind(5, s.columnInt(3))
              .bind(6, action)
              .bind(7, annotator)
              .bind(8, time)
              .bind(9, replaced)
              .bind(10, cls)
              .bind(11, cls);
          const bool there = present.step();
          present.reset();
          if (there) continue;
          insert.bind(1, setId)
              .bind(2, run->second)
              .bind(3, grp)
              .bind(4, s.columnInt(2))
              .bind(5, s.columnInt(3));
          if (cls.empty()) {
            insert.bindNull(6);
          } else {
            insert.bind(6, cls);
          }
          insert.bind(7, action).bind(8, annotator).bind(9, time).bind(10, replaced).run();
          ++report.revisionsCopied;
        }
      }
      transaction.commit();
    }

    // ---- models: by name; the same content is already there, other content is an error
    {
      db::Statement s(
          from.connection,
          "SELECT name, json, trained_on, metrics, created_at FROM models ORDER BY name");
      while (s.step()) {
        const std::string name = s.columnText(0);
        if (!options.models) break;
        db::Statement& existing = to.statement("SELECT json FROM models WHERE name = ?");
        existing.bind(1, name);
        if (existing.step()) {
          const bool same = existing.columnTextView(0) == s.columnTextView(1);
          existing.reset();
          if (!same) {
            report.warnings.push_back("model '" + name +
                                      "' not copied: the target holds another model of that name");
          }
          continue;
        }
        existing.reset();
        to.statement(
              "INSERT INTO models(name, json, trained_on, metrics, created_at) "
              "VALUES(?, ?, ?, ?, ?)")
            .bind(1, name)
            .bind(2, s.columnTextView(1))
            .bind(3, s.columnTextView(2))
            .bind(4, s.columnTextView(3))
            .bind(5, s.columnTextView(4))
            .run();
        ++report.modelsCopied;
      }
    }

    // ---- sweeps: by name, time and configuration
    if (options.sweeps) {
      std::vector<std::tuple<std::int64_t, std::string, std::string, std::string>> sweeps;
      {
        db::Statement s(from.connection,
                        "SELECT id, name, configuration, created_at FROM sweeps ORDER BY id");
        while (s.step()) {
          sweeps.emplace_back(s.columnInt(0), s.columnText(1), s.columnText(2), s.columnText(3));
        }
      }
      for (const auto& [id, name, configuration, createdAt] : sweeps) {
        db::Statement& existing = to.statement(
            "SELECT 1 FROM sweeps WHERE name = ? AND created_at = ? AND configuration = ?");
        existing.bind(1, name).bind(2, createdAt).bind(3, configuration);
        const bool present = existing.step();
        existing.reset();
        if (present) continue;
        db::Transaction transaction(to.connection);
        const std::int64_t newId =
            to.statement(
                  "INSERT INTO sweeps(name, configuration, created_at) VALUES(?, ?, ?) "
                  "RETURNING id")
                .bind(1, name)
                .bind(2, configuration)
                .bind(3, createdAt)
                .runReturningId();
        db::Statement cells(from.connection,
                            "SELECT configuration, metrics FROM sweep_cells WHERE sweep_id = ? "
                            "ORDER BY id");
        cells.bind(1, id);
        db::Statement& insert = to.statement(
            "INSERT INTO sweep_cells(sweep_id, configuration, metrics) VALUES(?, ?, ?)");
        while (cells.step()) {
          insert.bind(1, newId).bind(2, cells.columnTextView(0)).bind(3, cells.columnTextView(1));
          insert.run();
        }
        transaction.commit();
        ++report.sweepsCopied;
      }
    }
    to.refreshStepStatistics(report.stepsCopied);
    if (progress) progress(total, total);
    return report;
  } catch (const db::DbError& e) {
    return Error(e.file.empty() ? to.path.string() : e.file, e.what());
  } catch (const std::exception& e) {
    return Error(to.path.string(), e.what());
  }
}

}  // namespace tactile::storage
