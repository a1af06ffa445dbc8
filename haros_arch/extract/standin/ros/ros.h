// haros_arch stand-in: the umbrella header of roscpp
#ifndef HAROS_STANDIN_ROS_ROS_H
#define HAROS_STANDIN_ROS_ROS_H
#include <ros/forwards.h>
#include <ros/message_traits.h>  // and serialization, message_operations
#include <ros/common.h>
#include <ros/time.h>
#include <ros/console.h>
#include <ros/init.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/timer.h>
#include <ros/node_handle.h>
#include <ros/param.h>
#include <ros/service.h>
#include <ros/topic.h>
#include <ros/callback_queue.h>
#include <ros/master.h>
#endif
