// haros_arch stand-in: ros::init and the node's life cycle
#ifndef HAROS_STANDIN_ROS_INIT_H
#define HAROS_STANDIN_ROS_INIT_H
#include <ros/forwards.h>
namespace ros {
namespace init_options {
enum InitOption { NoSigintHandler = 1, AnonymousName = 2, NoRosout = 4 };
}
typedef init_options::InitOption InitOption;
void init(int& argc, char** argv, const std::string& name, uint32_t options = 0);
void init(const M_string& remappings, const std::string& name, uint32_t options = 0);
std::string getROSArg(int argc, const char* const* argv, const std::string& arg);
void removeROSArgs(int argc, const char* const* argv, V_string& args_out);
bool ok();
void shutdown();
void requestShutdown();
bool isInitialized();
bool isStarted();
bool isShuttingDown();
void spin();
void spinOnce();
void waitForShutdown();
void start();
class CallbackQueue;
CallbackQueue* getGlobalCallbackQueue();
namespace this_node {
const std::string& getName();
const std::string& getNamespace();
void getAdvertisedTopics(V_string& topics);
void getSubscribedTopics(V_string& topics);
}
namespace names {
std::string resolve(const std::string& name, bool remap = true);
std::string append(const std::string& left, const std::string& right);
std::string clean(const std::string& name);
std::string parentNamespace(const std::string& name);
const M_string& getRemappings();
const M_string& getUnresolvedRemappings();
}
class AsyncSpinner {
public:
  explicit AsyncSpinner(uint32_t thread_count);
  AsyncSpinner(uint32_t thread_count, CallbackQueue* queue);  // a queue of its own
  bool canStart();
  void start();
  void stop();
};
class MultiThreadedSpinner {
public:
  explicit MultiThreadedSpinner(uint32_t thread_count = 0);
  void spin(CallbackQueueInterface* queue = 0);
};
void spin(MultiThreadedSpinner& spinner);
}  // namespace ros
#endif
