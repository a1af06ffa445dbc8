// haros_arch stand-in for rosidl_runtime_cpp/traits.hpp: the traits rosidl_generator_cpp
// specialises for each generated interface (its ``detail/*__traits.hpp``), on which code
// chooses overloads (``std::enable_if_t<rosidl_generator_traits::is_message<T>::value>``).
// The synthesised interface headers (``ros2_interfaces.render``) specialise them as the
// generated ones do; the guard is rosidl's own, so the real header and this one are one.
#ifndef ROSIDL_RUNTIME_CPP__TRAITS_HPP_
#define ROSIDL_RUNTIME_CPP__TRAITS_HPP_
#include <string>
#include <type_traits>
namespace rosidl_generator_traits
{
template<typename T> inline const char * data_type();
template<typename T> inline const char * name();
template<typename T> struct has_fixed_size : std::false_type {};
template<typename T> struct has_bounded_size : std::false_type {};
template<typename T> struct is_message : std::false_type {};
template<typename T> struct is_service : std::false_type {};
template<typename T> struct is_service_request : std::false_type {};
template<typename T> struct is_service_response : std::false_type {};
template<typename T> struct is_action : std::false_type {};
template<typename T> struct is_action_goal : std::false_type {};
template<typename T> struct is_action_result : std::false_type {};
template<typename T> struct is_action_feedback : std::false_type {};
}  // namespace rosidl_generator_traits
#endif  // ROSIDL_RUNTIME_CPP__TRAITS_HPP_
