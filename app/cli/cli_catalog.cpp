// Catalog verbs: runs list|rename|delete and labels list|rename|delete|import|export, so runs and
// label sets are managed without the sqlite3 shell (docs/storage.md#catalog).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/cli/cli_common.h"
#include "run/json_text.h"
#include "storage/run_database.h"

namespace tactile::cli {

void registerCatalogVerbs(CLI::App& app);
// labels set|history|assign|assignments|agreement (cli_labels_team.cpp).
void registerTeamLabelVerbs(CLI::App& labels);

namespace {

void printJson(const nlohmann::json& doc) {
  std::printf("%s\n", dumpJson(doc).c_str());
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names)
    out += (out.empty() ? "" : ",") + name;
  return out.empty() ? "-" : out;
}

// ---- runs ------------------------------------------------------------------------------------

int runRunsList(const std::string& dbPath, bool json) {
  auto db = openDatabaseForRead(dbPath);
  auto runs = db->runs().catalog();
  if (!runs) throw std::runtime_error(runs.errorText());
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const storage::RunCatalogEntry& e : runs.value()) {
      list.push_back({{"name", e.run.name},
                      {"id", e.run.id},
                      {"steps", e.run.stepCount},
                      {"scene", e.run.scene},
                      {"label_sets", e.labelSets}});
    }
    printJson({{"runs", list}});
    return kExitOk;
  }
  std::printf("%-24s %6s %9s %-16s %s\n", "name", "id", "steps", "scene", "label sets");
  for (const storage::RunCatalogEntry& e : runs.value()) {
    std::printf("%-24s %6lld %9lld %-16s %s\n", e.run.name.c_str(),
                static_cast<long long>(e.run.id), static_cast<long long>(e.run.stepCount),
                e.run.scene.empty() ? "-" : e.run.scene.c_str(), joined(e.labelSets).c_str());
  }
  return kExitOk;
}

int runRunsRename(const std::string& dbPath, const std::string& from, const std::string& to,
                  bool json) {
  auto db = openDatabaseForWrite(dbPath);
  const auto status = db->runs().rename(from, to);
  if (!status) throw std::runtime_error(status.errorText());
  if (json) {
    printJson({{"renamed", {{"from", from}, {"to", to}}}});
  } else {
    std::printf("renamed run '%s' to '%s'\n", from.c_str(), to.c_str());
  }
  return kExitOk;
}

int runRunsDelete(const std::string& dbPath, const std::vector<std::string>& names, bool json) {
  auto db = openDatabaseForWrite(dbPath);
  const auto status = db->runs().remove(names);
  if (!status) throw std::runtime_error(status.errorText());
  if (json) {
    printJson({{"deleted", names}});
  } else {
    std::printf("deleted %zu run(s): %s\n", names.size(), joined(names).c_str());
  }
  return kExitOk;
}

// ---- labels ----------------------------------------------------------------------------------

int runLabelsList(const std::string& dbPath, bool json) {
  auto db = openDatabaseForRead(dbPath);
  auto sets = db->labels().catalog();
  if (!sets) throw std::runtime_error(sets.errorText());
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const storage::LabelSetCatalogEntry& e : sets.value()) {
      list.push_back({{"name", e.set.name},
                      {"id", e.set.id},
                      {"annotator", e.set.annotator},
                      {"segments", e.set.segmentCount},
                      {"runs", e.runs}});
    }
    printJson({{"label_sets", list}});
    return kExitOk;
  }
  std::printf("%-24s %6s %-12s %9s %s\n", "name", "id", "annotator", "segments", "runs");
  for (const storage::LabelSetCatalogEntry& e : sets.value()) {
    std::printf("%-24s %6lld %-12s %9lld %s\n", e.set.name.c_str(),
                static_cast<long long>(e.set.id),
                e.set.annotator.empty() ? "-" : e.set.annotator.c_str(),
                static_cast<long long>(e.set.segmentCount), joined(e.runs).c_str());
  }
  return kExitOk;
}

int runLabelsRename(const std::string& dbPath, const std::string& from, const std::string& to,
                    bool json) {
  auto db = openDatabaseForWrite(dbPath);
  const auto status = db->labels().rename(from, to);
  if (!status) throw std::runtime_error(status.errorText());
  if (json) {
    printJson({{"renamed", {{"from", from}, {"to", to}}}});
  } else {
    std::printf("renamed label set '%s' to '%s'\n", from.c_str(), to.c_str());
  }
  return kExitOk;
}

int runLabelsDelete(const std::string& dbPath, const std::vector<std::string>& names, bool json) {
  auto db = openDatabaseForWrite(dbPath);
  const auto status = db->labels().remove(names);
  if (!status) throw std::runtime_error(status.errorText());
  if (json) {
    printJson({{"deleted", names}});
  } else {
    std::printf("deleted %zu label set(s): %s\n", names.size(), joined(names).c_str());
  }
  return kExitOk;
}

int runLabelsImport(const std::string& dbPath, const std::string& set, const std::string& file,
                    bool json) {
  requireValidName(set, "--set", "label set");
  auto db = openDatabaseOrCreate(dbPath);
  auto count = db->labels().importFile(set, file);
  if (!count) throw std::runtime_error(count.errorText());
  if (json) {
    printJson({{"set", set}, {"segments", count.value()}});
  } else {
    std::printf("imported %lld segments from %s into label set '%s'\n",
                static_cast<long long>(count.value()), file.c_str(), set.c_str());
  }
  return kExitOk;
}

int runLabelsExport(const std::string& dbPath, const std::string& set, const std::string& file,
                    bool json) {
  auto db = openDatabaseForRead(dbPath);
  const auto status = db->labels().exportFile(set, file);
  if (!status) throw std::runtime_error(status.errorText());
  if (json) {
    printJson({{"set", set}, {"file", file}});
  } else {
    std::printf("wrote label set '%s' to %s\n", set.c_str(), file.c_str());
  }
  return kExitOk;
}

struct CatalogArgs {
  std::string db;
  std::vector<std::string> names;  // rename: OLD NEW; delete: the names
  bool json = false;
};

// `VERB rename --db DB OLD NEW` and `VERB delete --db DB NAME...` (names as `A B` or `A,B`).
void addRenameDelete(CLI::App* parent, const std::string& what, const std::string& contents,
                     int (*rename)(const std::string&, const std::string&, const std::string&,
                                   bool),
                     int (*remove)(const std::string&, const std::vector<std::string>&, bool)) {
  auto renameArgs = std::make_shared<CatalogArgs>();
  CLI::App* ren =
      parent->add_subcommand("rename", "Rename a " + what + " (with its " + contents + ")");
  ren->add_option("--db", renameArgs->db, "Database: a file or a PostgreSQL address (must exist)")
      ->envname("TACTILE_DB")
      ->required();
  ren->add_option("names", renameArgs->names, "The " + what + "'s name, then the new name")
      ->required()
      ->expected(2);
  ren->add_flag("--json", renameArgs->json, R"(Print {"renamed":{"from","to"}})");
  setAction(ren, [renameArgs, rename] {
    return rename(renameArgs->db, renameArgs->names[0], renameArgs->names[1], renameArgs->json);
  });

  auto deleteArgs = std::make_shared<CatalogArgs>();
  const std::string deleteHelp = "Delete " + what + "s by name with their " + contents +
                                 ", all in one transaction (an unknown name deletes nothing)";
  CLI::App* del = parent->add_subcommand("delete", deleteHelp);
  del->add_option("--db", deleteArgs->db, "Database: a file or a PostgreSQL address (must exist)")
      ->envname("TACTILE_DB")
      ->required();
  del->add_option("names", deleteArgs->names, std::string("Names (A B or A,B)"))
      ->required()
      ->delimiter(',');
  del->add_flag("--json", deleteArgs->json, R"(Print {"deleted":[names]})");
  setAction(del, [deleteArgs, remove] {
    return remove(deleteArgs->db, deleteArgs->names, deleteArgs->json);
  });
}

}  // namespace

void registerCatalogVerbs(CLI::App& app) {
  {
    CLI::App* runs = app.add_subcommand("runs", "List, rename or delete the runs of a database");
    runs->require_subcommand(1, 1);
    auto listArgs = std::make_shared<CatalogArgs>();
    CLI::App* list =
        runs->add_subcommand("list", "List runs with their steps, scene and label sets");
    list->add_option("--db", listArgs->db,
                     "Database: a file or a PostgreSQL address (must exist; opened read-only)")
        ->envname("TACTILE_DB")
        ->required();
    list->add_flag("--json", listArgs->json,
                   R"(Print {"runs":[{"name","id","steps","scene","label_sets"}]})");
    setAction(list, [listArgs] { return runRunsList(listArgs->db, listArgs->json); });
    addRenameDelete(runs, "run", "steps, truth, summaries and label segments", runRunsRename,
                    runRunsDelete);
  }
  {
    CLI::App* labels = app.add_subcommand(
        "labels",
        "Label sets: list, rename, delete, import, export; edits, history, assignments and "
        "agreement");
    labels->require_subcommand(1, 1);
    auto listArgs = std::make_shared<CatalogArgs>();
    CLI::App* list = labels->add_subcommand(
        "list", "List label sets with their annotator, segment count and runs covered");
    list->add_option("--db", listArgs->db,
                     "Database: a file or a PostgreSQL address (must exist; opened read-only)")
        ->envname("TACTILE_DB")
        ->required();
    list->add_flag("--json", listArgs->json,
                   R"(Print {"label_sets":[{"name","id","annotator","segments","runs"}]})");
    setAction(list, [listArgs] { return runLabelsList(listArgs->db, listArgs->json); });
    addRenameDelete(labels, "label set", "segments", runLabelsRename, runLabelsDelete);

    struct LabelArgs {
      std::string db, set, file;
      bool json = false;
    };
    auto importArgs = std::make_shared<LabelArgs>();
    CLI::App* imp = labels->add_subcommand(
        "import",
        "Add a label file's segments to a set (created when absent); newest wins. Provenance "
        "lines must match the stored runs' step counts and checksums");
    imp->add_option("--db", importArgs->db, "Database: a file or a PostgreSQL address")
        ->envname("TACTILE_DB")
        ->required();
    imp->add_option("--set", importArgs->set, "Label set name")->required();
    imp->add_option("file", importArgs->file, "Label file: .json, otherwise CSV")->required();
    imp->add_flag("--json", importArgs->json, R"(Print {"set","segments"})");
    setAction(imp, [importArgs] {
      return runLabelsImport(importArgs->db, importArgs->set, importArgs->file, importArgs->json);
    });
    auto exportArgs = std::make_shared<LabelArgs>();
    CLI::App* exp = labels->add_subcommand(
        "export", "Write a label set to a file, with each run's step count and checksum");
    exp->add_option("--db", exportArgs->db,
                    "Database: a file or a PostgreSQL address (must exist; opened read-only)")
        ->envname("TACTILE_DB")
        ->required();
    exp->add_option("--set", exportArgs->set, "Label set name")->required();
    exp->add_option("file", exportArgs->file, "Label file: .json, otherwise CSV")->required();
    exp->add_flag("--json", exportArgs->json, R"(Print {"set","file"})");
    setAction(exp, [exportArgs] {
      return runLabelsExport(exportArgs->db, exportArgs->set, exportArgs->file, exportArgs->json);
    });
    registerTeamLabelVerbs(*labels);
  }
}

}  // namespace tactile::cli
