// haros_arch stand-in: roscpp's message traits, serialization and printing
// (ros/message_traits.h, ros/builtin_message_traits.h, ros/serialization.h,
// ros/message_operations.h, which roscpp's own headers reach). A message header that
// gencpp generated and a package keeps in its source (robocup_catkin_ws_2024's
// serial_mcu/Motor_msg.h) specialises these templates for its ``Name_<Allocator>``
// struct; without them each specialisation was an error and a class holding such a
// message was invalid, every call on it an error near the node's ROS calls.
#ifndef HAROS_STANDIN_ROS_MESSAGE_TRAITS_H
#define HAROS_STANDIN_ROS_MESSAGE_TRAITS_H
#include <stdint.h>
#include <string>
namespace ros {
namespace message_traits {
struct TrueType { static const bool value = true; typedef TrueType type; };
struct FalseType { static const bool value = false; typedef FalseType type; };
template<typename M> struct IsSimple : public FalseType {};
template<typename M> struct IsFixedSize : public FalseType {};
template<typename M> struct IsMessage : public FalseType {};
template<typename M> struct HasHeader : public FalseType {};
template<typename M> struct MD5Sum {
  static const char* value();
  static const char* value(const M& m);
};
template<typename M> struct DataType {
  static const char* value();
  static const char* value(const M& m);
};
template<typename M> struct Definition {
  static const char* value();
  static const char* value(const M& m);
};
template<typename M> const char* md5sum();
template<typename M> const char* md5sum(const M& m);
template<typename M> const char* datatype();
template<typename M> const char* datatype(const M& m);
template<typename M> const char* definition();
template<typename M> const char* definition(const M& m);
}  // namespace message_traits
namespace serialization {
struct Stream {
  uint8_t* getData();
  uint8_t* advance(uint32_t len);
  uint32_t getLength();
};
struct IStream : public Stream {
  IStream(uint8_t* data, uint32_t count);
  template<typename T> void next(T& t);
  template<typename T> IStream& operator>>(T& t);
};
struct OStream : public Stream {
  OStream(uint8_t* data, uint32_t count);
  template<typename T> void next(const T& t);
  template<typename T> OStream& operator<<(const T& t);
};
struct LStream {
  template<typename T> void next(const T& t);
  uint32_t advance(uint32_t len);
  uint32_t getLength();
};
template<typename T> struct Serializer {
  template<typename S> static void write(S& stream, const T& t);
  template<typename S> static void read(S& stream, T& t);
  static uint32_t serializedLength(const T& t);
};
template<typename T, typename S> void serialize(S& stream, const T& t);
template<typename T, typename S> void deserialize(S& stream, T& t);
template<typename T> uint32_t serializationLength(const T& t);
}  // namespace serialization
namespace message_operations {
template<typename M> struct Printer {
  template<typename S> static void stream(S& s, const std::string& indent, const M& value);
};
}  // namespace message_operations
}  // namespace ros
// what a generated Serializer specialisation declares beside its allInOne
#define ROS_DECLARE_ALLINONE_SERIALIZER \
  template<typename Stream, typename T> inline static void write(Stream& stream, const T& t) \
  { allInOne<Stream, const T&>(stream, t); } \
  template<typename Stream, typename T> inline static void read(Stream& stream, T& t) \
  { allInOne<Stream, T&>(stream, t); } \
  template<typename T> inline static uint32_t serializedLength(const T& t) \
  { ::ros::serialization::LStream stream; allInOne< ::ros::serialization::LStream, \
      const T&>(stream, t); return stream.getLength(); }
#endif
