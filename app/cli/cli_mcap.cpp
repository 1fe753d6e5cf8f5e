// MCAP verbs: `mcap info`, and the MCAP forms of `import` and `export-run` (docs/interop.md).
#include "app/cli/cli_mcap.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli/cli_common.h"
#include "base/file_text.h"
#include "mcap/reader.h"
#include "mcap/ros2_bag.h"
#include "mcap/run_mcap.h"
#include "mcap/writer.h"
#include "run/json_text.h"
#include "run/synthetic_run.h"
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

// ---- bench mcap ------------------------------------------------------------------------------

struct BenchMcapArgs {
  std::size_t steps = 1000000;
  int repeats = 3;
  std::string dir;
  bool keep = false;
  bool json = false;
};

// CPU seconds (user + system) of this process so far, all its threads: the work done whatever
// else the machine runs (the export runs on one thread; reading a bag and storing it use more, so
// their wall time on an idle machine is below their CPU time).
double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Timing {
  std::vector<double> cpu, wall;
  template <class F>
  void measure(F&& f) {
    const double c0 = cpuSeconds();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back(cpuSeconds() - c0);
  }
  static double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
  nlohmann::json json() const {
    return {{"cpu_s", cpu},
            {"wall_s", wall},
            {"median_cpu_s", median(cpu)},
            {"median_wall_s", median(wall)}};
  }
};

// A little-endian XCDR1 message, field by field, aligned as the format says (from the end of the
// 4-byte encapsulation header), the way the ROS 2 middleware serialises.
class Cdr {
 public:
  explicit Cdr(std::string& out) : out_(out) {
    out_.clear();
    out_.append("\x00\x01\x00\x00", 4);
  }
  template <class T>
  Cdr& put(T v) {
    while ((out_.size() - 4) % sizeof(T) != 0)
      out_.push_back('\0');
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out_.append(b, sizeof(T));
    return *this;
  }
  Cdr& str(std::string_view s) {
    put<std::uint32_t>(static_cast<std::uint32_t>(s.size() + 1));
    out_.append(s);
    out_.push_back('\0');
    return *this;
  }

 private:
  std::string& out_;
};

constexpr std::string_view kSep =
    "================================================================================\n";

std::string msgDefs(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) {
    if (!out.empty()) out.append(kSep);
    out.append(p);
  }
  return out;
}

constexpr std::string_view kVector3 =
    "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n";

// A ROS 2 bag as `ros2 bag record` and the reference writer make it: nav_msgs/msg/Odometry on
// /odom and geometry_msgs/msg/Twist on /cmd_vel before each std_msgs/msg/Float32MultiArray on
// /tactile (88 values, normals then shears), jittered stamps about 20 ms apart, CDR messages in
// zstd chunks of 16 KiB (level 3), as the reference writer of the interop tests writes them.
void writeBenchBag(const RunData& run, const std::filesystem::path& file) {
  mcap::WriterOptions o;
  o.profile = "ros2";
  o.library = "tactile bench";
  o.zstdLevel = 3;
  o.zstdHashLog = 0;  // the level's own, as the reference writer's zstd
  o.chunkBytes = 16 * 1024;
  AtomicFileWriter out;
  if (Status opened = out.open(file); !opened) throw std::runtime_error(opened.errorText());
  mcap::Writer w(o, [&](std::string_view piece) {
    if (Status written = out.write(piece); !written) throw std::runtime_error(written.errorText());
  });
  const std::string odomDef = msgDefs(
      {"std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance "
       "pose\ngeometry_msgs/TwistWithCovariance twist\n",
       "MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n",
       "MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n",
       "MSG: geometry_msgs/PoseWithCovariance\nPose pose\nfloat64[36] covariance\n",
       "MSG: geometry_msgs/Pose\nPoint position\nQuaternion orientation\n",
       "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n",
       "MSG: geometry_msgs/Quaternion\nfloat64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
       "MSG: geometry_msgs/TwistWithCovariance\nTwist twist\nfloat64[36] covariance\n",
       "MSG: geometry_msgs/Twist\nVector3  linear\nVector3  angular\n", kVector3});
  const std::string twistDef = msgDefs({"Vector3  linear\nVector3  angular\n", kVector3});
  const std::string arrayDef =
      msgDefs({"MultiArrayLayout  layout\nfloat32[]         data\n",
               "MSG: std_msgs/MultiArrayLayout\nMultiArrayDimension[] dim\nuint32 data_offset\n",
               "MSG: std_msgs/MultiArrayDimension\nstring label\nuint32 size\nuint32 stride\n"});
  const mcap::KeyValues qos{{"offered_qos_profiles", ""}};
  const auto odomCh =
      w.addChannel(w.addSchema("nav_msgs/msg/Odometry", "ros2msg", odomDef), "/odom", "cdr", qos);
  const auto cmdCh = w.addChannel(w.addSchema("geometry_msgs/msg/Twist", "ros2msg", twistDef),
                                  "/cmd_vel", "cdr", qos);
  const auto tactileCh = w.addChannel(
      w.addSchema("std_msgs/msg/Float32MultiArray", "ros2msg", arrayDef), "/tactile", "cdr", qos);
  std::string msg;
  std::uint32_t seq = 0;
  std::uint64_t t = 1700000000ULL * 1000000000ULL;
  std::uint64_t jitter = 12345;
  for (std::size_t k = 0; k < run.stepCount(); ++k) {
    jitter = jitter * 6364136223846793005ULL + 1442695040888963407ULL;
    t += 20000000 + (jitter >> 33) % 2000000;  // 20 to 22 ms
    const std::uint64_t odomT = t - 3000000;
    const double x = run.x[k] / 1000.0, y = run.y[k] / 1000.0, yaw = run.theta[k];
    const double v = run.v[k] / 1000.0, w0 = run.omega[k];
    Cdr odom(msg);
    odom.put<std::int32_t>(static_cast<std::int32_t>(odomT / 1000000000ULL))
        .put<std::uint32_t>(static_cast<std::uint32_t>(odomT % 1000000000ULL))
        .str("odom")
        .str("base_link");
    for (double f : {x, y, 0.0, 0.0, 0.0, std::sin(yaw / 2), std::cos(yaw / 2)})
      odom.put(f);
    for (int i = 0; i < 36; ++i)
      odom.put(0.01);
    for (double f : {v, 0.0, 0.0, 0.0, 0.0, w0})
      odom.put(f);
    for (int i = 0; i < 36; ++i)
      odom.put(0.0);
    w.addMessage(odomCh, seq++, odomT, odomT, msg);
    Cdr cmd(msg);
    for (double f : {v, 0.0, 0.0, 0.0, 0.0, w0})
      cmd.put(f);
    w.addMessage(cmdCh, seq++, odomT, odomT, msg);
    Cdr tactile(msg);
    tactile.put<std::uint32_t>(1).str("domes").put<std::uint32_t>(88).put<std::uint32_t>(88);
    tactile.put<std::uint32_t>(0).put<std::uint32_t>(88);
    const double* values = run.stepSensors(k);
    for (int i = 0; i < kSensorCount; ++i)
      tactile.put(static_cast<float>(values[normalOffset(i)]));
    for (int i = 0; i < kSensorCount; ++i)
      tactile.put(static_cast<float>(values[shearOffset(i)]));
    w.addMessage(tactileCh, seq++, t, t, msg);
  }
  w.finish();
  if (Status committed = out.commit(); !committed) throw std::runtime_error(committed.errorText());
}

int runBenchMcap(const BenchMcapArgs& args) {
  if (args.steps == 0 || args.repeats < 1) throw UsageError("--steps and --repeats must be >= 1");
  std::filesystem::path dir = args.dir;
  if (dir.empty()) {
    dir = std::filesystem::temp_directory_path() /
          ("tactile-bench-mcap-" + std::to_string(static_cast<long>(::getpid())));
  }
  std::filesystem::create_directories(dir);
  const std::filesystem::path streamed = dir / "run.mcap";
  const std::filesystem::path inMemory = dir / "run-in-memory.mcap";
  const std::filesystem::path bag = dir / "bag.mcap";
  const std::filesystem::path mapping = dir / "mapping.json";

  // The run: synthetic steps with truth, and one label set (the truth, as autolabel makes it).
  const RunData run = makeSyntheticRun(args.steps, true, 7);
  mcap::RunExport what;
  what.run = &run;
  what.name = "bench";
  what.library = "tactile bench";
  mcap::LabelTrack labels;
  labels.set = "truth";
  labels.annotators = {"", "truth"};
  labels.classes.resize(run.truth.size());
  labels.annotator.assign(run.truth.size(), 1);
  for (std::size_t i = 0; i < run.truth.size(); ++i)
    labels.classes[i] = static_cast<std::int8_t>(run.truth[i]);
  what.labels.push_back(std::move(labels));

  Timing stream, memory, bagWrite, bagImport;
  std::uint64_t fileBytes = 0;
  for (int r = 0; r < args.repeats; ++r) {
    // Baseline first: the whole file built in memory, then written (the exporter before
    // streaming; same writer, same bytes).
    memory.measure([&] {
      const std::string bytes = mcap::writeRunMcap(what);
      if (Status ok = writeFileAtomically(inMemory, bytes); !ok)
        throw std::runtime_error(ok.errorText());
    });
    stream.measure([&] {
      AtomicFileWriter out;
      if (Status ok = out.open(streamed); !ok) throw std::runtime_error(ok.errorText());
      mcap::writeRunMcap(what, [&](std::string_view piece) {
        if (Status ok = out.write(piece); !ok) throw std::runtime_error(ok.errorText());
      });
      if (Status ok = out.commit(); !ok) throw std::runtime_error(ok.errorText());
    });
  }
  {
    auto a = readFileText(streamed);
    auto b = readFileText(inMemory);
    if (!a || !b || a.value() != b.value())
      throw std::runtime_error("the streamed export differs from the one built in memory");
    fileBytes = a->size();
  }
  std::filesystem::remove(inMemory);

  bagWrite.measure([&] { writeBenchBag(run, bag); });
  if (Status ok = writeFileAtomically(
          mapping,
          R"({"tactile":{"topic":"/tactile","layout":"normal-then-shear"},"pose":{"topic":"/odom"},"command":{"topic":"/cmd_vel"},"scale":1000})");
      !ok) {
    throw std::runtime_error(ok.errorText());
  }
  std::int64_t importedSteps = 0;
  Timing bagRead;
  for (int r = 0; r < args.repeats; ++r) {
    // The part of the import that is this part's: the bag read into a run, nothing stored.
    bagRead.measure([&] {
      FileText text;
      if (Status ok = text.load(bag); !ok) throw std::runtime_error(ok.errorText());
      auto mapText = readFileText(mapping);
      if (!mapText) throw std::runtime_error(mapText.errorText());
      auto map = mcap::parseMapping(mapText.value(), mapping.string());
      if (!map) throw std::runtime_error(map.errorText());
      auto read = mcap::readRos2Bag(text.view(), bag.string(), map.value());
      if (!read) throw std::runtime_error(read.errorText());
      if (read->run.stepCount() != args.steps) throw std::runtime_error("the bag read short");
    });
  }
  for (int r = 0; r < args.repeats; ++r) {
    const std::filesystem::path db = dir / ("bag-" + std::to_string(r) + ".db");
    std::filesystem::remove(db);
    auto database = openDatabaseOrCreate(db.string());
    bagImport.measure([&] {
      workspace::McapImportRequest request;
      request.file = bag;
      request.mapping = mapping;
      request.name = "bag";
      const storage::ImportOutcome outcome = workspace::importMcap(database->runs(), request);
      if (outcome.status != storage::ImportStatus::Imported)
        throw std::runtime_error(outcome.message);
      importedSteps = outcome.steps;
    });
    database.reset();
    if (!args.keep) {
      for (const char* suffix : {"", "-wal", "-shm"})
        std::filesystem::remove(db.string() + suffix);
    }
  }
  if (importedSteps != static_cast<std::int64_t>(args.steps))
    throw std::runtime_error("the bag imported as " + std::to_string(importedSteps) + " steps");
  const auto bagBytes = std::filesystem::file_size(bag);
  if (!args.keep) std::filesystem::remove_all(dir);

  if (args.json) {
    printMcapJson({{"benchmark", "mcap"},
                   {"steps", args.steps},
                   {"repeats", args.repeats},
                   {"export_bytes", fileBytes},
                   {"export_streamed", stream.json()},
                   {"export_in_memory_baseline", memory.json()},
                   {"bag_bytes", bagBytes},
                   {"bag_write", bagWrite.json()},
                   {"bag_read", bagRead.json()},
                   {"bag_import", bagImport.json()}});
    return kExitOk;
  }
  std::printf("MCAP export of a %zu-step run with truth and one label set (%.1f MB), %d repeats\n",
              args.steps, 1e-6 * static_cast<double>(fileBytes), args.repeats);
  auto line = [](const char* what, const Timing& t) {
    std::printf("  %-44s median %.3f s CPU, %.3f s wall (CPU:", what, Timing::median(t.cpu),
                Timing::median(t.wall));
    for (double c : t.cpu)
      std::printf(" %.3f", c);
    std::printf(")\n");
  };
  line("streamed to the file (the exporter)", stream);
  line("baseline: built in memory, then written", memory);
  std::printf("ROS 2 bag of %zu tactile messages with odometry and command (%.1f MB)\n", args.steps,
              1e-6 * static_cast<double>(bagBytes));
  line("writing it (this program's writer)", bagWrite);
  line("reading it into a run (nothing stored)", bagRead);
  line("import with a mapping, into a new database", bagImport);
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
    const storage::ImportOutcome outcome = workspace::importMcap(database->runs(), request);
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

void registerMcapVerbs(CLI::App& app, CLI::App& bench) {
  {
    auto args = std::make_shared<BenchMcapArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "mcap",
        "MCAP export of a synthetic run (streamed, and built in memory as the baseline) and "
        "import of a ROS 2 bag this program writes; CPU and wall seconds, medians");
    cmd->add_option("--steps", args->steps, "Steps of the run and tactile messages of the bag");
    cmd->add_option("--repeats", args->repeats, "Repeats to take the median of");
    cmd->add_option("--dir", args->dir, "Work folder (default: a new temporary folder)");
    cmd->add_flag("--keep", args->keep, "Keep the files written");
    cmd->add_flag("--json", args->json, "Print the figures as JSON");
    setAction(cmd, [args] { return runBenchMcap(*args); });
  }
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
