"""A function a ``bind`` or a thread is given is called with the arguments given after
it: Doosan's dsr_control builds its robot interface with the node's private handle in
main.cpp, and the interface's constructor, in another file, starts
``boost::thread(boost::bind(&thread_subscribe, private_nh_))``, a static method
that subscribes ``stop`` on the handle it is given: the subscription was ``?/stop``
(the call site of the parameter was the bind, which names ``boost::bind``), and is
``~stop``; so for ``std::thread(&Class::method, this, handle, rate)`` (a method: the
object goes before)."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "arm/package.xml": package_xml("arm", "catkin"),
    "arm/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(arm)
        find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
        catkin_package()
        include_directories(include ${catkin_INCLUDE_DIRS})
        add_executable(arm_node src/main.cpp src/interface.cpp)
        target_link_libraries(arm_node ${catkin_LIBRARIES})
        """,
    "arm/include/arm/interface.h": """
        #pragma once
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        #include <boost/thread.hpp>
        #include <boost/bind.hpp>
        #include <thread>
        class Interface {
         public:
          explicit Interface(ros::NodeHandle& nh);
          static void thread_subscribe(ros::NodeHandle nh);
          void thread_publish(ros::NodeHandle nh, int rate);
          static void on_stop(const std_msgs::String::ConstPtr& msg);
         private:
          ros::NodeHandle private_nh_;
          boost::thread th_subscribe_;
          std::thread th_publish_;
        };
        """,
    "arm/src/interface.cpp": """
        #include <arm/interface.h>
        Interface::Interface(ros::NodeHandle& nh) : private_nh_(nh) {
          th_subscribe_ = boost::thread(boost::bind(&thread_subscribe, private_nh_));
          th_publish_ = std::thread(&Interface::thread_publish, this, private_nh_, 10);
        }
        void Interface::thread_subscribe(ros::NodeHandle nh) {
          ros::Subscriber sub = nh.subscribe("stop", 100, &Interface::on_stop);
          ros::spin();
        }
        void Interface::thread_publish(ros::NodeHandle nh, int rate) {
          ros::Publisher pub = nh.advertise<std_msgs::String>("state", 100);
        }
        void Interface::on_stop(const std_msgs::String::ConstPtr& msg) {}
        """,
    "arm/src/main.cpp": """
        #include <arm/interface.h>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "arm");
          ros::NodeHandle private_nh("~");
          Interface* arm = new Interface(private_nh);
          ros::spin();
          delete arm;
        }
        """,
}


def test_a_bound_function_takes_the_arguments_after_it(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    (node,) = [n for n in ws.packages["arm"].nodes if n.executable == "arm_node"]
    extract_nodes([node], ws, cache_dir=None, jobs=1)
    assert sorted((c.kind, c.name) for c in node.calls) == [
        ("publish", "~state"), ("subscribe", "~stop")]
