#include "mcap/ros2_bag.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <numeric>

#include "mcap/reader.h"
#include "mcap/ros2msg.h"

namespace tactile::mcap {

namespace {

struct MappingFault {
  std::string message;
};

const nlohmann::json& member(const nlohmann::json& obj, const char* key, const std::string& where) {
  const auto it = obj.find(key);
  if (it == obj.end()) throw MappingFault{where + ": \"" + key + "\" is missing"};
  return *it;
}

std::string stringAt(const nlohmann::json& v, const std::string& where) {
  if (!v.is_string() || v.get_ref<const std::string&>().empty()) {
    throw MappingFault{where + " must be a non-empty string"};
  }
  return v.get<std::string>();
}

void onlyKeys(const nlohmann::json& obj, std::initializer_list<const char*> keys,
              const std::string& where) {
  if (!obj.is_object()) throw MappingFault{where + " must be a JSON object"};
  for (const auto& [k, v] : obj.items()) {
    if (std::none_of(keys.begin(), keys.end(), [&](const char* key) { return k == key; })) {
      std::string known;
      for (const char* key : keys)
        known += std::string(known.empty() ? "" : ", ") + key;
      throw MappingFault{where + ": unknown key \"" + k + "\" (known: " + known + ")"};
    }
  }
}

std::array<int, kSensorCount> indexList(const nlohmann::json& v, const std::string& where) {
  if (!v.is_array() || v.size() != static_cast<std::size_t>(kSensorCount)) {
    throw MappingFault{where + " must be a list of " + std::to_string(kSensorCount) +
                       " positions (one per dome, in the product's dome order)"};
  }
  std::array<int, kSensorCount> out{};
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!v[i].is_number_unsigned() || v[i].get<std::uint64_t>() > 1000000) {
      throw MappingFault{where + "[" + std::to_string(i) + "] must be a position from 0 up"};
    }
    out[i] = static_cast<int>(v[i].get<std::uint64_t>());
  }
  return out;
}

BagMapping::Topic topicOf(const nlohmann::json& obj, const std::string& where,
                          std::initializer_list<const char*> fieldKeys) {
  BagMapping::Topic t;
  t.topic = stringAt(member(obj, "topic", where), where + ".topic");
  bool any = false;
  for (const char* key : fieldKeys)
    any = any || obj.contains(key);
  if (any) {
    for (const char* key : fieldKeys) {
      t.fields.push_back(stringAt(member(obj, key, where + " (with any field named, all are)"),
                                  where + "." + key));
    }
  }
  return t;
}

}  // namespace

Result<BagMapping> parseMapping(std::string_view text, const std::string& fileName) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    const std::size_t upTo = std::min<std::size_t>(e.byte, text.size());
    const auto line = 1 + static_cast<std::size_t>(std::count(
                              text.begin(), text.begin() + static_cast<long>(upTo), '\n'));
    return Error(fileName, line, 0, "not valid JSON (" + std::string(e.what()) + ")");
  }
  BagMapping m;
  try {
    onlyKeys(doc, {"tactile", "pose", "command", "blocked", "scale"}, "the mapping");
    const auto& tactile = member(doc, "tactile", "the mapping");
    onlyKeys(tactile, {"topic", "field", "layout", "normals", "shears"}, "tactile");
    m.tactile.topic = stringAt(member(tactile, "topic", "tactile"), "tactile.topic");
    if (tactile.contains("field")) m.tactile.fields = {stringAt(tactile["field"], "tactile.field")};
    const bool explicitOrder = tactile.contains("normals") || tactile.contains("shears");
    const std::string layout = tactile.contains("layout")
                                   ? stringAt(tactile["layout"], "tactile.layout")
                                   : (explicitOrder ? "index" : "normal-then-shear");
    if (layout == "normal-then-shear") {
      for (int i = 0; i < kSensorCount; ++i) {
        m.normals[static_cast<std::size_t>(i)] = i;
        m.shears[static_cast<std::size_t>(i)] = kSensorCount + i;
      }
    } else if (layout == "interleaved") {
      for (int i = 0; i < kSensorCount; ++i) {
        m.normals[static_cast<std::size_t>(i)] = 2 * i;
        m.shears[static_cast<std::size_t>(i)] = 2 * i + 1;
      }
    } else if (layout == "index") {
      m.normals =
          indexList(member(tactile, "normals", "tactile (layout index)"), "tactile.normals");
      m.shears = indexList(member(tactile, "shears", "tactile (layout index)"), "tactile.shears");
    } else {
      throw MappingFault{
          "tactile.layout must be \"normal-then-shear\", \"interleaved\" or "
          "\"index\" (with \"normals\" and \"shears\"), found \"" +
          layout + "\""};
    }
    if (explicitOrder && layout != "index") {
      throw MappingFault{"tactile: \"normals\" and \"shears\" go with the layout \"index\""};
    }
    if (doc.contains("pose")) {
      onlyKeys(doc["pose"], {"topic", "x", "y", "qx", "qy", "qz", "qw"}, "pose");
      m.pose = topicOf(doc["pose"], "pose", {"x", "y", "qx", "qy", "qz", "qw"});
    }
    if (doc.contains("command")) {
      onlyKeys(doc["command"], {"topic", "linear", "angular"}, "command");
      m.command = topicOf(doc["command"], "command", {"linear", "angular"});
    }
    if (doc.contains("blocked")) {
      onlyKeys(doc["blocked"], {"topic", "field"}, "blocked");
      m.blocked = topicOf(doc["blocked"], "blocked", {"field"});
    }
    if (doc.contains("scale")) {
      const auto& s = doc["scale"];
      if (!s.is_number() || !std::isfinite(s.get<double>()) || s.get<double>() <= 0) {
        throw MappingFault{"scale must be a finite number > 0"};
      }
      m.scale = s.get<double>();
    }
  } catch (const MappingFault& f) {
    return Error(fileName, f.message);
  }
  return m;
}

namespace {

enum class Role : std::uint8_t { Unknown, None, Tactile, Pose, Command, Blocked };

struct Timed {
  std::uint64_t t;
  double a, b, c;
};

std::vector<std::string> defaultFields(Role role, const std::string& type) {
  switch (role) {
    case Role::Tactile:
      if (type == "std_msgs/Float32MultiArray" || type == "std_msgs/Float64MultiArray")
        return {"data"};
      break;
    case Role::Pose:
      if (type == "nav_msgs/Odometry" || type == "geometry_msgs/PoseWithCovarianceStamped") {
        return {"pose.pose.position.x",    "pose.pose.position.y",    "pose.pose.orientation.x",
                "pose.pose.orientation.y", "pose.pose.orientation.z", "pose.pose.orientation.w"};
      }
      if (type == "geometry_msgs/PoseStamped") {
        return {"pose.position.x",    "pose.position.y",    "pose.orientation.x",
                "pose.orientation.y", "pose.orientation.z", "pose.orientation.w"};
      }
      if (type == "geometry_msgs/Pose") {
        return {"position.x",    "position.y",    "orientation.x",
                "orientation.y", "orientation.z", "orientation.w"};
      }
      break;
    case Role::Command:
      if (type == "geometry_msgs/Twist") return {"linear.x", "angular.z"};
      if (type == "geometry_msgs/TwistStamped") return {"twist.linear.x", "twist.angular.z"};
      break;
    case Role::Blocked:
      if (type == "std_msgs/Bool") return {"data"};
      break;
    default:
      break;
  }
  return {};
}

const char* roleName(Role r) {
  switch (r) {
    case Role::Tactile:
      return "tactile";
    case Role::Pose:
      return "pose";
    case Role::Command:
      return "command";
    case Role::Blocked:
      return "blocked";
    default:
      return "";
  }
}

std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// Sorts by time, keeping file order among equal times.
void sortByTime(std::vector<Timed>& v) {
  if (!std::is_sorted(v.begin(), v.end(),
                      [](const Timed& a, const Timed& b) { return a.t < b.t; })) {
    std::stable_sort(v.begin(), v.end(), [](const Timed& a, const Timed& b) { return a.t < b.t; });
  }
}

}  // namespace

Result<McapRun> readRos2Bag(std::string_view bytes, const std::string& fileName,
                            const BagMapping& mapping, unsigned threads) {
  McapRun out;
  RunData& run = out.run;
  std::vector<Role> roles(65536, Role::Unknown);
  std::vector<std::unique_ptr<ros2::Decoder>> decoders(65536);
  std::vector<std::uint64_t> stepTimes;
  std::vector<Timed> poses, commands, blockedFlags;
  std::vector<double> scalars(8, 0.0);
  std::vector<std::vector<double>> arrays(8);
  int need = 0;
  for (int i = 0; i < kSensorCount; ++i)
    need = std::max({need, mapping.normals[static_cast<std::size_t>(i)] + 1,
                     mapping.shears[static_cast<std::size_t>(i)] + 1});
  std::array<std::string, 5> topicOf{};  // by role
  std::array<std::string, 5> typeOf{};

  // Sized once from the summary's count of tactile messages, where it has one that the file's
  // size makes plausible (the run's columns take at most four times the file), instead of growing
  // step by step (copies and fresh pages of a run of hundreds of megabytes).
  if (const auto expected = summaryTopicMessageCount(bytes, mapping.tactile.topic)) {
    const std::uint64_t bytesPerStep = kValuesPerStep * sizeof(double);
    if (*expected > 0 && *expected <= 4 * static_cast<std::uint64_t>(bytes.size()) / bytesPerStep) {
      const auto n = static_cast<std::size_t>(*expected);
      run.sensors.reserve(n * kValuesPerStep);
      stepTimes.reserve(n);
      if (mapping.pose) poses.reserve(n);
      if (mapping.command) commands.reserve(n);
    }
  }

  auto onMessage = [&](const MessageView& m, const Channel& channel,
                       const Schema* schema) -> Status {
    Role& role = roles[m.channelId];
    if (role == Role::Unknown) {
      role = Role::None;
      const BagMapping::Topic* topic = nullptr;
      if (channel.topic == mapping.tactile.topic) {
        role = Role::Tactile;
        topic = &mapping.tactile;
      } else if (mapping.pose && channel.topic == mapping.pose->topic) {
        role = Role::Pose;
        topic = &*mapping.pose;
      } else if (mapping.command && channel.topic == mapping.command->topic) {
        role = Role::Command;
        topic = &*mapping.command;
      } else if (mapping.blocked && channel.topic == mapping.blocked->topic) {
        role = Role::Blocked;
        topic = &*mapping.blocked;
      }
      if (role == Role::None) return {};
      const auto r = static_cast<std::size_t>(role) - 2;
      if (!topicOf[r].empty()) {
        return errorAt(
            fileName, m.fileOffset,
            "two channels carry the " + std::string(roleName(role)) + " topic " + channel.topic);
      }
      topicOf[r] = channel.topic;
      if (channel.messageEncoding != "cdr" || schema == nullptr || schema->encoding != "ros2msg") {
        return errorAt(fileName, m.fileOffset,
                       "topic " + channel.topic + ": message encoding '" + channel.messageEncoding +
                           "' with schema encoding '" + (schema ? schema->encoding : "") +
                           "'; this reader takes ROS 2 messages (cdr, ros2msg)");
      }
      auto defs = ros2::parseDefinitions(schema->name, schema->data);
      if (!defs)
        return errorAt(fileName, m.fileOffset, "topic " + channel.topic + ": " + defs.errorText());
      const std::string type = ros2::normalizeTypeName(schema->name);
      typeOf[r] = schema->name;
      std::vector<std::string> fields =
          topic->fields.empty() ? defaultFields(role, type) : topic->fields;
      if (fields.empty()) {
        return errorAt(fileName, m.fileOffset,
                       "topic " + channel.topic + " carries " + schema->name +
                           ", which has no default fields for the " + roleName(role) +
                           " role; name them in the mapping (docs/interop.md#writing-a-mapping)");
      }
      auto decoder = ros2::Decoder::make(defs.value(), fields);
      if (!decoder)
        return errorAt(fileName, m.fileOffset,
                       "topic " + channel.topic + ": " + decoder.errorText());
      const bool wantArray = role == Role::Tactile;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (decoder->isArray(k) != wantArray) {
          return errorAt(
              fileName, m.fileOffset,
              "topic " + channel.topic + ": field '" + fields[k] + "' of " + schema->name +
                  (wantArray ? " is not an array of numbers" : " is not a single number"));
        }
      }
      decoders[m.channelId] = std::make_unique<ros2::Decoder>(std::move(decoder.value()));
    }
    if (role == Role::None) return {};
    const ros2::Decoder& decoder = *decoders[m.channelId];
    if (auto problem = decoder.decode(m.data, scalars, arrays)) {
      return errorAt(
          fileName, m.fileOffset,
          "message on " + channel.topic + " (log time " + std::to_string(m.logTime) +
              (m.chunkOffset ? ", offset " + std::to_string(*m.chunkOffset) + " in the chunk"
                             : "") +
              "): " + *problem);
    }
    auto where = [&] {
      return "message " + std::to_string(stepTimes.size()) + " on " + channel.topic +
             " (log time " + std::to_string(m.logTime) +
             (m.chunkOffset ? ", offset " + std::to_string(*m.chunkOffset) + " in the chunk" : "") +
             ")";
    };
    switch (role) {
      case Role::Tactile: {
        const std::vector<double>& data = arrays[0];
        if (data.size() < static_cast<std::size_t>(need)) {
          return errorAt(fileName, m.fileOffset,
                         where() + ": " + std::to_string(data.size()) +
                             " values, the mapping needs " + std::to_string(need));
        }
        const std::size_t base = run.sensors.size();
        run.sensors.resize(base + kValuesPerStep);
        double* row = run.sensors.data() + base;
        for (int i = 0; i < kSensorCount; ++i) {
          const double n =
              data[static_cast<std::size_t>(mapping.normals[static_cast<std::size_t>(i)])];
          const double s =
              data[static_cast<std::size_t>(mapping.shears[static_cast<std::size_t>(i)])];
          if (!(n >= 0.0 && n <= kMaxNormal) || !(s >= -kMaxShear && s <= kMaxShear)) {
            run.sensors.resize(base);
            return errorAt(fileName, m.fileOffset,
                           where() + ": dome " + std::to_string(i) + " reads n " + shortest(n) +
                               ", s " + shortest(s) +
                               "; normals lie in [0, 5] and shears in [-5, 5]");
          }
          row[normalOffset(i)] = n;
          row[shearOffset(i)] = s;
        }
        stepTimes.push_back(m.logTime);
        break;
      }
      case Role::Pose: {
        const double qx = scalars[2], qy = scalars[3], qz = scalars[4], qw = scalars[5];
        const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
        poses.push_back({m.logTime, scalars[0] * mapping.scale, scalars[1] * mapping.scale, yaw});
        if (!std::isfinite(poses.back().a) || !std::isfinite(poses.back().b) ||
            !std::isfinite(yaw)) {
          return errorAt(fileName, m.fileOffset,
                         "pose message on " + channel.topic + " (log time " +
                             std::to_string(m.logTime) + ") is not finite");
        }
        break;
      }
      case Role::Command:
        commands.push_back({m.logTime, scalars[0] * mapping.scale, scalars[1], 0.0});
        if (!std::isfinite(commands.back().a) || !std::isfinite(commands.back().b)) {
          return errorAt(fileName, m.fileOffset,
                         "command message on " + channel.topic + " (log time " +
                             std::to_string(m.logTime) + ") is not finite");
        }
        break;
      case Role::Blocked:
        blockedFlags.push_back({m.logTime, scalars[0] != 0.0 ? 1.0 : 0.0, 0.0, 0.0});
        break;
      default:
        break;
    }
    return {};
  };

  auto scanned = scan(bytes, fileName, onMessage, threads);
  if (!scanned) return scanned.error();
  const std::size_t steps = stepTimes.size();
  if (steps == 0) {
    std::string topics;
    for (const auto& [id, c] : scanned->channels)
      topics += (topics.empty() ? "" : ", ") + c.topic;
    return Error(fileName, "no messages on the tactile topic " + mapping.tactile.topic +
                               " (the file's topics: " + (topics.empty() ? "none" : topics) + ")");
  }
  for (std::size_t r = 1; r < 4; ++r) {
    const std::optional<BagMapping::Topic>& t = r == 1   ? mapping.pose
                                                : r == 2 ? mapping.command
                                                         : mapping.blocked;
    if (t && topicOf[r].empty()) {
      out.warnings.push_back(fileName + ": no messages on the " +
                             roleName(static_cast<Role>(r + 2)) + " topic " + t->topic +
                             "; those values are 0");
    }
  }
  // Steps in log-time order (file order among equal times).
  std::vector<std::size_t> order(steps);
  std::iota(order.begin(), order.end(), 0);
  if (!std::is_sorted(stepTimes.begin(), stepTimes.end())) {
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return stepTimes[a] < stepTimes[b]; });
    std::vector<double> sorted(run.sensors.size());
    std::vector<std::uint64_t> times(steps);
    for (std::size_t i = 0; i < steps; ++i) {
      std::copy_n(run.sensors.data() + order[i] * kValuesPerStep, kValuesPerStep,
                  sorted.data() + i * kValuesPerStep);
      times[i] = stepTimes[order[i]];
    }
    run.sensors.swap(sorted);
    stepTimes.swap(times);
  }
  sortByTime(poses);
  sortByTime(commands);
  sortByTime(blockedFlags);
  for (auto* col : {&run.x, &run.y, &run.theta, &run.v, &run.omega})
    col->resize(steps);
  run.blocked.resize(steps);
  std::size_t p = 0, c = 0, b = 0;
  for (std::size_t i = 0; i < steps; ++i) {
    const std::uint64_t t = stepTimes[i];
    while (p < poses.size() && poses[p].t <= t)
      ++p;
    while (c < commands.size() && commands[c].t <= t)
      ++c;
    while (b < blockedFlags.size() && blockedFlags[b].t <= t)
      ++b;
    // Before the first pose message the first pose stands; before the first command, 0.
    if (!poses.empty()) {
      const Timed& pose = poses[p > 0 ? p - 1 : 0];
      run.x[i] = pose.a;
      run.y[i] = pose.b;
      run.theta[i] = pose.c;
    }
    if (c > 0) {
      run.v[i] = commands[c - 1].a;
      run.omega[i] = commands[c - 1].b;
    }
    run.blocked[i] = b > 0 && blockedFlags[b - 1].a != 0.0 ? 1 : 0;
  }
  run.metadata.emplace_back("format", std::string(kRunFormat));
  if (steps >= 2) {
    std::vector<std::uint64_t> periods(steps - 1);
    for (std::size_t i = 1; i < steps; ++i)
      periods[i - 1] = stepTimes[i] - stepTimes[i - 1];
    const std::size_t mid = periods.size() / 2;
    std::nth_element(periods.begin(), periods.begin() + static_cast<long>(mid), periods.end());
    double median = static_cast<double>(periods[mid]);
    if (periods.size() % 2 == 0) {
      const auto lower =
          *std::max_element(periods.begin(), periods.begin() + static_cast<long>(mid));
      median = 0.5 * (median + static_cast<double>(lower));
    }
    if (median <= 0.0) {
      return Error(fileName, "the tactile messages on " + mapping.tactile.topic +
                                 " share their log times: no period to take dt from");
    }
    run.setMeta("dt", shortest(median * 1e-9));
  }
  run.setMeta("source_tactile_topic", topicOf[0] + " (" + typeOf[0] + ")");
  if (!topicOf[1].empty()) run.setMeta("source_pose_topic", topicOf[1] + " (" + typeOf[1] + ")");
  if (!topicOf[2].empty()) run.setMeta("source_command_topic", topicOf[2] + " (" + typeOf[2] + ")");
  if (!topicOf[3].empty()) run.setMeta("source_blocked_topic", topicOf[3] + " (" + typeOf[3] + ")");
  return out;
}

}  // namespace tactile::mcap
