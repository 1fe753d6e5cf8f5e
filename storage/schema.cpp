#include "storage/schema.h"

#include "storage/step_checksum.h"

#include <algorithm>
#include <array>
#include <optional>
#include <system_error>

namespace tactile::storage::db {
namespace {

// Column notes that apply throughout:
// - groups are stored by short name ("F", "FLC", ...) and classes by their exact file spelling, so
//   the database reads well from the sqlite3 shell;
// - float64 columns of steps have no declared type: with REAL affinity SQLite would store
//   integral values as integers and lose the sign of -0.0, and we promise bit-exact round trips;
// - steps.truth packs the eight groups' truth classes, 3 bits each, group g (F, FLC, L, RLC, B,
//   RRC, R, FRC) at bit 3g, class codes 0 NoContact, 1 Wall, 2 Corner, 3 LeavingWall, 4 DeadPath;
//   NULL when the run has no truth columns (since version 4; the step_truth view spells it out);
// - steps.sensors (88 values n0, s0, ..., n43, s43) and step_blocks.minmax (88 minima, 88 maxima)
//   are float64 lists, dense or sparse (storage/run_codec.h; sparse since version 4);
// - runs.metadata (key, value, key, value, ...), runs.extra_columns (x_ names) and steps.extra
//   (x_ values) are lists of strings, each a 4-byte little-endian length and the bytes, so that
//   they round-trip byte for byte.
constexpr std::string_view kVersion1 = R"sql(
CREATE TABLE scenes(
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL,
  checksum TEXT NOT NULL UNIQUE,
  json TEXT NOT NULL
);
CREATE TABLE runs(
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  source_file TEXT NOT NULL,
  checksum TEXT NOT NULL,
  scene TEXT,
  scene_id INTEGER REFERENCES scenes(id),
  subject TEXT,
  outcome TEXT NOT NULL,
  dt REAL,
  step_count INTEGER NOT NULL CHECK(step_count >= 0),
  has_truth INTEGER NOT NULL CHECK(has_truth IN (0, 1)),
  metadata BLOB NOT NULL,
  extra_columns BLOB NOT NULL,
  imported_at TEXT NOT NULL
);
CREATE INDEX runs_by_checksum ON runs(checksum);
CREATE TABLE steps(
  run_id INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,
  step INTEGER NOT NULL,
  x, y, theta, v, omega,
  blocked INTEGER NOT NULL,
  sensors BLOB NOT NULL,
  extra BLOB,
  PRIMARY KEY(run_id, step)
) WITHOUT ROWID;
CREATE TABLE truth_segments(
  run_id INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,
  grp TEXT NOT NULL,
  first_step INTEGER NOT NULL,
  last_step INTEGER NOT NULL,
  class TEXT NOT NULL,
  PRIMARY KEY(run_id, grp, first_step)
) WITHOUT ROWID;
CREATE TABLE step_blocks(
  run_id INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,
  level INTEGER NOT NULL,
  block INTEGER NOT NULL,
  minmax BLOB NOT NULL,
  PRIMARY KEY(run_id, level, block)
) WITHOUT ROWID;
)sql";

constexpr std::string_view kVersion2 = R"sql(
CREATE TABLE label_sets(
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  annotator TEXT NOT NULL DEFAULT '',
  created_at TEXT NOT NULL
);
CREATE TABLE label_segments(
  id INTEGER PRIMARY KEY,
  set_id INTEGER NOT NULL REFERENCES label_sets(id) ON DELETE CASCADE,
  run_id INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,
  grp TEXT NOT NULL CHECK(grp IN ('F','FLC','L','RLC','B','RRC','R','FRC')),
  first_step INTEGER NOT NULL CHECK(first_step >= 0),
  last_step INTEGER NOT NULL,
  class TEXT NOT NULL CHECK(class IN ('NoContact','Wall','Corner','LeavingWall','DeadPath')),
  annotator TEXT NOT NULL DEFAULT '',
  created_at TEXT NOT NULL,
  CHECK(last_step >= first_step)
);
CREATE INDEX label_segments_by_range ON label_segments(set_id, run_id, grp, first_step);
CREATE INDEX label_segments_by_run ON label_segments(run_id);
)sql";

constexpr std::string_view kVersion3 = R"sql(
CREATE TABLE models(
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  json TEXT NOT NULL,
  trained_on TEXT NOT NULL DEFAULT '{}',
  metrics TEXT NOT NULL DEFAULT '{}',
  created_at TEXT NOT NULL
);
CREATE TABLE sweeps(
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL,
  configuration TEXT NOT NULL,
  created_at TEXT NOT NULL
);
CREATE TABLE sweep_cells(
  id INTEGER PRIMARY KEY,
  sweep_id INTEGER NOT NULL REFERENCES sweeps(id) ON DELETE CASCADE,
  configuration TEXT NOT NULL,
  metrics TEXT NOT NULL
);
CREATE INDEX sweep_cells_by_sweep ON sweep_cells(sweep_id);
)sql";

// Truth moves from run-length rows into the steps (simulated truth changes class every few steps,
// so the segments were almost as many rows as the steps), and sensors and minmax blobs may be
// sparse from now on (older programs would misread them; dense blobs stay valid). The view shows
// the packed truth by name for the sqlite3 shell.
constexpr std::string_view kVersion4 = R"sql(
ALTER TABLE steps ADD COLUMN truth INTEGER;
UPDATE steps SET truth =
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'F' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 0) |
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'FLC' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 3) |
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'L' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 6) |
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'RLC' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 9) |
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'B' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 12) |
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'RRC' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 15) |
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'R' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 18) |
  ((SELECT CASE class WHEN 'Wall' THEN 1 WHEN 'Corner' THEN 2 WHEN 'LeavingWall' THEN 3 WHEN 'DeadPath' THEN 4 ELSE 0 END FROM truth_segments AS t
     WHERE t.run_id = steps.run_id AND t.grp = 'FRC' AND t.first_step <= steps.step
     ORDER BY t.first_step DESC LIMIT 1) << 21)
WHERE run_id IN (SELECT id FROM runs WHERE has_truth = 1);
DROP TABLE truth_segments;
CREATE VIEW step_truth AS SELECT run_id, step,
  CASE (truth >> 0) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS F,
  CASE (truth >> 3) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS FLC,
  CASE (truth >> 6) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS L,
  CASE (truth >> 9) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS RLC,
  CASE (truth >> 12) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS B,
  CASE (truth >> 15) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS RRC,
  CASE (truth >> 18) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS R,
  CASE (truth >> 21) & 7 WHEN 0 THEN 'NoContact' WHEN 1 THEN 'Wall' WHEN 2 THEN 'Corner' WHEN 3 THEN 'LeavingWall' WHEN 4 THEN 'DeadPath' END AS FRC
FROM steps WHERE truth IS NOT NULL;
)sql";

// Checksums of the stored run data (storage/step_checksum.h): a CRC-32 per steps row, per summary
// block and per run row, computed here for the rows already stored (by the SQL functions the
// connection registers; a file that was damaged before this migration is taken as it is).
constexpr std::string_view kVersion5 = R"sql(
ALTER TABLE runs ADD COLUMN crc INTEGER;
ALTER TABLE steps ADD COLUMN crc INTEGER;
ALTER TABLE step_blocks ADD COLUMN crc INTEGER;
UPDATE runs SET crc = tactile_run_crc(id, name, step_count, has_truth, metadata, extra_columns);
UPDATE steps SET crc = tactile_step_crc(run_id, step, x, y, theta, v, omega, blocked, sensors,
                                        extra, truth);
UPDATE step_blocks SET crc = tactile_block_crc(run_id, level, block, minmax);
)sql";

// Label history and assignments: every label edit is a revision (who, when, the range, what it
// replaced), so annotators editing one corpus side by side see who changed what and an edit over
// steps changed since it was read is refused (docs/team.md#annotators-side-by-side). Assignments
// give runs (or one group of a run) to annotators with a state: todo, labelled, reviewed.
constexpr std::string_view kVersion6 = R"sql(
CREATE TABLE label_revisions(
  id INTEGER PRIMARY KEY,
  set_id INTEGER NOT NULL REFERENCES label_sets(id) ON DELETE CASCADE,
  run_id INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,
  grp TEXT NOT NULL CHECK(grp IN ('F','FLC','L','RLC','B','RRC','R','FRC')),
  first_step INTEGER NOT NULL,
  last_step INTEGER NOT NULL,
  class TEXT,
  action TEXT NOT NULL,
  annotator TEXT NOT NULL DEFAULT '',
  created_at TEXT NOT NULL,
  replaced TEXT NOT NULL DEFAULT '[]'
);
CREATE INDEX label_revisions_by_run ON label_revisions(set_id, run_id, id);
CREATE INDEX label_revisions_of_run ON label_revisions(run_id);
CREATE TABLE assignments(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,
  grp TEXT NOT NULL DEFAULT '',
  annotator TEXT NOT NULL,
  label_set TEXT NOT NULL DEFAULT '',
  state TEXT NOT NULL CHECK(state IN ('todo','labelled','reviewed')),
  updated_by TEXT NOT NULL DEFAULT '',
  updated_at TEXT NOT NULL,
  UNIQUE(run_id, grp, annotator)
);
)sql";

// Sweeps planned for workers (docs/cluster.md): one row per fit job of a sweep (the cells that
// differ only in the decision mode) with its cost in the sweep's cost model, pending until a
// worker claims it (the most expensive first); a claim holds a lease that
// the worker renews while it computes and that another worker takes over once it runs out (a
// worker killed mid-job). A job's cells go into sweep_cells in the transaction that marks it done.
constexpr std::string_view kVersion7 = R"sql(
CREATE TABLE sweep_claims(
  sweep_id INTEGER NOT NULL REFERENCES sweeps(id) ON DELETE CASCADE,
  job INTEGER NOT NULL,
  cells INTEGER NOT NULL,
  cost REAL NOT NULL DEFAULT 0,
  state TEXT NOT NULL CHECK(state IN ('pending','running','done','failed')),
  worker TEXT NOT NULL DEFAULT '',
  lease_until REAL NOT NULL DEFAULT 0,
  attempts INTEGER NOT NULL DEFAULT 0,
  error TEXT NOT NULL DEFAULT '',
  seconds REAL NOT NULL DEFAULT 0,
  finished_at TEXT NOT NULL DEFAULT '',
  PRIMARY KEY(sweep_id, job)
);
CREATE INDEX sweep_claims_by_state ON sweep_claims(sweep_id, state, cost DESC, job);
)sql";

constexpr std::array<Migration, 7> kMigrations{{
    {1, "runs, steps, truth, step summaries, scenes", kVersion1},
    {2, "label sets and segments", kVersion2},
    {3, "models, sweeps and sweep cells", kVersion3},
    {4, "truth packed into the steps, sparse sensors and summary blobs", kVersion4},
    {5, "checksums of every run, step and summary block row", kVersion5},
    {6, "label revisions and assignments", kVersion6},
    {7, "claims of planned sweep jobs", kVersion7},
}};
static_assert(kMigrations.back().version == kSchemaVersion);

}  // namespace

std::span<const Migration> migrations() {
  return kMigrations;
}

int schemaVersion(Connection& connection) {
  return static_cast<int>(connection.queryInt("PRAGMA user_version"));
}

std::filesystem::path backupPath(const std::filesystem::path& dbPath, int version) {
  const std::string base = dbPath.string() + ".v" + std::to_string(version);
  std::filesystem::path candidate = base + ".bak";
  std::error_code ec;
  for (int i = 1; std::filesystem::exists(candidate, ec); ++i) {
    candidate = base + "-" + std::to_string(i) + ".bak";
  }
  return candidate;
}

Identity readIdentity(Connection& connection) {
  Statement s(connection,
              "SELECT (SELECT application_id FROM pragma_application_id), "
              "(SELECT user_version FROM pragma_user_version), "
              "(SELECT count(*) FROM sqlite_schema)");
  if (!s.step()) throw DbError(connection.file(), "cannot read the schema identity");
  Identity identity;
  identity.applicationId = s.columnInt(0);
  identity.version = static_cast<int>(s.columnInt(1));
  identity.objects = s.columnInt(2);
  return identity;
}

namespace {

// The identity and version checks, on one snapshot. Throws DbError.
void checkMigratable(const Identity& identity, const std::string& name) {
  const int version = identity.version;
  if (version > kSchemaVersion) {
    throw DbError(name, "schema version " + std::to_string(version) + ", newer than version " +
                            std::to_string(kSchemaVersion) +
                            " that this program understands; use a newer tactile");
  }
  // The application id is the identity; only a blank file (no id, version or schema) becomes one.
  if (identity.applicationId != kApplicationId &&
      (identity.applicationId != 0 || version != 0 || identity.objects != 0)) {
    throw DbError(name,
                  "an SQLite database without the Tactile application id, not a Tactile "
                  "database");
  }
}

}  // namespace

std::optional<std::string> migrationProblem(Connection& connection, int targetVersion) {
  const int version = schemaVersion(connection);
  if (version <= 0 || version >= targetVersion) return std::nullopt;
  // The schema alone (no rows), copied into a private in-memory database: tables first, then
  // what refers to them.
  Connection trial = Connection::open(":memory:", true);
  registerChecksumFunctions(trial);  // the migrations to schema 5 compute checksums
  for (const char* type : {"table", "index", "view", "trigger"}) {
    Statement objects(connection,
                      "SELECT sql FROM sqlite_schema WHERE type = ? AND sql IS NOT NULL AND "
                      "name NOT LIKE 'sqlite_%' ORDER BY rowid");
    objects.bind(1, std::string_view(type));
    while (objects.step()) {
      try {
        trial.exec(objects.columnText(0));
      } catch (const DbError& e) {
        return std::string("its schema cannot be read back (") + e.what() + ")";
      }
    }
  }
  for (const Migration& migration : kMigrations) {
    if (migration.version <= version || migration.version > targetVersion) continue;
    try {
      trial.exec(migration.sql);
    } catch (const DbError& e) {
      // SQLite's reason only, without the statement text the error carries after it.
      std::string reason = e.what();
      reason = reason.substr(0, std::min(reason.find(" (in:"), reason.find('\n')));
      return "its tables do not match schema version " + std::to_string(version) +
             " (the migration to schema version " + std::to_string(migration.version) +
             " would fail: " + reason + ")";
    }
  }
  return std::nullopt;
}

MigrationReport migrate(Connection& connection, const std::filesystem::path& dbPath,
                        int targetVersion) {
  MigrationReport report;
  registerChecksumFunctions(connection);
  const Identity before = readIdentity(connection);
  report.fromVersion = before.version;
  report.toVersion = report.fromVersion;
  const std::string name = dbPath.string();
  checkMigratable(before, name);
  if (report.fromVersion >= targetVersion) return report;
  // A user_version that does not match the tables (a damaged header) is refused before any
  // backup or change, rather than failing halfway through.
  if (auto problem = migrationProblem(connection, targetVersion)) {
    throw DbError(name, "schema version " + std::to_string(report.fromVersion) + ", but " +
                            *problem + "; the file is damaged and is left unchanged");
  }

  const bool inMemory = name.empty() || name == ":memory:";
  if (report.fromVersion > 0 && !inMemory) {
    report.backupPath = backupPath(dbPath, report.fromVersion);
    backupTo(connection, report.backupPath);
  }
  // Several processes may open a new or old file at once: the write lock is taken first
  // (BEGIN IMMEDIATE waits through the busy timeout) and the version read again inside it, so only
  // the first one migrates and the others find the work done.
  Transaction transaction(connection);
  const Identity now = readIdentity(connection);
  const int current = now.version;
  checkMigratable(now, name);
  if (current >= targetVersion) {
    transaction.rollback();
    if (!report.backupPath.empty()) {
      std::error_code ec;
      std::filesystem::remove(report.backupPath, ec);  // another process migrated and kept one
      report.backupPath.clear();
    }
    report.fromVersion = current;
    report.toVersion = current;
    return report;
  }
  report.fromVersion = current;
  for (const Migration& migration : kMigrations) {
    if (migration.version <= report.fromVersion || migration.version > targetVersion) continue;
    try {
      connection.exec(migration.sql);
    } catch (const DbError& e) {
      throw DbError(name, "migration to schema version " + std::to_string(migration.version) +
                              " (" + std::string(migration.description) + ") failed: " + e.what());
    }
  }
  connection.exec("PRAGMA application_id = " + std::to_string(kApplicationId));
  connection.exec("PRAGMA user_version = " + std::to_string(targetVersion));
  transaction.commit();
  report.toVersion = targetVersion;
  return report;
}

}  // namespace tactile::storage::db
