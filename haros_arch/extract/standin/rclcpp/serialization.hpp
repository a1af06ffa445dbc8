// haros_arch stand-in: rclcpp::Serialization (declarations only)
#ifndef HAROS_STANDIN_RCLCPP_SERIALIZATION_HPP
#define HAROS_STANDIN_RCLCPP_SERIALIZATION_HPP
#include <rclcpp/serialized_message.hpp>
namespace rclcpp {
class SerializationBase {
public:
  void serialize_message(const void* ros_message, SerializedMessage* serialized_message) const;
  void deserialize_message(const SerializedMessage* serialized_message, void* ros_message) const;
};
template<class M> class Serialization : public SerializationBase {
public:
  Serialization();
};
}  // namespace rclcpp
#endif
