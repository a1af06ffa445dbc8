// haros_arch stand-in: rpg_vikit's parameter helpers (vikit_ros' params_helper.h,
// declarations only; every vikit/... header stands in as this one, read only when the
// workspace has no vikit package, headers.FALLBACK_UMBRELLAS), for uzh-rpg's SVO and the
// like: ``vk::getParam<T>(name, default)`` reads ``name`` through ros::param (in the
// node's namespace) with that default, ``vk::getParam<T>(name)`` without one, and
// ``vk::hasParam(name)`` asks whether it is set (API rows, api.VIKIT). vikit's camera
// models, maths and timers are left to the parse's permissive declarations.
#ifndef HAROS_STANDIN_VIKIT_H
#define HAROS_STANDIN_VIKIT_H
#include <string>
#include <ros/ros.h>

namespace vk {
bool hasParam(const std::string& name);
template<typename T> T getParam(const std::string& name, const T& defaultValue);
template<typename T> T getParam(const std::string& name);
}  // namespace vk
#endif
