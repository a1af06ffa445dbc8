// haros_arch: given to each ROS 2 unit after the precompiled stand-ins (``-include``):
// HAROS_UNIT_ROS names the unit's ROS for the stand-ins whose API differs by ROS in a
// way one declaration cannot serve (message_filters' SubscriberBase).
#ifndef HAROS_UNIT_ROS
#define HAROS_UNIT_ROS 2
#endif
