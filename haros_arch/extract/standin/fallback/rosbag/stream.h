// haros_arch stand-in: ROS 1 rosbag_storage's compression types (``rosbag/stream.h``),
// for a workspace that has rosbag installed, not as sources: a recorder's options hold
// a ``rosbag::compression::CompressionType``. The streams themselves are not declared.
#ifndef HAROS_STANDIN_ROSBAG_STREAM_H
#define HAROS_STANDIN_ROSBAG_STREAM_H
namespace rosbag {
namespace compression {
enum CompressionType { Uncompressed = 0, BZ2 = 1, LZ4 = 2 };
}  // namespace compression
typedef compression::CompressionType CompressionType;
}  // namespace rosbag
#endif  // HAROS_STANDIN_ROSBAG_STREAM_H
