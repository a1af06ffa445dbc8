"""The OpenCV and tf (ROS 1) stand-ins cover what real ROS 1 nodes use beside their ROS
calls: VINS-Mono reads its settings with ``cv::FileStorage`` (``fs["imu_topic"] >> t``,
``int n = fs["max_cnt"]``) and ``cv::cv2eigen`` in the function that reads its parameters,
DJI's vehicle node builds ``tf::Matrix3x3(1, 0, 0, ...)`` in the initialiser list of the
constructor that makes its calls, kinova's demos use ``setEulerYPR`` / ``getRow``.
Missing from the stand-ins, each was a C++ error in a function that calls the ROS API,
and the node was partial for code that makes no ROS call."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <opencv2/opencv.hpp>
#include <opencv2/core/eigen.hpp>
#include <Eigen/Dense>
#include <tf/transform_datatypes.h>
#include <tf/LinearMath/Matrix3x3.h>
#include <tf/LinearMath/Quaternion.h>
#include <tf/LinearMath/Vector3.h>

std::string IMU_TOPIC;
int MAX_CNT;

void readParameters(ros::NodeHandle& n) {
  std::string config_file;
  n.getParam("config_file", config_file);
  cv::FileStorage fs(config_file, cv::FileStorage::READ);
  if (!fs.isOpened()) ROS_ERROR("bad file");
  fs["imu_topic"] >> IMU_TOPIC;
  MAX_CNT = fs["max_cnt"];
  double gain = fs["gain"];
  cv::Mat R;
  fs["extrinsicRotation"] >> R;
  Eigen::Matrix3d eigen_R;
  cv::cv2eigen(R, eigen_R);
  cv::FileNode node = fs["cams"];
  for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it) {
    std::string cam = (std::string)(*it)["name"];
  }
  cv::Point2d p(1.0, 2.0), q = p * 2.0 + cv::Point2d(0.5, 0.5);
  double d = p.dot(q) / cv::norm(q);
  cv::Mat K = (cv::Mat_<double>(3, 3) << 1, 0, 0, 0, 1, 0, 0, 0, 1);
  cv::Mat part = K.rowRange(0, 2).mul(K.rowRange(1, 3)) + cv::Scalar::all(d + gain);
  fs.release();
  n.advertise<std_msgs::String>("status", 1);
}

class Vehicle {
public:
  Vehicle() : R_FLU2FRD_(tf::Matrix3x3(1, 0, 0, 0, -1, 0, 0, 0, -1)) {
    tf::Matrix3x3 m;
    m.setEulerYPR(0.1, 0.2, 0.3);
    m.setValue(1, 0, 0, 0, 1, 0, 0, 0, 1);
    tf::Vector3 row = m.getRow(0);
    tf::Quaternion a(0, 0, 0, 1), b;
    b.setX(row.x()); b.setY(0); b.setZ(0); b.setW(1);
    tf::Quaternion c = a.slerp(b, 0.5) * tf::createIdentityQuaternion();
    sub_ = nh_.subscribe<std_msgs::String>(IMU_TOPIC, 10, &Vehicle::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr& msg) {}
private:
  tf::Matrix3x3 R_FLU2FRD_;
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "tracker");
  ros::NodeHandle n("~");
  readParameters(n);
  Vehicle vehicle;
  ros::spin();
  return 0;
}
"""


def test_opencv_settings_and_tf_linear_math_make_no_error(write_tree) -> None:
    root = write_tree({
        "tracker/package.xml": package_xml("tracker", "catkin"),
        "tracker/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(tracker)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs tf)\n"
            "catkin_package()\nadd_executable(tracker src/tracker.cpp)\n"),
        "tracker/src/tracker.cpp": SOURCE})
    result = extract_cpp([str(root / "tracker" / "src" / "tracker.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    calls = [(c.kind, c.name) for c in result.calls]
    assert ("read", "~config_file") in calls and ("publish", "~status") in calls
    assert ("subscribe", "?") in calls
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING")]
    assert errors == []


LIBC = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <cstdio>
#include <csignal>
#include <iostream>
#include <limits>
#include <pwd.h>
#include <unistd.h>

void stop(int) { ros::shutdown(); }

int main(int argc, char** argv) {
  ros::init(argc, argv, "player");
  ros::NodeHandle n;
  ros::Publisher pub = n.advertise<std_msgs::String>("lines", 10);
  struct sigaction action;
  action.sa_handler = stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, NULL);
  const char* home = getpwuid(getuid())->pw_dir;
  FILE* file = std::fopen(home, "r");
  char line[256];
  while (!feof(file) && std::fgets(line, sizeof(line), file)) {
    std_msgs::String msg;
    msg.data = line;
    pub.publish(msg);
  }
  std::cin.clear();
  std::cin.ignore(std::numeric_limits<std::streamsize>::max(), '\\n');
  return 0;
}
"""


def test_libc_files_signals_and_users_make_no_error(write_tree) -> None:
    """VINS-Mono's benchmark publisher reads its file with ``feof``, DJI's samples set a
    ``struct sigaction`` and clear ``std::cin``, kinova's test reads ``getpwuid``: each an
    error in ``main``, which makes the node's calls."""
    root = write_tree({
        "player/package.xml": package_xml("player", "catkin"),
        "player/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(player)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
            "catkin_package()\nadd_executable(player src/player.cpp)\n"),
        "player/src/player.cpp": LIBC})
    result = extract_cpp([str(root / "player" / "src" / "player.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert ("publish", "lines") in [(c.kind, c.name) for c in result.calls]
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING")]
    assert errors == []


TF2 = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2/transform_datatypes.h>

class Force : public rclcpp::Node {
public:
  Force() : Node("force") {
    tf2::Matrix3x3 flip(1, 0, 0, 0, -1, 0, 0, 0, -1);
    tf2::Quaternion q;
    q.setX(0); q.setW(1);
    tf2::Vector3 axis = q.getAxis();
    tf2::Vector3 turned = tf2::quatRotate(q, axis.cross(flip.getRow(0)).normalized());
    double d = turned.dot(axis) + q.angleShortestPath(tf2::Quaternion::getIdentity());
    tf2::Stamped<tf2::Transform> stamped;
    stamped.setData(tf2::Transform(q));
    tf2::Transform moved;
    moved.mult(moved, stamped);
    pub_ = create_publisher<std_msgs::msg::String>("wrench_state", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Force>());
}
"""


def test_tf2_linear_math_makes_no_error(write_tree) -> None:
    """Universal_Robots_ROS2_Driver's force_mode_controller reads ``q.getAxis()``,
    robot_localization uses ``tf2::quatRotate``: errors where a node makes its calls."""
    root = write_tree({
        "force/package.xml": package_xml("force", "ament_cmake"),
        "force/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(force)\n"
            "find_package(rclcpp REQUIRED)\nadd_executable(force src/force.cpp)\n"),
        "force/src/force.cpp": TF2})
    result = extract_cpp([str(root / "force" / "src" / "force.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert ("publish", "wrench_state") in [(c.kind, c.name) for c in result.calls]
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING")]
    assert errors == []


CONTROLLER = """#include <memory>
#include <ros/ros.h>
#include <realtime_tools/realtime_box.h>
#include <std_msgs/Float64.h>

class HeadController {
public:
  bool init(ros::NodeHandle& nh) {
    std::shared_ptr<std_msgs::Float64> ratio(new std_msgs::Float64());
    ratio->data = 0.3;
    ratio_box_.set(ratio);
    pub_ = nh.advertise<std_msgs::Float64>("state", 1);
    timer_ = nh.createTimer(100, &HeadController::publish, this);
    return true;
  }
  void publish(const ros::TimerEvent&) {}
private:
  realtime_tools::RealtimeBox<std::shared_ptr<const std_msgs::Float64>> ratio_box_;
  ros::Publisher pub_;
  ros::Timer timer_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "head");
  ros::NodeHandle nh("head");
  HeadController c;
  c.init(nh);
  ros::spin();
  return 0;
}
"""


def test_a_box_of_a_shared_pointer_and_a_timer_at_a_rate_make_no_error(write_tree) -> None:
    """sawyer_simulator's controllers: ``box.set(shared_ptr<T>)`` of a
    ``RealtimeBox<shared_ptr<const T>>`` was ambiguous with the box's ``set(function)``
    (the stand-in's std::function took a smart pointer, which has no ``operator()``),
    and ``nh.createTimer(100, &C::f, this)`` found no overload (roscpp's
    ``Rate(double)`` is not explicit: 100 Hz): errors in a function that calls the ROS
    API, the node partial."""
    root = write_tree({
        "head/package.xml": package_xml("head", "catkin"),
        "head/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(head)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs realtime_tools)\n"
            "catkin_package()\nadd_executable(head src/head.cpp)\n"),
        "head/src/head.cpp": CONTROLLER})
    result = extract_cpp([str(root / "head" / "src" / "head.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert ("publish", "head/state") in [(c.kind, c.name) for c in result.calls]
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING")]
    assert errors == []


WAIT = """#include <ros/ros.h>
#include <ros/topic.h>
#include <sensor_msgs/CameraInfo.h>
#include <std_msgs/String.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "look");
  ros::NodeHandle n;
  if (!ros::Time::waitForValid(ros::WallDuration(10.0)))
    return 1;
  sensor_msgs::CameraInfoConstPtr msg = ros::topic::waitForMessage
      <sensor_msgs::CameraInfo>("/camera/info", ros::Duration(10.0));
  if (msg.use_count() > 0 && !msg.unique())
    n.advertise<std_msgs::String>("ready", 1);
  return 0;
}
"""


def test_time_wait_for_valid_with_a_timeout_and_shared_pointer_counts(write_tree) -> None:
    """PAL's tiago_tutorials wait for a valid time with a timeout
    (``ros::Time::waitForValid(ros::WallDuration(10.0))``) in ``main`` of four nodes, and
    look_to_point tests ``msg.use_count()`` of what ``waitForMessage`` gives: each an
    error in ``main``, which makes the node's calls (CPP_NODE_PARTIAL)."""
    root = write_tree({
        "look/package.xml": package_xml("look", "catkin"),
        "look/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(look)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp sensor_msgs std_msgs)\n"
            "catkin_package()\nadd_executable(look src/look.cpp)\n"),
        "look/src/look.cpp": WAIT})
    result = extract_cpp([str(root / "look" / "src" / "look.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    calls = [(c.kind, c.name) for c in result.calls]
    assert ("subscribe", "/camera/info") in calls and ("publish", "ready") in calls
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING")]
    assert errors == []


TOPICS = """#include <ros/ros.h>
#include <std_msgs/String.h>

class Manager {
public:
  Manager() {
    ros::NodeHandle nh("msf_core");
    pub_ = nh.advertise<std_msgs::String>("state_out", 10);
    ros::V_string topics;
    ros::this_node::getSubscribedTopics(topics);
    std::string text = ros::this_node::getName() + ":\\n";
    for (unsigned int i = 0; i < topics.size(); i++) text += topics.at(i);
    ros::this_node::getAdvertisedTopics(topics);
    ROS_INFO_STREAM(text);
  }
  ros::Publisher pub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "manager");
  Manager manager;
  ros::spin();
}
"""


def test_the_node_s_own_topic_lists_make_no_error(write_tree) -> None:
    """ethzasl_msf's sensor manager prints ``ros::this_node::getSubscribedTopics`` and
    ``getAdvertisedTopics`` (roscpp's this_node.h) in the constructor that advertises its
    state: unknown to the stand-ins, each was read as a declaration of ``topics`` again,
    an error there, and every msf node was partial."""
    root = write_tree({
        "manager/package.xml": package_xml("manager", "catkin"),
        "manager/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(manager)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
            "catkin_package()\nadd_executable(manager src/manager.cpp)\n"),
        "manager/src/manager.cpp": TOPICS})
    result = extract_cpp([str(root / "manager" / "src" / "manager.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "msf_core/state_out")]
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == []


QT_NODE = """#include <QThread>
#include <QStringListModel>
#include <ros/ros.h>
#include <std_msgs/String.h>

class QNode : public QThread {
public:
  bool init() {
    ros::NodeHandle nh;
    runstop_ = nh.advertise<std_msgs::String>("runstop", 1);
    QStringList header;
    header << "Sender" << "Motion Enabled" << "Time since last message";
    sub_ = nh.subscribe("chassisState", 1, &QNode::cb, this);
    return true;
  }
  void cb(const std_msgs::String::ConstPtr& msg) {}
  ros::Publisher runstop_;
  ros::Subscriber sub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "ocs");
  QNode node;
  node.init();
  ros::spin();
}
"""


def test_a_qt_string_list_built_with_the_stream_operator_makes_no_error(write_tree) -> None:
    """AutoRally's operator control station fills a table's header with ``QStringList
    header; header << "Sender" << ...`` in the ``init`` that subscribes to the chassis
    (qnode.cpp:164): without ``QList::operator<<`` in the Qt stand-in, an error in a
    function that calls the ROS API, and the node was partial."""
    root = write_tree({
        "ocs/package.xml": package_xml("ocs", "catkin"),
        "ocs/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(ocs)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
            "catkin_package()\nadd_executable(ocs src/qnode.cpp)\n"),
        "ocs/src/qnode.cpp": QT_NODE})
    result = extract_cpp([str(root / "ocs" / "src" / "qnode.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert {(c.kind, c.name) for c in result.calls} == {("publish", "runstop"),
                                                        ("subscribe", "chassisState")}
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == []


QT_WINDOW = """#include <QtGui>
#include <QMainWindow>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

class MainWindow : public QMainWindow {
public:
  MainWindow() {
    QObject::connect(this, SIGNAL(destroyed()), qApp, SLOT(quit()));
    client_ = nh_.serviceClient<std_srvs::Trigger>("solve");
  }
  ros::NodeHandle nh_;
  ros::ServiceClient client_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "gui");
  QApplication app(argc, argv);
  MainWindow window;
  return app.exec();
}
"""


def test_qt_s_application_macro_makes_no_error(write_tree) -> None:
    """industrial_calibration's ical_gui connects its About action to ``qApp`` (Qt's
    macro for the application object, qapplication.h) in the window constructor that
    makes its service clients (icalgui_main_window.cpp:56): without the macro in the Qt
    stand-in, an error in a function that calls the ROS API, and the node was partial."""
    root = write_tree({
        "gui/package.xml": package_xml("gui", "catkin"),
        "gui/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(gui)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_srvs)\n"
            "catkin_package()\nadd_executable(gui src/gui.cpp)\n"),
        "gui/src/gui.cpp": QT_WINDOW})
    result = extract_cpp([str(root / "gui" / "src" / "gui.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert {(c.kind, c.name) for c in result.calls} == {("client", "solve")}
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == []
