"""actionlib's ``SimpleClientGoalState(state, text = "")`` takes the state's text too:
denso_robot_core_test writes ``SimpleClientGoalState gs(SimpleClientGoalState::PENDING,
"")`` before it subscribes and makes its action client. The stand-in's constructor took
the state alone, so the function's C++ error ("no matching constructor") made the node
partial (CPP_NODE_PARTIAL) though nothing of ROS was hidden there."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "mover/package.xml": package_xml("mover", "catkin").replace(
        "<export>", "<depend>roscpp</depend><depend>actionlib</depend>"
                    "<depend>std_msgs</depend><export>"),
    "mover/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(mover)
        find_package(catkin REQUIRED COMPONENTS roscpp actionlib std_msgs)
        add_executable(mover src/mover.cpp)
        """,
    "mover/src/mover.cpp": """
        #include <ros/ros.h>
        #include <actionlib/client/simple_action_client.h>
        #include <std_msgs/Int32.h>
        using namespace actionlib;
        void feedback(const std_msgs::Int32::ConstPtr&) {}
        void move(const std::string& name)
        {
          ros::NodeHandle nh;
          SimpleClientGoalState gs(SimpleClientGoalState::PENDING, "");
          SimpleClientGoalState other(SimpleClientGoalState::ACTIVE);
          ros::Subscriber sub = nh.subscribe("feedback", 1, &feedback);
          if (gs == SimpleClientGoalState::PENDING && other.getText().empty()) {
            ros::spinOnce();
          }
        }
        int main(int argc, char ** argv)
        {
          ros::init(argc, argv, "mover");
          move("arm");
          ros::spin();
        }
        """,
}


def test_a_goal_state_built_with_its_text_is_no_error(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    pkg = ws.packages["mover"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [(c.kind, c.name) for c in node.calls] == [("subscribe", "feedback")]
    codes = [d.code for d in found]
    assert "CPP_NODE_PARTIAL" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
    assert node.completeness == "complete"
