// haros_arch stand-in: rclcpp::TypeAdapter. A topic of an adapted type carries its ROS
// message type (``ros_message_type``): TypeAdapter<Custom, Ros>, adapt_type<Custom>::as<Ros>,
// or a Custom that RCLCPP_USING_CUSTOM_TYPE_AS_ROS_MESSAGE_TYPE names.
#ifndef HAROS_STANDIN_RCLCPP_TYPE_ADAPTER_HPP
#define HAROS_STANDIN_RCLCPP_TYPE_ADAPTER_HPP
#include <type_traits>
namespace rclcpp {
template<class CustomType, class ROSMessageType = void, class Enable = void>
struct TypeAdapter {
  using is_specialized = std::false_type;
  using custom_type = CustomType;
  using ros_message_type = CustomType;
};
template<class CustomType> struct ImplicitTypeAdapter {
  using is_specialized = std::false_type;
};
template<class T> struct TypeAdapter<T, void,
    std::enable_if_t<ImplicitTypeAdapter<T>::is_specialized::value>>
  : ImplicitTypeAdapter<T> {};
template<class CustomType> struct adapt_type {
  template<class ROSMessageType> using as = TypeAdapter<CustomType, ROSMessageType>;
};
template<class T> struct is_type_adapter : std::false_type {};
template<class... A> struct is_type_adapter<TypeAdapter<A...>> : std::true_type {};
}  // namespace rclcpp
#define RCLCPP_USING_CUSTOM_TYPE_AS_ROS_MESSAGE_TYPE(CustomType, ROSMessageType) \
  template<> struct ::rclcpp::ImplicitTypeAdapter<CustomType> \
    : public ::rclcpp::TypeAdapter<CustomType, ROSMessageType> {}
#endif
