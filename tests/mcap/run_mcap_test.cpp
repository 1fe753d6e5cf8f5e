// Runs through MCAP: an export reads back value for value (and formats to the same run file), and
// a ROS 2 bag built here message by message imports with the values it holds.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "mcap/reader.h"
#include "mcap/ros2_bag.h"
#include "mcap/run_mcap.h"
#include "run/run_csv.h"
#include "run/synthetic_run.h"
#include "tests/mcap/mcap_test_util.h"
#include "tests/run_compare.h"

namespace tactile::mcap {
namespace {

using test::CdrOut;

RunData sampleRun(std::size_t steps) {
  RunData run = makeSyntheticRun(steps, true, 11);
  run.setMeta("dt", "0.05");
  run.setMeta("note", "a \"quoted\" value, with a comma");
  run.extraColumns = {"x_strategy", "x_status"};
  for (std::size_t k = 0; k < steps; ++k) {
    run.extraValues.push_back(k % 2 == 0 ? "GoStraight" : "Follow \\ Wall");
    run.extraValues.push_back(std::to_string(k));
  }
  run.sensors[5] = -0.0;  // a shear of -0 keeps its sign
  run.theta[1] = -0.0;
  return run;
}

TEST(RunMcap, ExportReadsBackValueForValue) {
  const RunData run = sampleRun(400);
  RunExport what;
  what.run = &run;
  what.name = "sample";
  what.sceneJson =
      R"({"name":"s","bounds":[0,0,1000,800],"obstacles":[{"polygon":[[1,1],[2,1],[2,2]]}]})";
  LabelTrack labels;
  labels.set = "mine";
  labels.classes.assign(400 * kGroupCount, -1);
  labels.annotator.assign(400 * kGroupCount, 0);
  labels.annotators = {"", "ann"};
  labels.classes[8 * 3 + 2] = static_cast<std::int8_t>(ContactClass::Wall);
  labels.annotator[8 * 3 + 2] = 1;
  what.labels.push_back(labels);
  WriterOptions small;
  small.chunkBytes = 10000;
  const std::string bytes = writeRunMcap(what, small);
  EXPECT_TRUE(looksLikeRunMcap(bytes));

  auto back = readRunMcap(bytes, "s.mcap");
  ASSERT_TRUE(back.ok()) << back.errorText();
  EXPECT_EQ(back->nameInFile, "sample");
  test_support::expectSameRun(run, back->run);
  EXPECT_EQ(formatRunCsv(run), formatRunCsv(back->run));

  // The viewer's channels, read as JSON: the label message of step 3 and a pose in metres.
  std::string label3;
  std::string pose0;
  std::string scene;
  auto scanned =
      scan(bytes, "s.mcap", [&](const MessageView& m, const Channel& c, const Schema* s) {
        if (c.topic == "/labels/mine" && m.sequence == 3) label3 = std::string(m.data);
        if (c.topic == "/robot/pose" && m.sequence == 0) pose0 = std::string(m.data);
        if (c.topic == "/scene") scene = std::string(m.data);
        if (c.topic == "/tactile") {
          EXPECT_EQ(m.logTime, m.sequence * 50000000ULL);
        }
        EXPECT_TRUE(s != nullptr && s->encoding == "jsonschema");
        return Status{};
      });
  ASSERT_TRUE(scanned.ok()) << scanned.errorText();
  const auto label = nlohmann::json::parse(label3);
  EXPECT_EQ(label["L"], "Wall");
  EXPECT_TRUE(label["F"].is_null());
  EXPECT_EQ(label["annotators"]["L"], "ann");
  const auto pose = nlohmann::json::parse(pose0);
  EXPECT_EQ(pose["frame_id"], "scene");
  EXPECT_NEAR(pose["pose"]["position"]["x"].get<double>(), run.x[0] / 1000.0, 1e-6);
  EXPECT_NEAR(pose["pose"]["orientation"]["z"].get<double>(), std::sin(run.theta[0] / 2), 1e-8);
  const auto sceneJson = nlohmann::json::parse(scene);
  ASSERT_EQ(sceneJson["entities"][0]["lines"].size(), 2U);  // the bounds and one obstacle
  EXPECT_EQ(sceneJson["entities"][0]["lines"][0]["points"][2]["x"], 1.0);  // (1000, 800) in m
  EXPECT_EQ(scanned->channels.size(), 7U);  // tactile, state, pose, truth, labels, extra, scene
}

TEST(RunMcap, NotAnExportIsRefused) {
  Writer w;
  w.addMessage(w.addChannel(0, "/x", "json"), 0, 1, 1, "{}");
  const std::string other = w.finish();
  EXPECT_FALSE(looksLikeRunMcap(other));
  auto r = readRunMcap(other, "o.mcap");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("o.mcap: not an MCAP export of this program"), std::string::npos);
}

// A bag as ROS 2 writes one: cdr messages with ros2msg schemas, tactile at jittered stamps.
struct Bag {
  std::string bytes;
  std::vector<std::vector<float>> tactile;  // as written, in time order
  std::vector<std::uint64_t> times;
};

Bag makeBag(std::size_t steps, Compression compression, bool summary = true,
            std::size_t chunkBytes = 4096) {
  WriterOptions o;
  o.profile = "ros2";
  o.compression = compression;
  o.chunkBytes = chunkBytes;
  o.summary = summary;
  Writer w(o);
  const auto tactile = w.addChannel(
      w.addSchema("std_msgs/msg/Float32MultiArray", "ros2msg", test::float32ArraySchema()),
      "/tactile", "cdr");
  const auto pose = w.addChannel(
      w.addSchema("geometry_msgs/msg/PoseStamped", "ros2msg", test::poseStampedSchema()), "/pose",
      "cdr");
  const auto cmd = w.addChannel(
      w.addSchema("geometry_msgs/msg/Twist", "ros2msg", test::twistSchema()), "/cmd_vel", "cdr");
  const auto bumper = w.addChannel(w.addSchema("std_msgs/msg/Bool", "ros2msg", test::boolSchema()),
                                   "/bumper", "cdr");
  Bag bag;
  for (std::size_t k = 0; k < steps; ++k) {
    const std::uint64_t t = 1000000000ULL + k * 20000000ULL + (k * 7919 % 13) * 100000ULL;
    // Pose and command 1 ms before the reading, so "at or before" picks them.
    CdrOut p;
    p.put<std::int32_t>(1).put<std::uint32_t>(0).str("odom");
    const double yaw = 0.01 * static_cast<double>(k);
    p.put<double>(0.001 * static_cast<double>(k)).put<double>(2.0).put<double>(0.0);
    p.put<double>(0.0)
        .put<double>(0.0)
        .put<double>(std::sin(yaw / 2))
        .put<double>(std::cos(yaw / 2));
    w.addMessage(pose, 0, t - 1000000, t - 1000000, p.bytes());
    CdrOut c;
    c.put<double>(0.25 + static_cast<double>(k)).put<double>(0.0).put<double>(0.0);
    c.put<double>(0.0).put<double>(0.0).put<double>(-0.5);
    w.addMessage(cmd, 0, t - 1000000, t - 1000000, c.bytes());
    if (k == 5 || k == 6) {
      CdrOut b;
      b.put<std::uint8_t>(k == 5 ? 1 : 0);
      w.addMessage(bumper, 0, t - 500000, t - 500000, b.bytes());
    }
    CdrOut m;
    m.put<std::uint32_t>(0).put<std::uint32_t>(0);  // no dims, data_offset 0
    m.put<std::uint32_t>(88);
    std::vector<float> values(88);
    for (std::size_t i = 0; i < 88; ++i) {
      values[i] = i < 44 ? static_cast<float>((k + i) % 50) * 0.1F
                         : static_cast<float>(static_cast<int>((k * 3 + i) % 100) - 50) * 0.1F;
      m.put<float>(values[i]);
    }
    w.addMessage(tactile, static_cast<std::uint32_t>(k), t, t, m.bytes());
    bag.tactile.push_back(values);
    bag.times.push_back(t);
  }
  bag.bytes = w.finish();
  return bag;
}

TEST(Ros2Bag, ImportsValuesFromTheMapping) {
  for (const Compression compression : {Compression::Zstd, Compression::None, Compression::Lz4}) {
    const Bag bag = makeBag(60, compression);
    auto mapping = parseMapping(
        R"({"tactile": {"topic": "/tactile", "layout": "normal-then-shear"},
            "pose": {"topic": "/pose"}, "command": {"topic": "/cmd_vel"},
            "blocked": {"topic": "/bumper"}, "scale": 1000})",
        "map.json");
    ASSERT_TRUE(mapping.ok()) << mapping.errorText();
    auto read = readRos2Bag(bag.bytes, "bag.mcap", mapping.value());
    ASSERT_TRUE(read.ok()) << read.errorText();
    const RunData& run = read->run;
    ASSERT_EQ(run.stepCount(), 60U);
    for (std::size_t k = 0; k < 60; ++k) {
      for (int i = 0; i < kSensorCount; ++i) {
        ASSERT_EQ(run.normal(k, i),
                  static_cast<double>(bag.tactile[k][static_cast<std::size_t>(i)]));
        ASSERT_EQ(run.shear(k, i),
                  static_cast<double>(bag.tactile[k][44 + static_cast<std::size_t>(i)]));
      }
      EXPECT_DOUBLE_EQ(run.x[k], 1000.0 * 0.001 * static_cast<double>(k));
      EXPECT_DOUBLE_EQ(run.y[k], 2000.0);
      EXPECT_NEAR(run.theta[k], 0.01 * static_cast<double>(k), 1e-12);
      EXPECT_DOUBLE_EQ(run.v[k], 1000.0 * (0.25 + static_cast<double>(k)));
      EXPECT_EQ(run.omega[k], -0.5);
      EXPECT_EQ(run.blocked[k], k == 5 ? 1 : 0);
    }
    // The median of the jittered periods (20 ms give or take 1.2 ms).
    const std::optional<double> dt = run.dtSeconds();
    ASSERT_TRUE(dt.has_value());
    std::vector<std::uint64_t> periods;
    for (std::size_t k = 1; k < 60; ++k)
      periods.push_back(bag.times[k] - bag.times[k - 1]);
    std::sort(periods.begin(), periods.end());
    EXPECT_DOUBLE_EQ(*dt, 0.5 * static_cast<double>(periods[28] + periods[29]) * 1e-9);
    // The run passes the run-file reader.
    auto csv = parseRunCsv(formatRunCsv(run), "bag.csv");
    EXPECT_TRUE(csv.ok()) << csv.errorText();
  }
}

const char* kFullMapping =
    R"({"tactile": {"topic": "/tactile", "layout": "normal-then-shear"},
        "pose": {"topic": "/pose"}, "command": {"topic": "/cmd_vel"},
        "blocked": {"topic": "/bumper"}, "scale": 1000})";

// Every message the scan hands over, in order: channel, log time and the message bytes.
std::vector<std::string> messagesOf(const std::string& bytes, unsigned threads) {
  std::vector<std::string> seen;
  auto r = scan(
      bytes, "b.mcap",
      [&](const MessageView& m, const Channel& c, const Schema*) {
        seen.push_back(c.topic + " " + std::to_string(m.logTime) + " " + std::string(m.data));
        return Status{};
      },
      threads);
  EXPECT_TRUE(r.ok()) << r.errorText();
  return seen;
}

TEST(Ros2Bag, ChunksReadAheadOnAnotherThreadGiveTheSameRun) {
  auto mapping = parseMapping(kFullMapping, "map.json");
  ASSERT_TRUE(mapping.ok()) << mapping.errorText();
  for (const Compression compression : {Compression::Zstd, Compression::None, Compression::Lz4}) {
    for (const bool summary : {true, false}) {
      SCOPED_TRACE(std::string(compressionName(compression)) + (summary ? "" : ", no summary"));
      // Chunks of 4 KiB: hundreds of them, several batches of the read-ahead.
      const Bag bag = makeBag(1500, compression, summary);
      auto info = scan(bag.bytes, "b.mcap", {}, 1);
      ASSERT_TRUE(info.ok()) << info.errorText();
      ASSERT_GT(info->chunkCount, 150U);
      EXPECT_EQ(messagesOf(bag.bytes, 1), messagesOf(bag.bytes, 2));
      auto one = readRos2Bag(bag.bytes, "b.mcap", mapping.value(), 1);
      auto two = readRos2Bag(bag.bytes, "b.mcap", mapping.value(), 2);
      ASSERT_TRUE(one.ok()) << one.errorText();
      ASSERT_TRUE(two.ok()) << two.errorText();
      ASSERT_EQ(two->run.stepCount(), 1500U);
      EXPECT_EQ(formatRunCsv(one->run), formatRunCsv(two->run));
      EXPECT_EQ(one->warnings, two->warnings);
    }
  }
  // Chunks of 300 KiB: batches of the read-ahead end by their size (a few chunks each).
  const Bag big = makeBag(8000, Compression::Zstd, true, 300 * 1024);
  auto info = scan(big.bytes, "b.mcap", {}, 1);
  ASSERT_TRUE(info.ok()) << info.errorText();
  ASSERT_GT(info->chunkCount, 10U);
  EXPECT_EQ(messagesOf(big.bytes, 1), messagesOf(big.bytes, 2));
  auto one = readRos2Bag(big.bytes, "b.mcap", mapping.value(), 1);
  auto two = readRos2Bag(big.bytes, "b.mcap", mapping.value(), 2);
  ASSERT_TRUE(one.ok() && two.ok());
  EXPECT_EQ(formatRunCsv(one->run), formatRunCsv(two->run));
}

TEST(Ros2Bag, DamagedChunkAmongManyGivesTheSameErrorOnAnyThreadCount) {
  auto mapping = parseMapping(kFullMapping, "map.json");
  ASSERT_TRUE(mapping.ok()) << mapping.errorText();
  for (const Compression compression : {Compression::Zstd, Compression::None, Compression::Lz4}) {
    SCOPED_TRACE(std::string(compressionName(compression)));
    const Bag bag = makeBag(1500, compression);
    auto info = scan(bag.bytes, "b.mcap", {}, 1);
    ASSERT_TRUE(info.ok()) << info.errorText();
    ASSERT_GT(info->chunkIndexes.size(), 150U);
    // A chunk in the middle (past the first batches read ahead): a flipped byte in its records,
    // then a wrong CRC of its records.
    const ChunkIndex& chunk = info->chunkIndexes[info->chunkIndexes.size() / 2 + 3];
    const std::size_t recordsEnd = chunk.chunkStartOffset + chunk.chunkLength;
    const std::size_t crcAt = chunk.chunkStartOffset + 9 + 24;
    for (const std::size_t at : {recordsEnd - 40, crcAt}) {
      std::string damaged = bag.bytes;
      damaged[at] = static_cast<char>(damaged[at] ^ 0x5A);
      auto one = readRos2Bag(damaged, "b.mcap", mapping.value(), 1);
      auto two = readRos2Bag(damaged, "b.mcap", mapping.value(), 2);
      ASSERT_FALSE(one.ok());
      ASSERT_FALSE(two.ok());
      EXPECT_EQ(one.errorText(), two.errorText());
      // Named by the chunk it is in: its offset, or an offset inside it.
      const std::string text = two.errorText();
      ASSERT_EQ(text.rfind("b.mcap: byte ", 0), 0U) << text;
      const std::uint64_t offset = std::stoull(text.substr(13));
      EXPECT_GE(offset, chunk.chunkStartOffset) << text;
      EXPECT_LT(offset, recordsEnd) << text;
    }
  }
}

TEST(Ros2Bag, InterleavedAndIndexLayouts) {
  const Bag bag = makeBag(3, Compression::Zstd);
  auto interleaved =
      parseMapping(R"({"tactile": {"topic": "/tactile", "layout": "interleaved"}})", "m.json");
  ASSERT_TRUE(interleaved.ok());
  // Interleaved reads value 2i as dome i's normal: at step 0 value 44 is -0.6 (written as a
  // shear), a normal out of range, so the first tactile message is refused by its offset.
  auto r = readRos2Bag(bag.bytes, "b.mcap", interleaved.value());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errorText().rfind("b.mcap: byte ", 0), 0U) << r.errorText();
  EXPECT_NE(r.errorText().find("message 0 on /tactile"), std::string::npos) << r.errorText();
  EXPECT_NE(r.errorText().find("dome 22 reads n -0.6"), std::string::npos) << r.errorText();
  nlohmann::json normals = nlohmann::json::array();
  nlohmann::json shears = nlohmann::json::array();
  for (int i = 0; i < 44; ++i) {
    normals.push_back(43 - i);
    shears.push_back(87 - i);
  }
  auto index = parseMapping(
      nlohmann::json{{"tactile", {{"topic", "/tactile"}, {"normals", normals}, {"shears", shears}}}}
          .dump(),
      "m.json");
  ASSERT_TRUE(index.ok()) << index.errorText();
  auto ri = readRos2Bag(bag.bytes, "b.mcap", index.value());
  ASSERT_TRUE(ri.ok()) << ri.errorText();
  EXPECT_EQ(ri->run.normal(1, 0), static_cast<double>(bag.tactile[1][43]));
  EXPECT_EQ(ri->run.shear(2, 10), static_cast<double>(bag.tactile[2][77]));
  EXPECT_EQ(ri->run.x[0], 0.0);  // no pose topic: zeros
}

TEST(Ros2Bag, MappingErrors) {
  EXPECT_NE(parseMapping("{", "m.json").errorText().find("m.json:1: not valid JSON"),
            std::string::npos);
  EXPECT_NE(parseMapping(R"({"tactile": {"topic": "/t"}, "pse": {}})", "m.json")
                .errorText()
                .find("unknown key \"pse\""),
            std::string::npos);
  EXPECT_FALSE(parseMapping(R"({"tactile": {"topic": "/t", "layout": "odd"}})", "m.json").ok());
  EXPECT_FALSE(parseMapping(R"({"tactile": {"topic": "/t"}, "scale": -1})", "m.json").ok());
  EXPECT_FALSE(parseMapping(R"({"pose": {"topic": "/p"}})", "m.json").ok());
  // A topic that is not in the bag: the error lists the bag's topics.
  const Bag bag = makeBag(2, Compression::None);
  auto m = parseMapping(R"({"tactile": {"topic": "/touch"}})", "m.json");
  ASSERT_TRUE(m.ok());
  auto r = readRos2Bag(bag.bytes, "b.mcap", m.value());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find(
                "no messages on the tactile topic /touch (the file's topics: /tactile, /pose"),
            std::string::npos)
      << r.errorText();
}

}  // namespace
}  // namespace tactile::mcap
