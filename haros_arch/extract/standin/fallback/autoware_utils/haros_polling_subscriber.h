// haros_arch stand-in: Autoware's polling subscriber (autoware_utils and
// autoware_utils_rclcpp spell the same class), for workspaces that have the library
// installed, not as sources: declarations only. Building one (or its static
// create_subscription) subscribes the node to the topic (an API row of the extractor).
// The node is any pointer (the library takes an rclcpp::Node *): a node class that the
// first parse of a unit finds invalid must not make the subscriber's construction an
// error, whose name would then be declared permissively over this class.
#ifndef HAROS_STANDIN_AUTOWARE_POLLING_SUBSCRIBER_H
#define HAROS_STANDIN_AUTOWARE_POLLING_SUBSCRIBER_H
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#define HAROS_AUTOWARE_POLLING_SUBSCRIBER                                                   \
  namespace polling_policy {                                                                \
  template<class MessageT> class Latest {                                                   \
   public: typename MessageT::ConstSharedPtr take_data(); };                                \
  template<class MessageT> class Newest {                                                   \
   public: typename MessageT::ConstSharedPtr take_data(); };                                \
  template<class MessageT> class All {                                                      \
   public: std::vector<typename MessageT::ConstSharedPtr> take_data(); };                   \
  }                                                                                         \
  template<class MessageT, template<class> class PollingPolicy = polling_policy::Latest>   \
  class InterProcessPollingSubscriber : public PollingPolicy<MessageT> {                    \
   public:                                                                                  \
    using SharedPtr = std::shared_ptr<InterProcessPollingSubscriber<MessageT, PollingPolicy>>; \
    template<class NodeT>                                                                   \
    explicit InterProcessPollingSubscriber(NodeT* node, const std::string& topic_name,      \
                                           const rclcpp::QoS& qos = rclcpp::QoS(1));        \
    template<class NodeT>                                                                   \
    static SharedPtr create_subscription(NodeT* node, const std::string& topic_name,        \
                                         const rclcpp::QoS& qos = rclcpp::QoS(1));          \
  };
namespace autoware_utils { HAROS_AUTOWARE_POLLING_SUBSCRIBER }
namespace autoware_utils_rclcpp { HAROS_AUTOWARE_POLLING_SUBSCRIBER }
#undef HAROS_AUTOWARE_POLLING_SUBSCRIBER
#endif
