// haros_arch stand-in: rclcpp::SerializedMessage (declarations only)
#ifndef HAROS_STANDIN_RCLCPP_SERIALIZED_MESSAGE_HPP
#define HAROS_STANDIN_RCLCPP_SERIALIZED_MESSAGE_HPP
#include <cstddef>
#include <cstdint>
#include <memory>
typedef struct rcutils_uint8_array_s {
  uint8_t* buffer; size_t buffer_length; size_t buffer_capacity;
} rcutils_uint8_array_t;
typedef rcutils_uint8_array_t rmw_serialized_message_t;
typedef rcutils_uint8_array_t rcl_serialized_message_t;
namespace rclcpp {
class SerializedMessage {
public:
  SerializedMessage();
  explicit SerializedMessage(size_t initial_capacity);
  SerializedMessage(const SerializedMessage& other);
  explicit SerializedMessage(const rcl_serialized_message_t& other);
  SerializedMessage& operator=(const SerializedMessage& other);
  rcl_serialized_message_t& get_rcl_serialized_message();
  const rcl_serialized_message_t& get_rcl_serialized_message() const;
  size_t size() const;
  size_t capacity() const;
  void reserve(size_t capacity);
  rcl_serialized_message_t release_rcl_serialized_message();
};
}  // namespace rclcpp
#endif
