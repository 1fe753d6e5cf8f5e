// MCAP verbs: `mcap info`, and the MCAP forms of `import` and `export-run` (docs/interop.md).
#include "app/cli/cli_mcap.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli/cli_common.h"
#include "mcap/reader.h"
#include "run/json_text.h"
#include "sim/scene_source.h"
#include "storage/run_database.h"
#include "workspace/run_mcap.h"
#include "workspace/workspace.h"

namespace tactile::cli {

bool isMcapPath(const std::string& path) {
  if (path.size() < 5) return false;
  std::string ext = path.substr(path.size() - 5);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".mcap";
}

namespace {

void printMcapJson(const nlohmann::json& doc) {
  std::printf("%s\n", dumpJson(doc).c_str());
}

std::string mcapSeconds(std::uint64_t ns) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%llu.%09llu", static_cast<unsigned long long>(ns / 1000000000U),
                static_cast<unsigned long long>(ns % 1000000000U));
  return buf;
}

int runMcapInfo(const std::string& file, bool json) {
  auto scanned = mcap::scanFile(file);
  if (!scanned) throw std::runtime_error(scanned.errorText());
  const mcap::ScanResult& s = scanned.value();
  const double duration =
      s.messageCount > 0 ? 1e-9 * static_cast<double>(s.messageEndTime - s.messageStartTime) : 0.0;
  nlohmann::json channels = nlohmann::json::array();
  for (const auto& [id, c] : s.channels) {
    const auto schema = s.schemas.find(c.schemaId);
    const auto count = s.channelMessageCounts.find(id);
    channels.push_back(
        {{"id", id},
         {"topic", c.topic},
         {"message_encoding", c.messageEncoding},
         {"schema_name", schema == s.schemas.end() ? "" : schema->second.name},
         {"schema_encoding", schema == s.schemas.end() ? "" : schema->second.encoding},
         {"messages", count == s.channelMessageCounts.end() ? 0 : count->second}});
  }
  nlohmann::json compression = nlohmann::json::object();
  for (const auto& [name, chunks] : s.chunkCompressions)
    compression[name.empty() ? "none" : name] = chunks;
  nlohmann::json metadata = nlohmann::json::array();
  for (const mcap::Metadata& m : s.metadata) {
    nlohmann::json entries = nlohmann::json::object();
    for (const auto& [k, v] : m.entries)
      entries[k] = v;
    metadata.push_back({{"name", m.name}, {"entries", entries}});
  }
  if (json) {
    printMcapJson({{"file", file},
                   {"bytes", s.fileSize},
                   {"library", s.library},
                   {"profile", s.profile},
                   {"messages", s.messageCount},
                   {"start_time_ns", s.messageStartTime},
                   {"end_time_ns", s.messageEndTime},
                   {"duration_s", duration},
                   {"chunks", s.chunkCount},
                   {"compression", compression},
                   {"messages_outside_chunks", s.messagesOutsideChunks},
                   {"message_indexes", s.messageIndexCount},
                   {"schemas", s.schemas.size()},
                   {"channels", channels},
                   {"attachments", s.attachments.size()},
                   {"metadata", metadata},
                   {"summary", s.hasSummary},
                   {"statistics", s.statistics.has_value()},
                   {"chunk_indexes", s.chunkIndexes.size()}});
    return kExitOk;
  }
  std::printf("library:   %s\nprofile:   %s\nmessages:  %llu\n", s.library.c_str(),
              s.profile.c_str(), static_cast<unsigned long long>(s.messageCount));
  if (s.messageCount > 0) {
    std::printf("duration:  %.9f s\nstart:     %s\nend:       %s\n", duration,
                mcapSeconds(s.messageStartTime).c_str(), mcapSeconds(s.messageEndTime).c_str());
  }
  std::printf("chunks:    %llu", static_cast<unsigned long long>(s.chunkCount));
  for (const auto& [name, chunks] : s.chunkCompressions) {
    std::printf(" (%s: %llu)", name.empty() ? "none" : name.c_str(),
                static_cast<unsigned long long>(chunks));
  }
  if (s.messagesOutsideChunks > 0) {
    std::printf("; %llu messages outside chunks",
                static_cast<unsigned long long>(s.messagesOutsideChunks));
  }
  std::printf("\nchannels:\n");
  for (const auto& c : channels) {
    std::printf("  (%d) %-24s %10llu msgs : %s [%s] (%s)\n", c["id"].get<int>(),
                c["topic"].get<std::string>().c_str(), c["messages"].get<unsigned long long>(),
                c["schema_name"].get<std::string>().c_str(),
                c["schema_encoding"].get<std::string>().c_str(),
                c["message_encoding"].get<std::string>().c_str());
  }
  std::printf("attachments: %zu\nmetadata:    %zu", s.attachments.size(), s.metadata.size());
  for (const mcap::Metadata& m : s.metadata)
    std::printf(" %s", m.name.c_str());
  std::printf("\nsummary:   %s", s.hasSummary ? "yes" : "no");
  if (s.hasSummary) {
    std::printf(" (%s, %zu chunk indexes)", s.statistics ? "statistics" : "no statistics",
                s.chunkIndexes.size());
  }
  std::printf("\n");
  return kExitOk;
}

}  // namespace

int runMcapImport(const std::string& db, const std::vector<std::string>& files,
                  const std::string& mapping, const std::string& name, bool json) {
  if (!name.empty() && files.size() != 1) {
    throw UsageError("--name needs exactly one file, got " + std::to_string(files.size()));
  }
  if (!name.empty()) requireValidName(name, "--name", "run");
  auto database = openDatabaseOrCreate(db);
  nlohmann::json runs = nlohmann::json::array();
  nlohmann::json skipped = nlohmann::json::array();
  nlohmann::json failed = nlohmann::json::array();
  std::int64_t steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const std::string& file : files) {
    workspace::McapImportRequest request;
    request.file = file;
    if (!mapping.empty()) request.mapping = mapping;
    request.name = name;
    request.sceneResolver = sim::proceduralSceneJson;
    const storage::ImportOutcome outcome = workspace::importMcap(*database, request);
    for (const std::string& warning : outcome.warnings)
      printWarning(warning);
    switch (outcome.status) {
      case storage::ImportStatus::Imported:
        steps += outcome.steps;
        runs.push_back({{"name", outcome.runName},
                        {"id", outcome.runId},
                        {"steps", outcome.steps},
                        {"file", file}});
        if (!json) {
          std::printf("imported %s as run '%s' (id %lld, %lld steps)\n", file.c_str(),
                      outcome.runName.c_str(), static_cast<long long>(outcome.runId),
                      static_cast<long long>(outcome.steps));
        }
        break;
      case storage::ImportStatus::Skipped:
        skipped.push_back({{"file", file},
                           {"name", outcome.runName},
                           {"id", outcome.runId},
                           {"message", outcome.message}});
        if (!json) std::printf("skipped %s\n", outcome.message.c_str());
        break;
      case storage::ImportStatus::Failed:
        failed.push_back({{"file", file}, {"message", outcome.message}});
        printError(outcome.message);
        break;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (json) {
    printMcapJson({{"runs", runs},
                   {"skipped", skipped},
                   {"failed", failed},
                   {"steps", steps},
                   {"seconds", seconds}});
  }
  return failed.empty() ? kExitOk : kExitFailure;
}

int runMcapExport(const std::string& db, const std::string& run, const std::string& out,
                  const std::vector<std::string>& sets, const std::string& model, bool json) {
  auto ws = std::make_unique<workspace::Workspace>(openDatabaseForRead(db));
  workspace::McapExportRequest request;
  request.run = run;
  request.labelSets = splitNames(sets);
  request.model = model;
  request.out = out;
  auto report = workspace::exportRunMcap(*ws, request);
  if (!report) {
    const Error& e = report.error();
    throw std::runtime_error(e.file.empty() ? db + ": " + e.message : e.text());
  }
  for (const std::string& warning : report->warnings)
    printWarning(warning);
  if (json) {
    printMcapJson({{"run", report->run},
                   {"steps", report->steps},
                   {"out", out},
                   {"format", "mcap"},
                   {"bytes", report->bytes},
                   {"topics", report->topics}});
  }
  return kExitOk;
}

void registerMcapVerbs(CLI::App& app) {
  CLI::App* mcapCmd = app.add_subcommand("mcap", "MCAP files (Foxglove, Lichtblick, ROS 2 bags)");
  mcapCmd->require_subcommand(1, 1);
  struct InfoArgs {
    std::string file;
    bool json = false;
  };
  auto args = std::make_shared<InfoArgs>();
  CLI::App* info = mcapCmd->add_subcommand(
      "info",
      "Describe an MCAP file: its channels (topic, encodings, schema, message count), message "
      "count, time range and compression; every record is read and checked");
  info->add_option("file", args->file, "MCAP file")->required();
  info->add_flag(
      "--json", args->json,
      R"(Print {"messages","channels":[{"topic","message_encoding","schema_name","schema_encoding","messages"}],"compression",...})");
  setAction(info, [args] { return runMcapInfo(args->file, args->json); });
}

}  // namespace tactile::cli
