// haros_arch stand-in for roscpp_traits' <ros/message_forward.h>: a message declared ahead
// of its header, with gencpp's pointer typedefs. The synthesised message headers define
// each message as a plain struct of that name (not gencpp's ``Msg_<Allocator>``
// template), so the forward declaration names the struct.
#ifndef HAROS_STANDIN_ROS_MESSAGE_FORWARD_H
#define HAROS_STANDIN_ROS_MESSAGE_FORWARD_H
#include <boost/shared_ptr.hpp>
#define ROS_DECLARE_MESSAGE_WITH_ALLOCATOR(msg, new_name, alloc) \
  struct new_name; \
  typedef boost::shared_ptr<new_name> new_name##Ptr; \
  typedef boost::shared_ptr<new_name const> new_name##ConstPtr;
#define ROS_DECLARE_MESSAGE(msg) ROS_DECLARE_MESSAGE_WITH_ALLOCATOR(msg, msg, std::allocator)
#endif
