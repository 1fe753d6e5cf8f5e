// Helpers of the MCAP tests: hand-built CDR messages and ROS 2 schema texts.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace tactile::mcap::test {

// A little-endian XCDR1 message, built field by field with the alignment rules of the format
// (each primitive aligned to its size, counted from the end of the 4-byte header).
class CdrOut {
 public:
  CdrOut() { bytes_ = std::string("\x00\x01\x00\x00", 4); }
  template <class T>
  CdrOut& put(T v) {
    align(sizeof(T));
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    bytes_.append(b, sizeof(T));
    return *this;
  }
  CdrOut& str(std::string_view s) {
    put<std::uint32_t>(static_cast<std::uint32_t>(s.size() + 1));
    bytes_.append(s);
    bytes_.push_back('\0');
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void align(std::size_t n) {
    while ((bytes_.size() - 4) % n != 0)
      bytes_.push_back('\0');
  }
  std::string bytes_;
};

inline constexpr std::string_view kSeparator =
    "================================================================================\n";

inline std::string twistSchema() {
  return "# A comment\ngeometry_msgs/Vector3  linear\ngeometry_msgs/Vector3  angular\n" +
         std::string(kSeparator) +
         "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z # metres\n";
}

inline std::string float32ArraySchema() {
  return "MultiArrayLayout  layout\nfloat32[]         data\n" + std::string(kSeparator) +
         "MSG: std_msgs/MultiArrayLayout\nMultiArrayDimension[] dim\nuint32 data_offset\n" +
         std::string(kSeparator) +
         "MSG: std_msgs/MultiArrayDimension\nstring label\nuint32 size\nuint32 stride\n";
}

inline std::string poseStampedSchema() {
  return "std_msgs/Header header\nPose pose\n" + std::string(kSeparator) +
         "MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n" +
         std::string(kSeparator) +
         "MSG: geometry_msgs/Pose\nPoint position\nQuaternion orientation\n" +
         std::string(kSeparator) + "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n" +
         std::string(kSeparator) +
         "MSG: geometry_msgs/Quaternion\nfloat64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n";
}

inline std::string boolSchema() {
  return "bool data\nint32 CONSTANT=3 # a constant\n";
}

}  // namespace tactile::mcap::test
