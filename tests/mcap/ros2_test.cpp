// ROS 2 message definitions and CDR decoding against hand-built messages (the bytes written out
// field by field from the CDR rules, not by the code under test).
#include <gtest/gtest.h>

#include "mcap/ros2msg.h"
#include "tests/mcap/mcap_test_util.h"

namespace tactile::mcap::ros2 {
namespace {

using test::CdrOut;

TEST(Ros2Msg, ParsesDefinitionsWithDependencies) {
  auto defs = parseDefinitions("geometry_msgs/msg/PoseStamped", test::poseStampedSchema());
  ASSERT_TRUE(defs.ok()) << defs.errorText();
  EXPECT_EQ(defs->types[0].name, "geometry_msgs/PoseStamped");
  ASSERT_EQ(defs->types[0].fields.size(), 2U);
  const FieldDef& header = defs->types[0].fields[0];
  EXPECT_EQ(header.type, Primitive::Message);
  EXPECT_EQ(defs->types[static_cast<std::size_t>(header.message)].name, "std_msgs/Header");
  // Time is known without a MSG: section.
  const auto& headerDef = defs->types[static_cast<std::size_t>(header.message)];
  EXPECT_EQ(defs->types[static_cast<std::size_t>(headerDef.fields[0].message)].name,
            "builtin_interfaces/Time");
  // Constants are not fields; default values are ignored.
  auto b = parseDefinitions("std_msgs/msg/Bool", test::boolSchema());
  ASSERT_TRUE(b.ok());
  ASSERT_EQ(b->types[0].fields.size(), 1U);
  EXPECT_EQ(b->types[0].fields[0].type, Primitive::Bool);
}

TEST(Ros2Msg, ArraysAndBounds) {
  auto d = parseDefinitions("p/msg/T",
                            "float32[3] a\nint16[] b\nuint8[<=4] c\nstring<=8 d\n"
                            "string<=8[2] e\n");
  ASSERT_TRUE(d.ok()) << d.errorText();
  const auto& f = d->types[0].fields;
  EXPECT_EQ(f[0].array, FieldDef::Array::Fixed);
  EXPECT_EQ(f[0].length, 3U);
  EXPECT_EQ(f[1].array, FieldDef::Array::Sequence);
  EXPECT_EQ(f[2].array, FieldDef::Array::Sequence);
  EXPECT_EQ(f[2].length, 4U);
  EXPECT_EQ(f[3].type, Primitive::String);
  EXPECT_EQ(f[4].array, FieldDef::Array::Fixed);
}

TEST(Ros2Msg, ErrorsNameTheSchemaAndLine) {
  auto missing = parseDefinitions("a/msg/B", "float64 x\nc/Thing t\n");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.errorText().find("schema a/msg/B, line 2: type 'c/Thing'"), std::string::npos)
      << missing.errorText();
  auto self = parseDefinitions("a/msg/B", "B inner\n");
  ASSERT_FALSE(self.ok());
  EXPECT_NE(self.errorText().find("contains itself"), std::string::npos);
  auto bad = parseDefinitions("a/msg/B", "float64[x] v\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.errorText().find("line 1"), std::string::npos);
}

TEST(Ros2Cdr, DecodesPoseStampedFieldsByPath) {
  auto defs = parseDefinitions("geometry_msgs/msg/PoseStamped", test::poseStampedSchema());
  ASSERT_TRUE(defs.ok());
  auto dec =
      Decoder::make(defs.value(), {"pose.position.x", "pose.position.y", "pose.orientation.z",
                                   "pose.orientation.w", "header.stamp.nanosec"});
  ASSERT_TRUE(dec.ok()) << dec.errorText();
  CdrOut m;
  m.put<std::int32_t>(12).put<std::uint32_t>(345).str("map");  // header: stamp, frame_id
  // pose.position (float64, aligned to 8 after the 4+4+4+4 = 16 bytes... padded by CdrOut)
  m.put<double>(1.5).put<double>(-2.25).put<double>(0.0);
  m.put<double>(0.0).put<double>(0.0).put<double>(0.6).put<double>(0.8);
  std::vector<double> scalars;
  std::vector<std::vector<double>> arrays;
  ASSERT_EQ(dec->decode(m.bytes(), scalars, arrays), std::nullopt);
  EXPECT_EQ(scalars[0], 1.5);
  EXPECT_EQ(scalars[1], -2.25);
  EXPECT_EQ(scalars[2], 0.6);
  EXPECT_EQ(scalars[3], 0.8);
  EXPECT_EQ(scalars[4], 345.0);
  // Cut short: an error naming where it ends, no crash.
  for (std::size_t n = 0; n < m.bytes().size(); n += 3) {
    EXPECT_NE(dec->decode(m.bytes().substr(0, n), scalars, arrays), std::nullopt) << n;
  }
}

TEST(Ros2Cdr, Float32MultiArrayAndBigEndian) {
  auto defs = parseDefinitions("std_msgs/msg/Float32MultiArray", test::float32ArraySchema());
  ASSERT_TRUE(defs.ok()) << defs.errorText();
  auto dec = Decoder::make(defs.value(), {"data", "layout.data_offset"});
  ASSERT_TRUE(dec.ok()) << dec.errorText();
  EXPECT_TRUE(dec->isArray(0));
  CdrOut m;
  m.put<std::uint32_t>(1).str("domes").put<std::uint32_t>(3).put<std::uint32_t>(3);  // one dim
  m.put<std::uint32_t>(7);                                                           // data_offset
  m.put<std::uint32_t>(3).put<float>(0.5F).put<float>(-1.25F).put<float>(4.0F);
  std::vector<double> scalars;
  std::vector<std::vector<double>> arrays;
  ASSERT_EQ(dec->decode(m.bytes(), scalars, arrays), std::nullopt);
  EXPECT_EQ(arrays[0], (std::vector<double>{0.5, -1.25, 4.0}));
  EXPECT_EQ(scalars[1], 7.0);

  // The same message big-endian: header 00 00, every multi-byte value swapped.
  std::string be = m.bytes();
  be[1] = 0x00;
  auto swap4 = [&](std::size_t at) {
    std::swap(be[at], be[at + 3]), std::swap(be[at + 1], be[at + 2]);
  };
  for (std::size_t at : {4U, 8U, 20U, 24U, 28U, 32U, 36U, 40U, 44U})
    swap4(at);
  ASSERT_EQ(dec->decode(be, scalars, arrays), std::nullopt);
  EXPECT_EQ(arrays[0], (std::vector<double>{0.5, -1.25, 4.0}));

  // A sequence count far past the message: refused without allocating.
  std::string huge = m.bytes();
  huge[4] = huge[5] = huge[6] = static_cast<char>(0xFF);
  auto problem = dec->decode(huge, scalars, arrays);
  ASSERT_NE(problem, std::nullopt);
  EXPECT_NE(problem->find("runs past the end of the message"), std::string::npos) << *problem;
  // An unknown representation is named.
  std::string odd = m.bytes();
  odd[1] = 0x0B;
  problem = dec->decode(odd, scalars, arrays);
  ASSERT_NE(problem, std::nullopt);
  EXPECT_NE(problem->find("unsupported CDR representation 0x000B"), std::string::npos);
}

TEST(Ros2Cdr, PathErrors) {
  auto defs = parseDefinitions("geometry_msgs/msg/Twist", test::twistSchema());
  ASSERT_TRUE(defs.ok());
  EXPECT_FALSE(Decoder::make(defs.value(), {"linear.w"}).ok());
  EXPECT_FALSE(Decoder::make(defs.value(), {"linear"}).ok());
  EXPECT_TRUE(Decoder::make(defs.value(), {"linear.x", "angular.z"}).ok());
}

}  // namespace
}  // namespace tactile::mcap::ros2
