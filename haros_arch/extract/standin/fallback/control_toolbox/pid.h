// haros_arch stand-in: ROS 1 control_toolbox's PID controller (declarations only), for a
// workspace that has control_toolbox installed, not as sources (cob_frame_tracker's
// trackers, the effort and velocity controllers of ros_controllers). What its
// initialisers read and serve on the handle given is in the API rows
// (extract/cpp/api.py, CONTROL_TOOLBOX); computing a command makes no ROS call.
#ifndef HAROS_STANDIN_CONTROL_TOOLBOX_PID_H
#define HAROS_STANDIN_CONTROL_TOOLBOX_PID_H
#include <string>
#include <ros/ros.h>

class TiXmlElement;

namespace control_toolbox {

class Pid {
 public:
  struct Gains {
    Gains();
    Gains(double p, double i, double d, double i_max, double i_min);
    Gains(double p, double i, double d, double i_max, double i_min, bool antiwindup);
    double p_gain_;
    double i_gain_;
    double d_gain_;
    double i_max_;
    double i_min_;
    bool antiwindup_;
  };

  Pid(double p = 0.0, double i = 0.0, double d = 0.0, double i_max = 0.0,
      double i_min = -0.0, bool antiwindup = false);
  Pid(const Pid &source);
  ~Pid();
  Pid &operator=(const Pid &source);

  // gains given: no ROS call; the overloads that take a handle (which they ignore)
  // also start the gains' reconfigure server under the node's ``pid`` namespace
  void initPid(double p, double i, double d, double i_max, double i_min,
               bool antiwindup = false);
  void initPid(double p, double i, double d, double i_max, double i_min,
               const ros::NodeHandle &node);
  void initPid(double p, double i, double d, double i_max, double i_min, bool antiwindup,
               const ros::NodeHandle &node);
  // the gains read from the handle's namespace (or the namespace named), and the
  // reconfigure server started there
  bool initParam(const std::string &prefix, const bool quiet = false);
  bool init(const ros::NodeHandle &n, const bool quiet = false);
  bool initXml(TiXmlElement *config);
  void initDynamicReconfig(ros::NodeHandle &node);

  void reset();
  void reset(double d_error, double i_error);
  void getGains(double &p, double &i, double &d, double &i_max, double &i_min);
  void getGains(double &p, double &i, double &d, double &i_max, double &i_min,
                bool &antiwindup);
  Gains getGains();
  void setGains(double p, double i, double d, double i_max, double i_min,
                bool antiwindup = false);
  void setGains(const Gains &gains);
  void updateDynamicReconfig();
  void updateDynamicReconfig(Gains gains_config);
  double computeCommand(double error, ros::Duration dt);
  double computeCommand(double error, double error_dot, ros::Duration dt);
  double updatePid(double p_error, ros::Duration dt);
  double updatePid(double error, double error_dot, ros::Duration dt);
  void setCurrentCmd(double cmd);
  double getCurrentCmd();
  void getCurrentPIDErrors(double *pe, double *ie, double *de);
  void printValues();
};

}  // namespace control_toolbox
#endif
