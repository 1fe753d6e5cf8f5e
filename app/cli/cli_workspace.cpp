// Verbs on what a database keeps besides runs and labels: models (list, export, import, delete)
// and sweeps (list, delete). Training, sweeping, reporting and classifying from a database are
// the --db forms of train, sweep, report and classify (cli_learn.cpp).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "analysis/model_file.h"
#include "app/cli/cli_common.h"
#include "app/cli/cli_sweep.h"
#include "base/file_text.h"
#include "run/json_text.h"
#include "storage/run_database.h"
#include "workspace/workspace.h"

namespace tactile::cli {
namespace {

using nlohmann::json;

json parsedOrNull(const std::string& text) {
  json v = json::parse(text, nullptr, false);
  return v.is_discarded() ? json(nullptr) : v;
}

struct Common {
  std::string db;
  bool json = false;
};

int modelsList(const Common& c) {
  auto db = openDatabaseForRead(c.db);
  auto models = db->models().list();
  if (!models) throw std::runtime_error(models.errorText());
  json list = json::array();
  for (const storage::ModelInfo& m : models.value()) {
    const json trainedOn = parsedOrNull(m.trainedOnJson);
    const json metrics = parsedOrNull(m.metricsJson);
    json groups = json::array();
    if (metrics.is_object()) {
      for (auto it = metrics.begin(); it != metrics.end(); ++it)
        groups.push_back(it.key());
    }
    json entry{{"name", m.name}, {"id", m.id}, {"created", m.createdAt}, {"groups", groups}};
    if (trainedOn.is_object()) {
      entry["label_set"] = trainedOn.value("label_set", "");
      json runs = json::array();
      for (const json& r : trainedOn.value("train_runs", json::array()))
        runs.push_back(r.value("name", ""));
      entry["train_runs"] = runs;
      if (trainedOn.contains("imported_from")) entry["imported_from"] = trainedOn["imported_from"];
    }
    list.push_back(std::move(entry));
  }
  if (c.json) {
    std::cout << dumpJson(json{{"models", list}}) << "\n";
    return kExitOk;
  }
  std::printf("%-24s %5s  %-20s  %-16s %s\n", "name", "id", "created", "label set", "groups");
  for (const json& m : list) {
    std::string groups;
    for (const json& g : m["groups"])
      groups += (groups.empty() ? "" : ",") + g.get<std::string>();
    std::printf("%-24s %5lld  %-20s  %-16s %s\n", m["name"].get<std::string>().c_str(),
                static_cast<long long>(m["id"].get<std::int64_t>()),
                m["created"].get<std::string>().c_str(),
                m.value("label_set", std::string()).c_str(), groups.c_str());
  }
  return kExitOk;
}

int modelsExport(const Common& c, const std::string& name, const std::string& out) {
  const Status writable = checkWritable(out);
  if (!writable) throw std::runtime_error(writable.errorText());
  workspace::Workspace ws(openDatabaseForRead(c.db));
  const Status written = ws.exportModel(name, out);
  if (!written) throw std::runtime_error(c.db + ": " + written.errorText());
  const std::size_t groups = ws.loadModel(name).value().models.size();
  if (c.json) {
    std::cout << dumpJson(json{{"model", name}, {"out", out}, {"groups", groups}}) << "\n";
  } else {
    std::printf("wrote model '%s' (%zu group model(s)) to %s\n", name.c_str(), groups, out.c_str());
  }
  return kExitOk;
}

int modelsImport(const Common& c, const std::string& file, const std::string& name) {
  if (!name.empty()) requireValidName(name, "--name", "model");
  workspace::Workspace ws(openDatabaseOrCreate(c.db));
  const Result<std::string> stored = ws.importModel(file, name);
  if (!stored) throw std::runtime_error(stored.errorText());
  const std::size_t groups = ws.loadModel(stored.value()).value().models.size();
  auto id = ws.modelStore().info(stored.value());
  if (c.json) {
    std::cout << dumpJson(
                     json{{"model", stored.value()}, {"id", id ? id->id : 0}, {"groups", groups}})
              << "\n";
  } else {
    std::printf("stored model '%s' from %s\n", stored.value().c_str(), file.c_str());
  }
  return kExitOk;
}

int modelsFromSweep(const Common& c, std::int64_t sweepId, std::size_t cell,
                    const std::string& name, const std::string& out) {
  if (!name.empty()) requireValidName(name, "--name", "model");
  if (!out.empty()) {
    const Status writable = checkWritable(out);
    if (!writable) throw std::runtime_error(writable.errorText());
  }
  workspace::Workspace ws(openDatabaseForWrite(c.db));
  auto trained = ws.trainSweepCell(sweepId, cell, name);
  if (!trained) throw std::runtime_error(c.db + ": " + trained.errorText());
  if (!out.empty()) {
    const Status written = ws.exportModel(trained->modelName, out);
    if (!written) throw std::runtime_error(written.errorText());
  }
  const workspace::GroupTrainReport& g = trained->groups.front();
  if (c.json) {
    json report = {
        {"model", trained->modelName},
        {"id", trained->modelId},
        {"sweep", sweepId},
        {"cell", cell},
        {"group", std::string(groupInfo(g.group).shortName)},
        {"accuracy", g.accuracy ? json(*g.accuracy) : json(nullptr)},
        {"balanced_accuracy", g.balancedAccuracy ? json(*g.balancedAccuracy) : json(nullptr)},
        {"samples_train", g.samplesTrain},
        {"samples_test", g.samplesTest}};
    if (!out.empty()) report["out"] = out;
    std::cout << dumpJson(report) << "\n";
  } else {
    if (!g.balancedAccuracy) {
      std::printf("stored model '%s' (group %s, no test data on the sweep's test runs)\n",
                  trained->modelName.c_str(), std::string(groupInfo(g.group).shortName).c_str());
    } else
      std::printf(
          "stored model '%s' (group %s, balanced accuracy %.1f %% on the sweep's test runs)\n",
          trained->modelName.c_str(), std::string(groupInfo(g.group).shortName).c_str(),
          100.0 * g.balancedAccuracy.value_or(0.0));
    if (!out.empty()) std::printf("wrote it to %s\n", out.c_str());
  }
  return kExitOk;
}

int modelsDelete(const Common& c, std::vector<std::string> names) {
  // A name given twice is one model.
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  auto db = openDatabaseForWrite(c.db);
  const Status deleted = db->models().remove(names);
  if (!deleted) throw std::runtime_error(c.db + ": " + deleted.errorText());
  if (c.json) {
    std::cout << dumpJson(json{{"deleted", names}}) << "\n";
  } else {
    std::printf("deleted %zu model(s)\n", names.size());
  }
  return kExitOk;
}

int sweepsList(const Common& c) {
  auto db = openDatabaseForRead(c.db);
  auto sweeps = db->sweeps().list();
  if (!sweeps) throw std::runtime_error(sweeps.errorText());
  json list = json::array();
  for (const storage::SweepInfo& w : sweeps.value()) {
    const json configuration = parsedOrNull(w.configurationJson);
    json entry{{"id", w.id}, {"name", w.name}, {"created", w.createdAt}, {"cells", w.cellCount}};
    if (configuration.is_object()) {
      entry["state"] = configuration.value("state", "");
      entry["label_set"] = configuration.value("label_set", "");
      if (configuration.contains("error")) entry["error"] = configuration.value("error", "");
    }
    list.push_back(std::move(entry));
  }
  if (c.json) {
    std::cout << dumpJson(json{{"sweeps", list}}) << "\n";
    return kExitOk;
  }
  std::printf("%5s  %-24s %-20s %6s  %-10s %s\n", "id", "name", "created", "cells", "state",
              "label set");
  for (const json& w : list) {
    std::printf(
        "%5lld  %-24s %-20s %6lld  %-10s %s\n", static_cast<long long>(w["id"].get<std::int64_t>()),
        w["name"].get<std::string>().c_str(), w["created"].get<std::string>().c_str(),
        static_cast<long long>(w["cells"].get<std::int64_t>()),
        w.value("state", std::string()).c_str(), w.value("label_set", std::string()).c_str());
    if (w.contains("error")) std::printf("       error: %s\n", w.value("error", "").c_str());
  }
  return kExitOk;
}

int sweepsDelete(const Common& c, std::vector<std::int64_t> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  auto db = openDatabaseForWrite(c.db);
  const Status deleted = db->sweeps().remove(ids);
  if (!deleted) throw std::runtime_error(c.db + ": " + deleted.errorText());
  if (c.json) {
    std::cout << dumpJson(json{{"deleted", ids}}) << "\n";
  } else {
    std::printf("deleted %zu sweep(s) with their cells\n", ids.size());
  }
  return kExitOk;
}

CLI::App* withCommon(CLI::App* cmd, Common& c) {
  cmd->add_option("--db", c.db, "Database: a file or a PostgreSQL address")
      ->envname("TACTILE_DB")
      ->required();
  cmd->add_flag("--json", c.json, "Print one JSON object");
  return cmd;
}

}  // namespace

void registerWorkspaceVerbs(CLI::App& app) {
  CLI::App* models = app.add_subcommand("models", "List, export, import and delete stored models");
  models->require_subcommand(1);
  {
    auto c = std::make_shared<Common>();
    CLI::App* cmd = withCommon(models->add_subcommand("list", "List the stored models"), *c);
    setAction(cmd, [c] { return modelsList(*c); });
  }
  {
    auto c = std::make_shared<Common>();
    auto name = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    CLI::App* cmd =
        withCommon(models->add_subcommand("export", "Write a stored model to a model file"), *c);
    cmd->add_option("NAME", *name, "Stored model")->required();
    cmd->add_option("--out", *out, "Model bundle JSON to write (atomically)")->required();
    setAction(cmd, [c, name, out] { return modelsExport(*c, *name, *out); });
  }
  {
    auto c = std::make_shared<Common>();
    auto file = std::make_shared<std::string>();
    auto name = std::make_shared<std::string>();
    CLI::App* cmd = withCommon(
        models->add_subcommand("import", "Store a model file (checked by the model reader)"), *c);
    cmd->add_option("FILE", *file, "Model or model bundle JSON")->required();
    cmd->add_option("--name", *name, "Name to store it under (default: the file's stem)");
    setAction(cmd, [c, file, name] { return modelsImport(*c, *file, *name); });
  }
  {
    auto c = std::make_shared<Common>();
    auto sweep = std::make_shared<std::int64_t>(0);
    auto cell = std::make_shared<std::size_t>(0);
    auto name = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    CLI::App* cmd = withCommon(
        models->add_subcommand("from-sweep",
                               "Train and store the model of one sweep cell (its settings, the "
                               "sweep's label set and runs)"),
        *c);
    cmd->add_option("--sweep", *sweep, "Stored sweep id (see tactile sweeps list)")->required();
    cmd->add_option("--cell", *cell,
                    "Cell index, 0-based in the sweep's grid order (the \"cell\" column of "
                    "tactile report)")
        ->required();
    cmd->add_option("--name", *name, "Name to store it under (default: from the cell's settings)");
    cmd->add_option("--out", *out, "Also write it to this model file");
    setAction(cmd, [c, sweep, cell, name, out] {
      return modelsFromSweep(*c, *sweep, *cell, *name, *out);
    });
  }
  {
    auto c = std::make_shared<Common>();
    auto names = std::make_shared<std::vector<std::string>>();
    CLI::App* cmd = withCommon(
        models->add_subcommand("delete", "Delete stored models (all named or none)"), *c);
    cmd->add_option("NAMES", *names, "Stored models")->required()->delimiter(',');
    setAction(cmd, [c, names] { return modelsDelete(*c, *names); });
  }

  CLI::App* sweeps = app.add_subcommand("sweeps", "List, export and delete stored sweeps");
  sweeps->require_subcommand(1);
  {
    auto c = std::make_shared<Common>();
    CLI::App* cmd = withCommon(sweeps->add_subcommand("list", "List the stored sweeps"), *c);
    setAction(cmd, [c] { return sweepsList(*c); });
  }
  {
    auto c = std::make_shared<Common>();
    auto ids = std::make_shared<std::vector<std::int64_t>>();
    CLI::App* cmd = withCommon(
        sweeps->add_subcommand("delete", "Delete stored sweeps with their cells (all or none)"),
        *c);
    cmd->add_option("IDS", *ids, "Sweep ids")->required()->delimiter(',');
    setAction(cmd, [c, ids] { return sweepsDelete(*c, *ids); });
  }
  registerSweepExportVerb(*sweeps);
}

}  // namespace tactile::cli
