// haros_arch stand-in: ros::master (roscpp's master.h): questions to the ROS master
// about the graph at run time (topics advertised, nodes, its address). They name no
// topic, service or parameter of the node: no call is made of them.
#ifndef HAROS_STANDIN_ROS_MASTER_H
#define HAROS_STANDIN_ROS_MASTER_H
#include <ros/forwards.h>
#include <ros/time.h>
namespace ros {
namespace master {
struct TopicInfo {
  TopicInfo();
  TopicInfo(const std::string& name, const std::string& datatype);
  std::string name;
  std::string datatype;
};
typedef std::vector<TopicInfo> V_TopicInfo;
bool execute(const std::string& method, const XmlRpc::XmlRpcValue& request,
             XmlRpc::XmlRpcValue& response, XmlRpc::XmlRpcValue& payload,
             bool wait_for_master);
const std::string& getHost();
uint32_t getPort();
const std::string& getURI();
bool check();
bool getTopics(V_TopicInfo& topics);
bool getNodes(V_string& nodes);
void setRetryTimeout(ros::WallDuration timeout);
}  // namespace master
}  // namespace ros
#endif
