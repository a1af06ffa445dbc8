// haros_arch stand-in: ROS 1 gazebo_plugins' GazeboRos helper (noetic-devel
// gazebo_plugins/gazebo_ros_utils.h), which Gazebo classic plugins of other packages build
// on (a diff drive, a fork lifter: ``GazeboRosPtr(new GazeboRos(parent, sdf, "Name"))``).
// Read only when the workspace has no such header (headers.FALLBACK). What it does that
// the graph sees, written as the library does it: the handle ``node()`` gives is
// ``new ros::NodeHandle(ns)``, ``ns`` the <plugin> element's <robotNamespace> (the model's
// name where that is absent or empty, which the description's host gives); getParameter
// and getParameterBoolean set the value to the element's child of that tag (api.SDF rows,
// the default where absent). Left out, as the table rows of gazebo_plugins' own plugins
// built on it leave it out (robot.gazebo_plugins): the constructor's search of the
// tf_prefix parameter from that handle (gazebo_ros_utils.cpp's readCommonParameter).
// Gazebo's own types (the parent model or sensor, a joint)
// are left to the parse, as the Gazebo stand-in leaves them: templates here.
#ifndef HAROS_STANDIN_GAZEBO_ROS_UTILS_H
#define HAROS_STANDIN_GAZEBO_ROS_UTILS_H
#include <map>
#include <string>
#include <boost/shared_ptr.hpp>
#include <ros/ros.h>
#include <gazebo/gazebo.hh>
#include <sdf/sdf.hh>

#ifndef GAZEBO_SENSORS_USING_DYNAMIC_POINTER_CAST
#define GAZEBO_SENSORS_USING_DYNAMIC_POINTER_CAST using std::dynamic_pointer_cast
#endif

namespace gazebo
{
template <class S> std::string GetModelName(const S &parent);
template <class S> std::string GetRobotNamespace(const S &parent, const sdf::ElementPtr &sdf,
                                                 const char *pInfo = NULL)
{
  return sdf->Get<std::string>("robotNamespace");
}

class GazeboRos
{
private:
  sdf::ElementPtr sdf_;
  std::string plugin_;
  std::string namespace_;
  boost::shared_ptr<ros::NodeHandle> rosnode_;
  std::string tf_prefix_;
  std::string info_text;

public:
  // (physics::ModelPtr &, ...) and (sensors::SensorPtr, ...)
  template <class P> GazeboRos(P _parent, sdf::ElementPtr _sdf, const std::string &_plugin)
    : sdf_(_sdf), plugin_(_plugin)
  {
    namespace_ = _sdf->Get<std::string>("robotNamespace");
    rosnode_ = boost::shared_ptr<ros::NodeHandle>(new ros::NodeHandle(namespace_));
  }
  const char *info() const;
  boost::shared_ptr<ros::NodeHandle> &node() { return rosnode_; }
  const boost::shared_ptr<ros::NodeHandle> &node() const { return rosnode_; }
  std::string resolveTF(const std::string &_name);
  void getParameterBoolean(bool &_value, const char *_tag_name, const bool &_default);
  void getParameterBoolean(bool &_value, const char *_tag_name);
  // a physics::JointPtr, a type the parse declares: what converts to it
  struct Joint
  {
    template <class J> operator J() const;
  };
  template <class P> Joint getJoint(const P &_parent, const char *_tag_name,
                                    const std::string &_joint_default_name);
  void isInitialized();
  template <class T> void getParameter(T &_value, const char *_tag_name, const T &_default);
  template <class T> void getParameter(T &_value, const char *_tag_name);
  template <class T> void getParameter(T &_value, const char *_tag_name,
                                       const std::map<std::string, T> &_options,
                                       const T &_default);
};
typedef boost::shared_ptr<GazeboRos> GazeboRosPtr;
}  // namespace gazebo
#endif
