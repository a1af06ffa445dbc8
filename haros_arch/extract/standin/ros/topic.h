// haros_arch stand-in: ros::topic
#ifndef HAROS_STANDIN_ROS_TOPIC_H
#define HAROS_STANDIN_ROS_TOPIC_H
#include <ros/forwards.h>
#include <ros/time.h>
namespace ros { namespace topic {
template<class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic, NodeHandle& nh);
template<class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic, NodeHandle& nh,
                                          Duration timeout);
template<class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic);
template<class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic, Duration timeout);
} }  // namespace ros::topic
#endif
