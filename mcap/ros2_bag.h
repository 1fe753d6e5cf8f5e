// Import of ROS 2 bags (MCAP, `cdr` messages with `ros2msg` schemas) into a run, by a mapping
// file (docs/interop.md#writing-a-mapping):
//
//   {"tactile": {"topic": "/tactile", "layout": "normal-then-shear"},
//    "pose": {"topic": "/odom"}, "command": {"topic": "/cmd_vel"},
//    "blocked": {"topic": "/bumper"}, "scale": 1000}
//
// One step per message on the tactile topic (std_msgs/msg/Float32MultiArray or
// Float64MultiArray: 88 values, the 44 normals then the 44 shears in the product's dome order,
// or "interleaved" n0, s0, n1, ..., or explicit "normals" and "shears" index lists). Pose
// (nav_msgs/msg/Odometry or geometry_msgs/msg/PoseStamped, or any type with "x", "y" and
// quaternion fields named in the mapping), command (geometry_msgs/msg/Twist or TwistStamped) and
// blocked flag (std_msgs/msg/Bool) are the latest messages on their topics at or before the
// step's log time. dt is the median period of the tactile messages. `scale` multiplies
// positions and linear speed (the bag's units to scene units).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"
#include "mcap/run_mcap.h"
#include "run/sensor_layout.h"

namespace tactile::mcap {

struct BagMapping {
  struct Topic {
    std::string topic;
    // Field paths; empty: chosen from the message type.
    std::vector<std::string> fields;
  };
  Topic tactile;
  // positions in the message's data array of each dome's normal and shear value
  std::array<int, kSensorCount> normals{};
  std::array<int, kSensorCount> shears{};
  std::optional<Topic> pose;     // fields: x, y, and the quaternion's x, y, z, w
  std::optional<Topic> command;  // fields: linear speed, angular speed
  std::optional<Topic> blocked;  // fields: the flag
  double scale = 1.0;
};

// Reads a mapping (JSON text); errors name the file and the key at fault.
Result<BagMapping> parseMapping(std::string_view text, const std::string& fileName);

// Reads a ROS 2 bag into a run (metadata: format, dt, and the source topics). Errors name the
// file and the byte offset of the record at fault. `threads`: as for scan() (1: all on the
// calling thread); the run and any error are the same whatever the number.
Result<McapRun> readRos2Bag(std::string_view bytes, const std::string& fileName,
                            const BagMapping& mapping, unsigned threads = 0);

}  // namespace tactile::mcap
