// haros_arch: given to each ROS 1 unit after the precompiled stand-ins (``-include``).
// HAROS_UNIT_ROS names the unit's ROS for the stand-ins whose API differs by ROS in a
// way one declaration cannot serve (message_filters' SubscriberBase: a class in ROS 1, a
// template in ROS 2); roscpp's headers bring boost::bind's _1, _2 into the global
// namespace (Boost before 1.73), ROS 2 code has std::placeholders there instead.
#ifndef HAROS_UNIT_ROS
#define HAROS_UNIT_ROS 1
#endif
#include <boost/bind.hpp>
