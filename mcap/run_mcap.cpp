#include "mcap/run_mcap.h"

#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mcap/bytes.h"
#include "mcap/json_out.h"
#include "mcap/reader.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::mcap {

namespace {

namespace jo = json_out;

// ---- schemas ---------------------------------------------------------------------------------

std::string groupProperties(const std::string& valueSchema) {
  std::string out;
  for (const GroupInfo& g : kSensorGroups) {
    if (!out.empty()) out += ',';
    out += "\"" + std::string(g.shortName) + "\":" + valueSchema;
  }
  return out;
}

std::string classEnum() {
  std::string out = "{\"type\":[\"string\",\"null\"],\"enum\":[";
  for (std::string_view name : kContactClassNames)
    out += "\"" + std::string(name) + "\",";
  return out + "null]}";
}

std::string tactileSchema() {
  return R"j({"title":"tactile.TactileReadings","description":"The 44 domes' normal (n, 0 to 5) and shear (s, -5 to 5) values of one step, by sensor group, domes in the product's order within each group","type":"object","properties":{"step":{"type":"integer"},)j" +
         groupProperties(
             R"j({"type":"object","properties":{"n":{"type":"array","items":{"type":"number"}},"s":{"type":"array","items":{"type":"number"}}}})j") +
         "}}";
}

constexpr std::string_view kStateSchema =
    R"j({"title":"tactile.RobotState","description":"Pose (x, y in scene units, theta in radians), command (v, omega) and blocked flag of one step","type":"object","properties":{"step":{"type":"integer"},"x":{"type":"number"},"y":{"type":"number"},"theta":{"type":"number"},"v":{"type":"number"},"omega":{"type":"number"},"blocked":{"type":"boolean"}}})j";

std::string classesSchema() {
  return R"j({"title":"tactile.Classes","description":"One contact class per sensor group (null: none)","type":"object","properties":{"step":{"type":"integer"},)j" +
         groupProperties(classEnum()) + "}}";
}

std::string labelsSchema() {
  return R"j({"title":"tactile.Labels","description":"A label set's class per sensor group (null: not labelled) and its annotators","type":"object","properties":{"step":{"type":"integer"},"set":{"type":"string"},)j" +
         groupProperties(classEnum()) +
         R"j(,"annotators":{"type":"object","description":"who labelled each labelled group, where the segment names an annotator","additionalProperties":{"type":"string"}}}})j";
}

constexpr std::string_view kExtraSchema =
    R"j({"title":"tactile.ExtraColumns","description":"The run's x_ columns of one step, as text","type":"object","properties":{"step":{"type":"integer"}},"additionalProperties":{"type":"string"}})j";

constexpr std::string_view kTimeSchema =
    R"j({"type":"object","properties":{"sec":{"type":"integer","minimum":0},"nsec":{"type":"integer","minimum":0,"maximum":999999999}}})j";
constexpr std::string_view kVector3Schema =
    R"j({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},"z":{"type":"number"}}})j";
constexpr std::string_view kQuaternionSchema =
    R"j({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},"z":{"type":"number"},"w":{"type":"number"}}})j";

std::string poseSchema() {
  return std::string(R"j({"type":"object","properties":{"position":)j") +
         std::string(kVector3Schema) + R"j(,"orientation":)j" + std::string(kQuaternionSchema) +
         "}}";
}

std::string poseInFrameSchema() {
  return R"j({"title":"foxglove.PoseInFrame","description":"A timestamped pose for an object or reference frame in 3D space","type":"object","properties":{"timestamp":)j" +
         std::string(kTimeSchema) + R"j(,"frame_id":{"type":"string"},"pose":)j" + poseSchema() +
         "}}";
}

std::string sceneUpdateSchema() {
  const std::string color =
      R"j({"type":"object","properties":{"r":{"type":"number"},"g":{"type":"number"},"b":{"type":"number"},"a":{"type":"number"}}})j";
  const std::string line =
      R"j({"type":"object","properties":{"type":{"type":"integer","description":"0 line strip, 1 line loop, 2 line list"},"pose":)j" +
      poseSchema() +
      R"j(,"thickness":{"type":"number"},"scale_invariant":{"type":"boolean"},"points":{"type":"array","items":)j" +
      std::string(kVector3Schema) + R"j(},"color":)j" + color +
      R"j(,"colors":{"type":"array","items":)j" + color +
      R"j(},"indices":{"type":"array","items":{"type":"integer"}}}})j";
  const std::string any = R"j({"type":"array","items":{"type":"object"}})j";
  const std::string entity =
      R"j({"type":"object","properties":{"timestamp":)j" + std::string(kTimeSchema) +
      R"j(,"frame_id":{"type":"string"},"id":{"type":"string"},"lifetime":)j" +
      std::string(kTimeSchema) + R"j(,"frame_locked":{"type":"boolean"},"metadata":)j" + any +
      R"j(,"arrows":)j" + any + R"j(,"cubes":)j" + any + R"j(,"spheres":)j" + any +
      R"j(,"cylinders":)j" + any + R"j(,"lines":{"type":"array","items":)j" + line +
      R"j(},"triangles":)j" + any + R"j(,"texts":)j" + any + R"j(,"models":)j" + any + "}}";
  return R"j({"title":"foxglove.SceneUpdate","description":"An update to the entities displayed in a 3D scene","type":"object","properties":{"deletions":{"type":"array","items":{"type":"object"}},"entities":{"type":"array","items":)j" +
         entity + "}}}";
}

// ---- messages --------------------------------------------------------------------------------

void timestamp(Appender& out, std::uint64_t ns) {
  out.lit("{\"sec\":");
  out.integer(ns / 1000000000U);
  out.lit(",\"nsec\":");
  out.integer(ns % 1000000000U);
  out.put('}');
}

void vector3(Appender& out, double x, double y, double z) {
  out.lit("{\"x\":");
  out.number(x);
  out.lit(",\"y\":");
  out.number(y);
  out.lit(",\"z\":");
  out.number(z);
  out.put('}');
}

// The Foxglove messages are for viewing (the exact values are on /robot/state): positions to the
// micrometre, quaternions to 9 decimals.
void position(Appender& out, double x, double y) {
  out.lit("{\"x\":");
  out.fixed(x, 6);
  out.lit(",\"y\":");
  out.fixed(y, 6);
  out.lit(",\"z\":0}");
}

void yawQuaternion(Appender& out, double theta) {
  out.lit("{\"x\":0,\"y\":0,\"z\":");
  out.fixed(std::sin(0.5 * theta), 9);
  out.lit(",\"w\":");
  out.fixed(std::cos(0.5 * theta), 9);
  out.put('}');
}

std::string sceneUpdate(const std::string& sceneJson, std::uint64_t ns) {
  const nlohmann::json scene = nlohmann::json::parse(sceneJson, nullptr, false);
  if (!scene.is_object()) return {};
  Buffer linesBuffer;
  Appender lines(linesBuffer);
  bool anyLine = false;
  auto loop = [&](const std::vector<std::pair<double, double>>& points, std::string_view color) {
    if (points.size() < 2) return;
    if (anyLine) lines.put(',');
    anyLine = true;
    lines.text(
        R"j({"type":1,"pose":{"position":{"x":0,"y":0,"z":0},"orientation":{"x":0,"y":0,"z":0,"w":1}},"thickness":0.01,"scale_invariant":false,"points":[)j");
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i > 0) lines.put(',');
      vector3(lines, points[i].first / kSceneUnitsPerMetre, points[i].second / kSceneUnitsPerMetre,
              0.0);
    }
    lines.lit("],\"color\":");
    lines.text(color);
    lines.lit(R"j(,"colors":[],"indices":[]})j");
  };
  const auto& bounds = scene.value("bounds", nlohmann::json::array());
  if (bounds.is_array() && bounds.size() == 4 &&
      std::all_of(bounds.begin(), bounds.end(), [](const auto& v) { return v.is_number(); })) {
    const double x0 = bounds[0].get<double>(), y0 = bounds[1].get<double>();
    const double x1 = bounds[2].get<double>(), y1 = bounds[3].get<double>();
    loop({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, R"j({"r":0.6,"g":0.6,"b":0.6,"a":1})j");
  }
  const auto& obstacles = scene.value("obstacles", nlohmann::json::array());
  if (obstacles.is_array()) {
    for (const auto& o : obstacles) {
      if (!o.is_object() || !o.contains("polygon") || !o["polygon"].is_array()) continue;
      std::vector<std::pair<double, double>> points;
      for (const auto& p : o["polygon"]) {
        if (p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number()) {
          points.emplace_back(p[0].get<double>(), p[1].get<double>());
        }
      }
      loop(points, R"j({"r":0.9,"g":0.5,"b":0.1,"a":1})j");
    }
  }
  lines.flush();
  Buffer outBuffer;
  Appender out(outBuffer);
  out.lit(R"j({"deletions":[],"entities":[{"timestamp":)j");
  timestamp(out, ns);
  out.text(
      R"j(,"frame_id":"scene","id":"walls","lifetime":{"sec":0,"nsec":0},"frame_locked":false,"metadata":[],"arrows":[],"cubes":[],"spheres":[],"cylinders":[],"lines":[)j");
  out.text(linesBuffer.view());
  out.lit(R"j(],"triangles":[],"texts":[],"models":[]}]})j");
  out.flush();
  return std::string(outBuffer.view());
}

std::uint64_t stepTime(std::size_t step, double dt) {
  return static_cast<std::uint64_t>(std::llround(static_cast<double>(step) * dt * 1e9));
}

}  // namespace

namespace {

bool writeRun(Writer& w, const RunExport& what, const ExportProgress& progress) {
  const RunData& run = *what.run;
  const std::size_t steps = what.window ? what.steps : run.stepCount();
  const bool hasTruth = what.window ? what.truth : run.hasTruth();
  const std::optional<double> runDt = run.dtSeconds();
  const double dt = runDt && *runDt > 0 ? *runDt : kDefaultExportDt;

  // Metadata first, so a reader knows the file before its messages.
  KeyValues exportInfo{{"format", std::string(kRunMcapFormat)},
                       {"run", what.name},
                       {"steps", std::to_string(steps)},
                       {"truth", hasTruth ? "yes" : "no"},
                       {"scene_units_per_metre", "1000"}};
  if (!runDt) exportInfo.emplace_back("dt_assumed", "0.1");
  {
    std::string columns = "[";
    for (std::size_t i = 0; i < run.extraColumns.size(); ++i) {
      if (i > 0) columns.push_back(',');
      jo::string(columns, run.extraColumns[i]);
    }
    exportInfo.emplace_back("extra_columns", columns + "]");
  }
  w.addMetadata("tactile.export", exportInfo);
  w.addMetadata("tactile.run", run.metadata);

  const std::uint16_t tactileCh = w.addChannel(
      w.addSchema("tactile.TactileReadings", "jsonschema", tactileSchema()), "/tactile", "json");
  const std::uint16_t stateCh = w.addChannel(
      w.addSchema("tactile.RobotState", "jsonschema", kStateSchema), "/robot/state", "json");
  const std::uint16_t poseCh =
      w.addChannel(w.addSchema("foxglove.PoseInFrame", "jsonschema", poseInFrameSchema()),
                   "/robot/pose", "json");
  std::uint16_t classesSchemaId = 0;
  auto classes = [&] {
    if (classesSchemaId == 0)
      classesSchemaId = w.addSchema("tactile.Classes", "jsonschema", classesSchema());
    return classesSchemaId;
  };
  const std::uint16_t truthCh = hasTruth ? w.addChannel(classes(), "/truth", "json") : 0;
  std::vector<std::uint16_t> labelChs;
  if (!what.labels.empty()) {
    const std::uint16_t schema = w.addSchema("tactile.Labels", "jsonschema", labelsSchema());
    for (const LabelTrack& t : what.labels)
      labelChs.push_back(w.addChannel(schema, "/labels/" + t.set, "json", {{"label_set", t.set}}));
  }
  std::vector<std::uint16_t> decisionChs;
  for (const DecisionTrack& t : what.decisions) {
    decisionChs.push_back(w.addChannel(classes(), "/decisions/" + t.model, "json",
                                       {{"model", t.model}, {"decision", t.decision}}));
  }
  const std::uint16_t extraCh =
      run.extraColumns.empty()
          ? 0
          : w.addChannel(w.addSchema("tactile.ExtraColumns", "jsonschema", kExtraSchema), "/extra",
                         "json");
  if (what.sceneJson) {
    const std::string update = sceneUpdate(*what.sceneJson, 0);
    if (!update.empty()) {
      const std::uint16_t sceneCh = w.addChannel(
          w.addSchema("foxglove.SceneUpdate", "jsonschema", sceneUpdateSchema()), "/scene", "json");
      w.addMessage(sceneCh, 0, 0, 0, update);
    }
  }

  std::array<std::string, kGroupCount> keys;  // ",\"F\":" ...
  for (const GroupInfo& g : kSensorGroups)
    keys[static_cast<std::size_t>(groupIndex(g.group))] = ",\"" + std::string(g.shortName) + "\":";
  std::array<std::string, kContactClassNames.size()> quoted;  // "\"NoContact\"" ...
  for (std::size_t c = 0; c < quoted.size(); ++c)
    quoted[c] = "\"" + std::string(kContactClassNames[c]) + "\"";
  auto className = [&](int c) -> std::string_view { return quoted[static_cast<std::size_t>(c)]; };

  const std::size_t extras = run.extraColumns.size();
  // The steps: the whole run, or a window of it at a time (`at` is the window's first step).
  const RunData* win = &run;
  std::size_t at = 0;
  for (std::size_t k = 0; k < steps; ++k) {
    if (k - at >= win->stepCount()) {
      if (!what.window) throw std::logic_error("the run has fewer steps than it says");
      win = what.window(k);
      at = k;
      if (win == nullptr || win->stepCount() == 0 ||
          win->sensors.size() < win->stepCount() * kValuesPerStep ||
          (hasTruth && win->truth.size() < win->stepCount() * kGroupCount) ||
          win->extraValues.size() < win->stepCount() * extras)
        throw std::runtime_error("step " + std::to_string(k) + ": the run's window holds no steps");
    }
    const std::size_t i = k - at;  // the step in the window
    if (progress && k % kProgressSteps == 0 && !progress(k, steps)) return false;
    const std::uint64_t t = stepTime(k, dt);
    const auto seq = static_cast<std::uint32_t>(k);
    w.addMessageWith(tactileCh, seq, t, t, [&](Appender& out) {
      out.lit("{\"step\":");
      out.integer(k);
      const double* v = win->stepSensors(i);
      for (const GroupInfo& g : kSensorGroups) {
        out.text(keys[static_cast<std::size_t>(groupIndex(g.group))]);
        out.lit("{\"n\":[");
        for (int i = 0; i < g.sensorCount; ++i) {
          if (i > 0) out.put(',');
          out.number(v[normalOffset(g.firstSensor + i)]);
        }
        out.lit("],\"s\":[");
        for (int i = 0; i < g.sensorCount; ++i) {
          if (i > 0) out.put(',');
          out.number(v[shearOffset(g.firstSensor + i)]);
        }
        out.lit("]}");
      }
      out.put('}');
    });
    w.addMessageWith(stateCh, seq, t, t, [&](Appender& out) {
      out.lit("{\"step\":");
      out.integer(k);
      out.lit(",\"x\":");
      out.number(win->x[i]);
      out.lit(",\"y\":");
      out.number(win->y[i]);
      out.lit(",\"theta\":");
      out.number(win->theta[i]);
      out.lit(",\"v\":");
      out.number(win->v[i]);
      out.lit(",\"omega\":");
      out.number(win->omega[i]);
      out.text(win->blocked[i] != 0 ? ",\"blocked\":true}" : ",\"blocked\":false}");
    });
    w.addMessageWith(poseCh, seq, t, t, [&](Appender& out) {
      out.lit("{\"timestamp\":");
      timestamp(out, t);
      out.lit(",\"frame_id\":\"scene\",\"pose\":{\"position\":");
      position(out, win->x[i] / kSceneUnitsPerMetre, win->y[i] / kSceneUnitsPerMetre);
      out.lit(",\"orientation\":");
      yawQuaternion(out, win->theta[i]);
      out.lit("}}");
    });
    if (truthCh != 0) {
      w.addMessageWith(truthCh, seq, t, t, [&](Appender& out) {
        out.lit("{\"step\":");
        out.integer(k);
        for (int g = 0; g < kGroupCount; ++g) {
          out.text(keys[static_cast<std::size_t>(g)]);
          out.text(className(
              static_cast<int>(win->truth[i * kGroupCount + static_cast<std::size_t>(g)])));
        }
        out.put('}');
      });
    }
    for (std::size_t s = 0; s < what.labels.size(); ++s) {
      const LabelTrack& track = what.labels[s];
      w.addMessageWith(labelChs[s], seq, t, t, [&](Appender& out) {
        out.lit("{\"step\":");
        out.integer(k);
        out.lit(",\"set\":");
        out.string(track.set);
        bool anyAnnotator = false;
        for (int g = 0; g < kGroupCount; ++g) {
          const std::size_t i = k * kGroupCount + static_cast<std::size_t>(g);
          out.text(keys[static_cast<std::size_t>(g)]);
          if (track.classes[i] < 0) {
            out.lit("null");
            continue;
          }
          anyAnnotator = anyAnnotator || track.annotator[i] != 0;
          out.text(className(track.classes[i]));
        }
        if (anyAnnotator) {
          // Who labelled each labelled group (groups without an annotator are left out).
          out.lit(",\"annotators\":{");
          bool first = true;
          for (int g = 0; g < kGroupCount; ++g) {
            const std::size_t i = k * kGroupCount + static_cast<std::size_t>(g);
            if (track.classes[i] < 0 || track.annotator[i] == 0) continue;
            if (!first) out.put(',');
            first = false;
            out.text(keys[static_cast<std::size_t>(g)].substr(1));
            out.string(track.annotators[track.annotator[i]]);
          }
          out.put('}');
        }
        out.put('}');
      });
    }
    for (std::size_t m = 0; m < what.decisions.size(); ++m) {
      const DecisionTrack& track = what.decisions[m];
      w.addMessageWith(decisionChs[m], seq, t, t, [&](Appender& out) {
        out.lit("{\"step\":");
        out.integer(k);
        for (int g = 0; g < kGroupCount; ++g) {
          const std::int8_t c = track.classes[k * kGroupCount + static_cast<std::size_t>(g)];
          out.text(keys[static_cast<std::size_t>(g)]);
          if (c < 0) {
            out.lit("null");
          } else {
            out.text(className(c));
          }
        }
        out.put('}');
      });
    }
    if (extraCh != 0) {
      w.addMessageWith(extraCh, seq, t, t, [&](Appender& out) {
        out.lit("{\"step\":");
        out.integer(k);
        for (std::size_t c = 0; c < extras; ++c) {
          out.put(',');
          out.string(run.extraColumns[c]);
          out.put(':');
          out.string(win->extraValues[i * extras + c]);
        }
        out.put('}');
      });
    }
  }
  if (progress && !progress(steps, steps)) return false;
  return true;
}

WriterOptions exportOptions(const RunExport& what, WriterOptions options) {
  options.library = what.library;
  return options;
}

}  // namespace

std::string writeRunMcap(const RunExport& what, WriterOptions options) {
  options = exportOptions(what, options);
  // About 1.3 KB a step before compression, a fifth of that after (measured on simulated runs).
  options.reserveBytes = std::max<std::size_t>(options.reserveBytes, 300 * what.run->stepCount());
  Writer w(options);
  writeRun(w, what, {});
  return w.finish();
}

bool writeRunMcap(const RunExport& what, const Sink& sink, WriterOptions options,
                  const ExportProgress& progress) {
  Writer w(exportOptions(what, options), sink);
  if (!writeRun(w, what, progress)) return false;
  w.finish();
  return true;
}

// ---- import ----------------------------------------------------------------------------------

bool looksLikeRunMcap(std::string_view bytes) {
  // Magic, Header, then the exporter's first record: Metadata "tactile.export".
  if (bytes.size() < kMagic.size() + 9 || bytes.substr(0, kMagic.size()) != kMagic) return false;
  std::size_t pos = kMagic.size();
  const std::uint64_t headerLen = bytes::getU64(bytes.data() + pos + 1);
  if (bytes[pos] != 0x01 || headerLen > bytes.size() - pos - 9) return false;
  pos += 9 + static_cast<std::size_t>(headerLen);
  if (bytes.size() - pos < 9 + 4 + 14 || bytes[pos] != 0x0C) return false;
  const std::uint32_t nameLen = bytes::getU32(bytes.data() + pos + 9);
  return nameLen == 14 && bytes.substr(pos + 13, 14) == "tactile.export";
}

namespace {

enum class Kind : std::int8_t { Unknown = -2, Other = -1, Tactile, State, Truth, Extra };

Kind kindOf(const Channel& c, const std::map<std::uint16_t, Schema>& schemas) {
  const auto it = schemas.find(c.schemaId);
  if (it == schemas.end() || c.messageEncoding != "json") return Kind::Other;
  const std::string& name = it->second.name;
  if (name == "tactile.TactileReadings" && c.topic == "/tactile") return Kind::Tactile;
  if (name == "tactile.RobotState") return Kind::State;
  if (name == "tactile.Classes" && c.topic == "/truth") return Kind::Truth;
  if (name == "tactile.ExtraColumns") return Kind::Extra;
  return Kind::Other;
}

struct Fail {
  std::string message;
};

double numberAt(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) throw Fail{std::string("\"") + key + "\" is not a number"};
  return it->get<double>();
}

}  // namespace

Result<McapRun> readRunMcap(std::string_view bytes, const std::string& fileName) {
  McapRun out;
  RunData& run = out.run;
  const std::uint64_t maxSteps = bytes.size() / 31;  // every step has a message of >= 31 bytes
  std::vector<std::array<std::uint8_t, 4>> seen;     // per step: tactile, state, truth, extra
  std::vector<std::string> extraColumns;
  bool haveExport = false;
  bool haveTruth = false;
  std::size_t declaredSteps = 0;
  std::vector<Kind> kinds(65536, Kind::Unknown);
  // Schemas are known to the scan; the callback sees channels. Keep the schema names by id.
  std::map<std::uint16_t, Schema> schemasSeen;

  auto ensure = [&](std::uint64_t step) {
    if (step >= maxSteps)
      throw Fail{"step " + std::to_string(step) + " is past what a file of " +
                 std::to_string(bytes.size()) + " bytes can hold"};
    if (step < seen.size()) return;
    const std::size_t n = static_cast<std::size_t>(step) + 1;
    seen.resize(n, {0, 0, 0, 0});
    for (auto* col : {&run.x, &run.y, &run.theta, &run.v, &run.omega})
      col->resize(n, 0.0);
    run.blocked.resize(n, 0);
    run.sensors.resize(n * kValuesPerStep, 0.0);
    if (haveTruth) run.truth.resize(n * kGroupCount, ContactClass::NoContact);
    run.extraValues.resize(n * extraColumns.size());
  };

  auto onMessage = [&](const MessageView& m, const Channel& channel, const Schema*) -> Status {
    Kind& kind = kinds[m.channelId];
    if (kind == Kind::Unknown) {
      // The exporter writes its Metadata records first; nothing else is read without them.
      kind = Kind::Other;
      const auto it = schemasSeen.find(channel.schemaId);
      if (it != schemasSeen.end()) kind = kindOf(channel, schemasSeen);
    }
    if (kind == Kind::Other) return {};
    const std::uint64_t recordAt = m.fileOffset;
    try {
      nlohmann::json j = nlohmann::json::parse(m.data.begin(), m.data.end());
      if (!j.is_object()) throw Fail{"the message is not a JSON object"};
      const auto stepIt = j.find("step");
      if (stepIt == j.end() || !stepIt->is_number_unsigned())
        throw Fail{"\"step\" is not a step number"};
      const std::uint64_t step = stepIt->get<std::uint64_t>();
      ensure(step);
      auto& flags = seen[static_cast<std::size_t>(step)];
      auto& flag = flags[static_cast<std::size_t>(kind)];
      if (flag != 0)
        throw Fail{"step " + std::to_string(step) + " appears twice on " + channel.topic};
      flag = 1;
      const auto k = static_cast<std::size_t>(step);
      switch (kind) {
        case Kind::Tactile: {
          double* values = run.sensors.data() + k * kValuesPerStep;
          for (const GroupInfo& g : kSensorGroups) {
            const auto git = j.find(std::string(g.shortName));
            if (git == j.end() || !git->is_object()) {
              throw Fail{"group " + std::string(g.shortName) + " is missing"};
            }
            for (const char* part : {"n", "s"}) {
              const auto pit = git->find(part);
              if (pit == git->end() || !pit->is_array() ||
                  pit->size() != static_cast<std::size_t>(g.sensorCount)) {
                throw Fail{"group " + std::string(g.shortName) + ": \"" + part +
                           "\" does not hold " + std::to_string(g.sensorCount) + " numbers"};
              }
              for (int i = 0; i < g.sensorCount; ++i) {
                const auto& v = (*pit)[static_cast<std::size_t>(i)];
                if (!v.is_number())
                  throw Fail{"group " + std::string(g.shortName) + ": a value is not a number"};
                const int sensor = g.firstSensor + i;
                values[part[0] == 'n' ? normalOffset(sensor) : shearOffset(sensor)] =
                    v.get<double>();
              }
            }
          }
          break;
        }
        case Kind::State: {
          run.x[k] = numberAt(j, "x");
          run.y[k] = numberAt(j, "y");
          run.theta[k] = numberAt(j, "theta");
          run.v[k] = numberAt(j, "v");
          run.omega[k] = numberAt(j, "omega");
          const auto bit = j.find("blocked");
          if (bit == j.end() || !bit->is_boolean()) throw Fail{"\"blocked\" is not true or false"};
          run.blocked[k] = bit->get<bool>() ? 1 : 0;
          break;
        }
        case Kind::Truth: {
          if (!haveTruth)
            throw Fail{"/truth messages in a file whose tactile.export says truth: no"};
          for (const GroupInfo& g : kSensorGroups) {
            const auto git = j.find(std::string(g.shortName));
            if (git == j.end() || !git->is_string())
              throw Fail{"truth of group " + std::string(g.shortName) + " is missing"};
            const auto cls = parseContactClass(git->get_ref<const std::string&>());
            if (!cls) throw Fail{"unknown class '" + git->get<std::string>() + "'"};
            run.truth[k * kGroupCount + static_cast<std::size_t>(groupIndex(g.group))] = *cls;
          }
          break;
        }
        case Kind::Extra: {
          for (std::size_t c = 0; c < extraColumns.size(); ++c) {
            const auto eit = j.find(extraColumns[c]);
            if (eit == j.end() || !eit->is_string())
              throw Fail{"column " + extraColumns[c] + " is missing"};
            run.extraValues[k * extraColumns.size() + c] = eit->get<std::string>();
          }
          break;
        }
        default:
          break;
      }
    } catch (const Fail& f) {
      return errorAt(fileName, recordAt, channel.topic + " message: " + f.message);
    } catch (const nlohmann::json::exception& e) {
      return errorAt(fileName, recordAt,
                     channel.topic + " message: not valid JSON (" + e.what() + ")");
    }
    return {};
  };

  // Two passes: the first, without messages, finds the Metadata and Schema records wherever they
  // are in the file (cheap next to parsing the messages); the second reads the messages.
  auto first = scan(bytes, fileName);
  if (!first) return first.error();
  for (const Metadata& m : first->metadata) {
    if (m.name == "tactile.export") {
      haveExport = true;
      for (const auto& [k, v] : m.entries) {
        if (k == "format" && v != kRunMcapFormat) {
          return Error(fileName, "an MCAP export of format '" + v + "'; this program reads '" +
                                     std::string(kRunMcapFormat) + "'");
        }
        if (k == "run") out.nameInFile = v;
        if (k == "truth") haveTruth = v == "yes";
        if (k == "steps") {
          std::uint64_t n = 0;
          for (char c : v)
            n = c >= '0' && c <= '9' && n < maxSteps ? n * 10 + static_cast<std::uint64_t>(c - '0')
                                                     : maxSteps;
          declaredSteps = static_cast<std::size_t>(std::min<std::uint64_t>(n, maxSteps));
        }
        if (k == "extra_columns") {
          const nlohmann::json cols = nlohmann::json::parse(v, nullptr, false);
          if (!cols.is_array())
            return Error(fileName, "tactile.export: extra_columns is not a JSON array");
          for (const auto& c : cols) {
            if (!c.is_string())
              return Error(fileName, "tactile.export: extra_columns holds a non-string");
            extraColumns.push_back(c.get<std::string>());
          }
        }
      }
    } else if (m.name == "tactile.run") {
      run.metadata = m.entries;
    }
  }
  if (!haveExport) {
    return Error(
        fileName,
        "not an MCAP export of this program (it has no tactile.export Metadata record); "
        "to import a ROS 2 bag, give a mapping file (--mapping MAP.json, docs/interop.md)");
  }
  schemasSeen = first->schemas;
  run.extraColumns = extraColumns;
  if (haveTruth) run.truth.reserve(declaredSteps * kGroupCount);
  auto second = scan(bytes, fileName, onMessage);
  if (!second) return second.error();
  const std::size_t n = seen.size();
  if (n != declaredSteps) {
    return Error(fileName, "tactile.export says " + std::to_string(declaredSteps) +
                               " steps, the messages hold " + std::to_string(n));
  }
  if (n == 0) return Error(fileName, "the run has no steps");
  for (std::size_t k = 0; k < n; ++k) {
    const auto& f = seen[k];
    const char* missing = f[0] == 0                              ? "/tactile"
                          : f[1] == 0                            ? "/robot/state"
                          : (haveTruth && f[2] == 0)             ? "/truth"
                          : (!extraColumns.empty() && f[3] == 0) ? "/extra"
                                                                 : nullptr;
    if (missing != nullptr) {
      return Error(fileName, "step " + std::to_string(k) + " has no message on " + missing);
    }
  }
  return out;
}

}  // namespace tactile::mcap
