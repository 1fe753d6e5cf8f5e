// ROS 2 message definitions (the `ros2msg` schema encoding: a .msg text followed by the texts of
// the types it uses, each after a line of '=' and a `MSG: pkg/Type` line) and decoding of CDR
// messages (the `cdr` message encoding: XCDR1, or plain XCDR2, little- or big-endian) driven by
// them. Field positions are found by walking the definition, never fixed offsets, so a message of
// any layout is read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"

namespace tactile::mcap::ros2 {

enum class Primitive : std::uint8_t {
  Bool,
  Byte,
  Char,
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Int64,
  UInt64,
  Float32,
  Float64,
  String,
  WString,
  Message,  // a nested message type
};

struct FieldDef {
  std::string name;
  Primitive type = Primitive::Float64;
  int message = -1;  // for Primitive::Message: index into Definitions::types
  enum class Array : std::uint8_t { None, Fixed, Sequence } array = Array::None;
  std::uint32_t length = 0;  // Fixed: the length; Sequence: the bound (0 = none)
};

struct MessageDef {
  std::string name;  // "pkg/Type" (a "pkg/msg/Type" name is stored without "msg/")
  std::vector<FieldDef> fields;
};

struct Definitions {
  std::vector<MessageDef> types;  // types[0] is the schema's own type
};

// "geometry_msgs/msg/Twist" and "geometry_msgs/Twist" both give "geometry_msgs/Twist".
std::string normalizeTypeName(std::string_view name);

// Parses a ros2msg schema. Errors name the schema and the line ("schema std_msgs/msg/Bool, line
// 3: unknown type 'flaot32'"); a type used but not defined in the text is an error, except
// builtin_interfaces/Time and Duration, which are known.
Result<Definitions> parseDefinitions(std::string_view schemaName, std::string_view text);

// Decodes chosen fields of CDR messages of one type. Paths are dotted field names from the root
// ("linear.x", "pose.pose.orientation.w", "data"); a path ends at a number or bool (a scalar) or
// at an array or sequence of them (an array).
class Decoder {
 public:
  // An error names the path and the type that lacks it.
  static Result<Decoder> make(const Definitions& defs, const std::vector<std::string>& paths);

  // Decodes one message: scalars[k] (or arrays[k]) receives path k's value(s); the other slots
  // are left alone. Returns what went wrong, or nullopt.
  std::optional<std::string> decode(std::string_view message, std::vector<double>& scalars,
                                    std::vector<std::vector<double>>& arrays) const;

  bool isArray(std::size_t path) const { return pathIsArray_[path]; }

  struct Action {
    enum class Kind : std::uint8_t { Skip, Scalar, Array, Child } kind = Kind::Skip;
    int slot = -1;   // Scalar / Array: the path's index
    int child = -1;  // Child: index into plans_
  };
  struct Plan {
    int type = 0;
    std::vector<Action> actions;  // one per field
  };

 private:
  Definitions defs_;
  std::vector<Plan> plans_;
  std::vector<bool> pathIsArray_;
};

}  // namespace tactile::mcap::ros2
