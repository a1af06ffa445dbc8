// haros_arch stand-in: ROS 1 navigation's plugin interfaces, nav_core (declarations only;
// every nav_core/... header stands in as this one, read only when the workspace has no
// nav_core package, headers.FALLBACK_UMBRELLAS), as of noetic (tf2). The interfaces make
// no ROS call: a planner's or recovery's calls are its own, in its initialize(name, ...),
// which move_base calls with the plugin's name. parameter_magic.h's functions read
// parameters from the handle they are given and are not declared here: the parse declares
// them permissively and a node that gives them its handle is partial
// (CPP_NODE_TO_UNKNOWN).
#ifndef HAROS_STANDIN_NAV_CORE_H
#define HAROS_STANDIN_NAV_CORE_H
#include <string>
#include <vector>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <costmap_2d/costmap_2d_ros.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>

namespace nav_core {

class BaseGlobalPlanner {
public:
  virtual bool makePlan(const geometry_msgs::PoseStamped& start,
                        const geometry_msgs::PoseStamped& goal,
                        std::vector<geometry_msgs::PoseStamped>& plan) = 0;
  virtual bool makePlan(const geometry_msgs::PoseStamped& start,
                        const geometry_msgs::PoseStamped& goal,
                        std::vector<geometry_msgs::PoseStamped>& plan, double& cost);
  virtual void initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) = 0;
  virtual ~BaseGlobalPlanner();
protected:
  BaseGlobalPlanner();
};

class BaseLocalPlanner {
public:
  virtual bool computeVelocityCommands(geometry_msgs::Twist& cmd_vel) = 0;
  virtual bool isGoalReached() = 0;
  virtual bool setPlan(const std::vector<geometry_msgs::PoseStamped>& plan) = 0;
  virtual void initialize(std::string name, tf2_ros::Buffer* tf,
                          costmap_2d::Costmap2DROS* costmap_ros) = 0;
  virtual ~BaseLocalPlanner();
protected:
  BaseLocalPlanner();
};

class RecoveryBehavior {
public:
  virtual void initialize(std::string name, tf2_ros::Buffer* tf,
                          costmap_2d::Costmap2DROS* global_costmap,
                          costmap_2d::Costmap2DROS* local_costmap) = 0;
  virtual void runBehavior() = 0;
  virtual ~RecoveryBehavior();
protected:
  RecoveryBehavior();
};

}  // namespace nav_core
#endif
