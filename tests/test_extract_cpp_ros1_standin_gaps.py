"""ROS 1 forms of neonavigation (noetic) that the stand-in headers did not parse:
``tf2::Stamped<tf2::Transform>`` stamped with a ``ros::Time`` (the precompiled stand-ins
include rclcpp in every unit, which made every stamp ROS 2's ``TimePoint``), ``ros::Timer::
isValid()``, a ``boost::function`` tested as a bool, and xmlrpcpp's own headers
(``<xmlrpcpp/XmlRpcValue.h>`` was synthesised as a message without fields, and
``XmlRpc::XmlRpcException`` was not declared); and boost's ``lexical_cast``, which
gazebo_plugins' ``getParameter`` (gazebo_ros_utils.h) uses beside a ROS call: every plugin
of gazebo_plugins was partial for it. Each left a C++ error in a function that calls the
ROS API."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = r"""
#include <ros/ros.h>
#include <boost/function.hpp>
#include <nav_msgs/Odometry.h>
#include <std_msgs/Float32.h>
#include <tf2/utils.h>
#include <tf2_ros/transform_listener.h>
#include <xmlrpcpp/XmlRpcValue.h>
#include <xmlrpcpp/XmlRpcException.h>
#include <string>

class Tracker
{
public:
  Tracker() : pnh_("~")
  {
    sub_ = nh_.subscribe("odom", 10, &Tracker::cbOdometry, this);
    XmlRpc::XmlRpcValue footprint;
    pnh_.getParam("footprint", footprint);
    try
    {
      radius_ = static_cast<double>(footprint[0][0]);
    }
    catch (XmlRpc::XmlRpcException& e)
    {
      ROS_ERROR("%s", e.getMessage().c_str());
    }
  }
  void cbOdometry(const nav_msgs::Odometry::ConstPtr& odom)
  {
    if (timer_.isValid())
      timer_.setPeriod(ros::Duration(0.1), true);
    tf2::Transform robot;
    const tf2::Stamped<tf2::Transform> stamped(robot, odom->header.stamp,
                                               odom->header.frame_id);
    const double age = (ros::Time::now() - stamped.stamp_).toSec();
    if (check_ && age > 0.1)
      pub_ = nh_.advertise<std_msgs::Float32>("delay", 1);
  }

  ros::NodeHandle nh_, pnh_;
  ros::Subscriber sub_;
  ros::Publisher pub_;
  ros::Timer timer_;
  boost::function<bool(double)> check_;
  double radius_;
};
"""


def test_ros1_forms_parse_clean_for_a_noetic_workspace(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("tracker"))
    source = tmp_path / "tracker.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    errors = [(d.location.line, d.message) for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_MESSAGE_UNKNOWN", "CPP_ERROR_NEAR_CALL")]
    assert errors == []
    assert [(c.kind, c.name) for c in result.calls if c.kind != "read"] == [
        ("subscribe", "odom"), ("publish", "delay")]


def test_a_ros2_workspace_keeps_tf2_s_own_time_point(tmp_path) -> None:
    """ROS 2's tf2::Stamped is stamped with tf2::TimePoint, which rclcpp code gives it
    (robot_localization's ``tf2::timeFromSec``)."""
    (tmp_path / "package.xml").write_text(package_xml("loc", "ament_cmake"))
    source = tmp_path / "loc.cpp"
    source.write_text(
        "#include <rclcpp/rclcpp.hpp>\n#include <tf2/utils.h>\n"
        "#include <tf2_ros/buffer.h>\n"
        "void f(double t) {\n"
        "  tf2::Stamped<tf2::Transform> pose;\n"
        "  pose.stamp_ = tf2::timeFromSec(t);\n"
        "}\n")
    for distro in ("jazzy", None):
        result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                             distro=distro)
        assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_boost_lexical_cast_beside_a_ros_call(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("plugin"))
    source = tmp_path / "plugin.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
        # as gazebo_ros_utils.h: lexical_cast comes with gazebo's headers, not found here
        "#include <boost/algorithm/string.hpp>\n#include <gazebo/common/common.hh>\n"
        "template <class T> void getParameter(ros::NodeHandle& nh, const T& fallback) {\n"
        "  ROS_WARN(\"default is %s\", boost::lexical_cast<std::string>(fallback).c_str());\n"
        "  static ros::Publisher pub = nh.advertise<std_msgs::String>(\"out\", 1);\n"
        "}\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"plugin\");\n"
        "  ros::NodeHandle nh;\n"
        "  getParameter(nh, 2.5);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_an_opencv_window_handed_to_gtk_and_a_stamped_camera_publish(tmp_path) -> None:
    """image_view's nodelets (image_pipeline before 1.12.20: ``#ifdef HAVE_GTK``, which its
    CMakeLists.txt defines for every target) give the window's native handle to GTK
    beside their ROS calls, and video_stream_opencv publishes through a CameraPublisher
    with a stamp: each was an error in a function that calls the ROS API (partial)."""
    (tmp_path / "package.xml").write_text(package_xml("view"))
    source = tmp_path / "view.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <image_transport/image_transport.h>\n"
        "#include <opencv2/highgui/highgui.hpp>\n#include <gtk/gtk.h>\n"
        "#include <sensor_msgs/CameraInfo.h>\n"
        "static void destroyNode(GtkWidget* widget, gpointer data) {}\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"view\");\n"
        "  ros::NodeHandle nh;\n"
        "  image_transport::ImageTransport it(nh);\n"
        "  image_transport::CameraPublisher pub = it.advertiseCamera(\"camera\", 1);\n"
        "  GtkWidget* widget = GTK_WIDGET(cvGetWindowHandle(\"view\"));\n"
        "  g_signal_connect(widget, \"destroy\", G_CALLBACK(destroyNode), NULL);\n"
        "  sensor_msgs::Image image;\n"
        "  sensor_msgs::CameraInfo info;\n"
        "  pub.publish(image, info, ros::Time::now());\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert ("publish", "camera") in [(c.kind, c.name) for c in result.calls]


def test_nmea_comms_forms_a_message_declared_ahead_poll_flags_and_a_timed_join(
        tmp_path) -> None:
    """nmea_comms (noetic, survey Z39) declares its message ahead with roscpp's
    ``ROS_DECLARE_MESSAGE`` and names its ``ConstPtr`` in a callback's signature, tests a
    poll's ``POLLHUP | POLLERR | POLLNVAL``, measures with ``strnlen``, clears with
    ``bzero`` and waits with ``boost::thread::timed_join``: each was an error in a function
    that makes the node's calls (serial_node and socket_node partial), and the subscribe
    that binds the declared callback was unresolved."""
    (tmp_path / "package.xml").write_text(package_xml("nmea"))
    source = tmp_path / "rx.cpp"
    source.write_text(
        "#include \"ros/ros.h\"\nnamespace std_msgs { ROS_DECLARE_MESSAGE(String); }\n"
        "void tx_msg_callback(const std_msgs::StringConstPtr msg, int fd);\n"
        "#include <poll.h>\n#include <string.h>\n#include <boost/thread.hpp>\n"
        "#include <std_msgs/String.h>\n"
        "void tx_msg_callback(const std_msgs::StringConstPtr msg, int fd) {}\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"rx\");\n"
        "  ros::NodeHandle n;\n"
        "  int fd = 3;\n"
        "  ros::Subscriber sub = n.subscribe<std_msgs::String>(\"out\", 5,\n"
        "      boost::bind(tx_msg_callback, _1, fd));\n"
        "  struct pollfd fds[] = { { fd, POLLIN | POLLOUT, 0 } };\n"
        "  char buffer[64];\n"
        "  bzero(buffer, sizeof(buffer));\n"
        "  if (fds[0].revents & (POLLHUP | POLLERR | POLLNVAL) && strnlen(buffer, 64) == 0)\n"
        "    return 1;\n"
        "  ros::Publisher pub = n.advertise<std_msgs::String>(\"in\", 5);\n"
        "  boost::thread worker;\n"
        "  worker.timed_join(boost::posix_time::milliseconds(10));\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_UNRESOLVED")
            ] == []
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "out"),
                                                         ("publish", "in")]


def test_spencer_forms_names_remap_string_algorithms_and_a_synchroniser_penalty(
        tmp_path) -> None:
    """spencer_people_tracking (noetic, survey Z39) logs and subscribes through
    ``ros::names::remap(topic)``, splits and trims with Boost.StringAlgo
    (``<boost/algorithm/string.hpp>`` was not found, its names unknown), sets an
    ApproximateTime policy's age penalty, calls ``std::terminate``, reads a
    ``time_duration``'s ticks, keeps a ``posix_time::seconds`` (a class, not a function)
    and catches ``boost::thread_interrupted``: each was an error in the function that
    makes the node's calls (eleven of spencer's nodes partial); the name ``remap`` gives
    is the name as written, which the graph remaps."""
    (tmp_path / "package.xml").write_text(package_xml("tracks"))
    source = tmp_path / "filter.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <boost/algorithm/string.hpp>\n"
        "#include <boost/algorithm/string/split.hpp>\n#include <exception>\n"
        "#include <message_filters/subscriber.h>\n"
        "#include <message_filters/synchronizer.h>\n"
        "#include <message_filters/sync_policies/approximate_time.h>\n"
        "#include <sensor_msgs/LaserScan.h>\n#include <std_msgs/String.h>\n"
        "void scan(const sensor_msgs::LaserScan::ConstPtr& msg) {}\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"filter\");\n"
        "  ros::NodeHandle nh;\n"
        "  std::string topic = \"laser\", list = \" a, b \";\n"
        "  std::vector<std::string> words;\n"
        "  boost::algorithm::trim(list);\n"
        "  boost::trim(list, std::locale(\"\"));\n"
        "  boost::split(words, list, boost::is_any_of(\",\"), boost::token_compress_on);\n"
        "  if (words.empty() || !boost::starts_with(list, \"a\")) std::terminate();\n"
        "  ros::Subscriber sub = nh.subscribe(ros::names::remap(topic), 1, &scan);\n"
        "  typedef message_filters::sync_policies::ApproximateTime<sensor_msgs::LaserScan,\n"
        "      std_msgs::String> Policy;\n"
        "  Policy policy(10);\n"
        "  policy.setAgePenalty(1.0);\n"
        "  long t = boost::posix_time::seconds(1).ticks() / "
        "boost::posix_time::time_duration::ticks_per_second();\n"
        "  ROS_INFO_STREAM(\"output \" << ros::names::remap(\"out\") << t);\n"
        "  boost::posix_time::seconds interval(3);\n"
        "  try { boost::this_thread::sleep(interval); }\n"
        "  catch (boost::thread_interrupted&) { return 0; }\n"
        "  ros::Publisher pub = nh.advertise<std_msgs::String>(\"out\", 1);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING",
                          "CPP_NAMES_DECLARED")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "laser"),
                                                         ("publish", "out")]


def test_piksi_forms_eigenvalues_a_path_compare_and_strftime(tmp_path) -> None:
    """ethz_piksi_ros' piksi_multi_cpp (noetic, survey Z39) logs a covariance's
    ``R.eigenvalues().real().cwiseSqrt()``, compares a ``std::filesystem::path``'s
    extension and formats a time with ``std::strftime``: each was an error in the
    function that makes the node's calls (piksi_multi and piksi_multi_config partial);
    spencer's trackers make an ``Eigen::FullPivLU`` from a matrix for its determinant
    and inverse, and divide a vector in place (srl_nearest_neighbor_tracker and the
    laser segmentation nodes partial)."""
    (tmp_path / "package.xml").write_text(package_xml("piksi"))
    source = tmp_path / "piksi.cc"
    source.write_text(
        "#include <ros/ros.h>\n#include <Eigen/Dense>\n#include <filesystem>\n"
        "#include <ctime>\n#include <std_msgs/String.h>\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"piksi\");\n"
        "  ros::NodeHandle nh;\n"
        "  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();\n"
        "  ROS_DEBUG_STREAM(\"bound \" << R.eigenvalues().real().cwiseSqrt().transpose());\n"
        # spencer's trackers: a decomposition made from a matrix, a mean divided in place
        "  Eigen::FullPivLU<Eigen::Matrix3d> lu(R);\n"
        "  Eigen::Matrix3d Sinv = lu.inverse();\n"
        "  Eigen::Vector2d mean = Eigen::Vector2d::Zero();\n"
        "  mean /= (double) 2;\n"
        "  if (std::log(lu.determinant()) > 0 && mean.norm() > 0) return 2;\n"
        "  std::filesystem::path file(\"a.ini\");\n"
        "  if (file.extension().compare(\".ini\") != 0) return 1;\n"
        "  std::time_t now = std::time(nullptr);\n"
        "  char text[32];\n"
        "  std::strftime(text, sizeof(text), \"%Y\", std::localtime(&now));\n"
        "  ros::Publisher pub = nh.advertise<std_msgs::String>(\"settings\", 1);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "settings")]


def test_a_filter_subscriber_subscribed_again_makes_no_other_call(tmp_path) -> None:
    """rwth_upper_body_detector and rwth_ground_plane (spencer, survey Z39) unsubscribe
    their message_filters subscribers until someone listens, then ``subscribe()`` them
    again to the topic they had: the method without arguments was hidden by the
    stand-in's own ``subscribe(node, topic, ...)``, an error in the connect callback
    that makes the node's calls. The re-subscription is no call of its own."""
    (tmp_path / "package.xml").write_text(package_xml("detector"))
    source = tmp_path / "detector.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <message_filters/subscriber.h>\n"
        "#include <sensor_msgs/CameraInfo.h>\n"
        "void connect(message_filters::Subscriber<sensor_msgs::CameraInfo>& sub, bool on) {\n"
        "  if (on) sub.subscribe(); else sub.unsubscribe();\n"
        "}\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"detector\");\n"
        "  ros::NodeHandle n;\n"
        "  message_filters::Subscriber<sensor_msgs::CameraInfo> info(n, \"camera_info\", 1);\n"
        "  info.unsubscribe();\n"
        "  connect(info, true);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "camera_info")]
