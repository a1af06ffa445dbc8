"""Two stand-in gaps that made orunav_mpc's controller node (navigation_oru) partial:
``ros::CallbackQueue::isEmpty()`` (roscpp's other spelling of ``empty()``:
``while (comm_queue.isEmpty() == false) comm_queue.callOne();`` in trajectoryReader's
read loop) and a string stream built from an open mode alone (swLogger.h's ``SW_LOG``:
``ostringstream log_stream12(ostringstream::out);``). Each was a clang error in a
function that subscribes and publishes, so a place where a ROS call may be missing.
Likewise the stand-in Eigen had a translation times a rotation and not a rotation times
a translation (the pallet detector's ``Eigen::AngleAxisd(yaw, UnitZ()) *
Eigen::Translation3d(p)`` in its constructor, which makes its publishers)."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml


def _files() -> dict[str, str]:
    return {
        "mpc/package.xml": package_xml("mpc", "catkin").replace(
            "<export>", "<depend>roscpp</depend><depend>std_msgs</depend><export>"),
        "mpc/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(mpc)
            find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
            add_executable(controller src/controller.cpp)
            """,
        "mpc/src/controller.cpp": """
            #include <sstream>
            #include <string>
            #include <ros/ros.h>
            #include <ros/callback_queue.h>
            #include <Eigen/Dense>
            #include <Eigen/Geometry>
            #include <std_msgs/String.h>
            using namespace std;
            void onState(const std_msgs::String::ConstPtr&) {}
            void readLoop() {
              ros::NodeHandle nh;
              ros::CallbackQueue comm_queue;
              nh.setCallbackQueue(&comm_queue);
              ros::Subscriber sub = nh.subscribe("state", 1, onState);
              ros::Publisher pub = nh.advertise<std_msgs::String>("report", 1);
              while (ros::ok()) {
                while (comm_queue.isEmpty() == false) {
                  comm_queue.callOne();
                }
                Eigen::Affine3d offset = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
                    Eigen::Translation3d(Eigen::Vector3d(1.0, 2.0, 0.0));
                Eigen::Affine3d turned = Eigen::Quaterniond::Identity() * offset;
                (void)turned;
                ostringstream log_stream(ostringstream::out);
                log_stream << "read" << endl;
                std_msgs::String msg;
                msg.data = log_stream.str();
                pub.publish(msg);
              }
            }
            int main(int argc, char ** argv)
            {
              ros::init(argc, argv, "controller");
              readLoop();
            }
            """,
    }


def test_an_is_empty_queue_and_a_stream_of_an_open_mode_parse(write_tree):
    ws = scan([str(write_tree(_files()))])
    pkg = ws.packages["mpc"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert sorted((c.kind, c.name) for c in node.calls) == [
        ("publish", "report"), ("subscribe", "state")]
    assert [d.message for d in found if d.code in ("CPP_PARSE_ERROR",
                                                    "CPP_ERROR_NEAR_CALL")] == []
    assert node.completeness == "complete"
