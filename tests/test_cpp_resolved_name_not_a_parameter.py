"""roscpp's ``ros::names::resolve(name)`` and ``NodeHandle::resolveName(name)`` are rows
of kind read only to mark the remap the code uses; the name they return is no parameter's
value. A topic held from one (topic_tools' mux: ``sub_info.topic_name =
ros::names::resolve(topics[i])``, the words of its command line) was said to be named by
a parameter ``?``, and one resolved from a parameter's value (``resolve(topic)``, topic
read from ``~topic``) lost that parameter for the same ``?``."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

CMAKE = """
    cmake_minimum_required(VERSION 3.0.2)
    project(relay)
    find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
    catkin_package()
    include_directories(${catkin_INCLUDE_DIRS})
    add_executable(relay src/relay.cpp)
    target_link_libraries(relay ${catkin_LIBRARIES})
    """

SOURCE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <vector>
    void cb(const std_msgs::String::ConstPtr& m) {}
    struct info_t { std::string topic_name; ros::Subscriber* sub; };
    int main(int argc, char** argv) {
      ros::init(argc, argv, "relay");
      std::vector<std::string> topics;
      for (int i = 2; i < argc; i++) topics.push_back(argv[i]);
      ros::NodeHandle n, pnh("~");
      for (size_t i = 0; i < topics.size(); i++) {
        struct info_t sub_info;
        sub_info.topic_name = ros::names::resolve(topics[i]);
        sub_info.sub = new ros::Subscriber(n.subscribe(sub_info.topic_name, 10, cb));
      }
      std::string topic;
      pnh.param<std::string>("topic", topic, "scan");
      std::string resolved = ros::names::resolve(topic);
      ros::Subscriber a = n.subscribe(resolved, 10, cb);
      std::string remapped = n.resolveName(topic);
      ros::Subscriber b = n.subscribe(remapped, 10, cb);
      ros::spin();
    }
    """


def test_a_resolved_name_is_named_by_the_parameter_its_argument_holds(write_tree) -> None:
    root = write_tree({"relay/package.xml": package_xml("relay", "catkin"),
                       "relay/CMakeLists.txt": CMAKE, "relay/src/relay.cpp": SOURCE})
    ws = scan([str(root)])
    package = ws.packages["relay"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    (node,) = package.nodes
    subscriptions = sorted((c.location.line, c.name, c.name_param, c.name_default)
                           for c in node.calls if c.kind == "subscribe")
    assert [s[1:] for s in subscriptions] == [
        ("?", None, None), ("?", "~topic", "scan"), ("?", "~topic", "scan")]
