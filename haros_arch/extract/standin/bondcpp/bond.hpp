// haros_arch stand-in: bondcpp's bond::Bond (declarations only)
#ifndef HAROS_STANDIN_BONDCPP_BOND_HPP
#define HAROS_STANDIN_BONDCPP_BOND_HPP
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
namespace bond {
class Bond {
public:
  template<class NodeT>
  Bond(const std::string& topic, const std::string& id, NodeT node,
       std::function<void()> on_broken = std::function<void()>(),
       std::function<void()> on_formed = std::function<void()>());
  // ROS 1 (bondcpp/bond.h): the bond's topic on the global node handle
  Bond(const std::string& topic, const std::string& id,
       std::function<void()> on_broken = std::function<void()>(),
       std::function<void()> on_formed = std::function<void()>());
  ~Bond();
  void setHeartbeatPeriod(double dur);
  void setHeartbeatTimeout(double dur);
  void setConnectTimeout(double dur);
  void setDisconnectTimeout(double dur);
  // ROS 2 (bondcpp/bond.hpp): the callbacks set after construction, the timeouts read
  void setDeadPublishPeriod(double dur);
  double getConnectTimeout() const;
  double getDisconnectTimeout() const;
  double getHeartbeatTimeout() const;
  double getHeartbeatPeriod() const;
  double getDeadPublishPeriod() const;
  void setFormedCallback(std::function<void()> on_formed);
  void setBrokenCallback(std::function<void()> on_broken);
  std::string getTopic() const;
  std::string getId() const;
  std::string getInstanceId() const;
  void start();
  void breakBond();
  bool isBroken();
  bool waitUntilFormed(rclcpp::Duration timeout = rclcpp::Duration(-1, 0));
  bool waitUntilBroken(rclcpp::Duration timeout = rclcpp::Duration(-1, 0));
};
}  // namespace bond
#endif
