"""boost::iterator_facade, the base ROS 1 rosbag_storage's ``View::iterator`` derives: a
loop over a class's iterator built on it (``it != end``, ``++it``, ``it->getTopic()``)
parses, so a ROS call in that function leaves its node whole. rosbag's play and encrypt,
read beside rosbag_storage's source (ros_comm's tree), were partial for it."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

CMAKE = """
    cmake_minimum_required(VERSION 3.0.2)
    project(replay)
    find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
    catkin_package()
    include_directories(${catkin_INCLUDE_DIRS})
    add_executable(replay src/replay.cpp)
    target_link_libraries(replay ${catkin_LIBRARIES})
    """

SOURCE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <boost/iterator/iterator_facade.hpp>
    #include <string>
    struct Item { const std::string& getTopic() const; };
    class Items {
    public:
      class iterator
          : public boost::iterator_facade<iterator, Item, boost::forward_traversal_tag> {
      public:
        iterator();
      private:
        friend class boost::iterator_core_access;
        bool equal(const iterator& other) const;
        void increment();
        Item& dereference() const;
      };
      iterator begin();
      iterator end();
    };
    int main(int argc, char** argv) {
      ros::init(argc, argv, "replay");
      ros::NodeHandle n;
      Items items;
      for (Items::iterator it = items.begin(); it != items.end(); ++it) {
        ros::Publisher p = n.advertise<std_msgs::String>(it->getTopic(), 1);
      }
      ros::spin();
    }
    """


def test_a_loop_over_an_iterator_facade_parses(write_tree) -> None:
    root = write_tree({"replay/package.xml": package_xml("replay", "catkin"),
                       "replay/CMakeLists.txt": CMAKE, "replay/src/replay.cpp": SOURCE})
    ws = scan([str(root)])
    package = ws.packages["replay"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    (node,) = package.nodes
    assert [(c.kind, c.name, c.type) for c in node.calls] == [
        ("publish", "?", "std_msgs/String")]
    assert node.completeness == "complete", node.completeness_reasons
