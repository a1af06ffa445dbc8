"""A class of another workspace package that a ROS 1 node builds is judged by the code
of its constructor (``_client``: a NodeHandle there makes it a client, whose calls the
node does not read); that code was looked for among the first 400 C++ files of the
package's folder, in name order, and quadruped-robot's quadruped keeps 396 files of
vendored libraries in ``extern/`` and 74 headers before its ``src/``:
``qrStateDataFlow``, a struct of Eigen members its example nodes build in their robot
(qr_robot.h:627), was not found and said unseen, each example node partial. The
sources of the libraries the package's CMake builds are read first
(``_library_sources``)."""

from __future__ import annotations

from typing import Any

from test_extract_cpp_class_unseen import _depends, _model

HEADER = """
    #include <vector>
    namespace legs {
    struct Flow {
      Flow();
      std::vector<double> forces;
    };
    }  // namespace legs
    """

SOURCE = """
    #include "legs/flow.h"
    namespace legs {
    Flow::Flow() : forces(4, 0.0) {%s}
    }  // namespace legs
    """

USER = """
    #include <ros/ros.h>
    #include "legs/flow.h"
    int main(int argc, char** argv) {
      ros::init(argc, argv, "walker");
      legs::Flow flow;
      ros::spin();
    }
    """


def _walker(write_tree: Any, body: str) -> Any:
    vendored = {f"src/legs/extern/solver/s{index:03}.h": f"int s{index:03}();\n"
                for index in range(420)}
    model = _model(write_tree, {
        **vendored,
        "src/legs/package.xml": _depends("legs", "roscpp"),
        "src/legs/CMakeLists.txt":
            "project(legs)\nfind_package(catkin REQUIRED COMPONENTS roscpp)\n"
            "catkin_package(INCLUDE_DIRS include LIBRARIES legs)\n"
            "include_directories(include)\nadd_library(legs src/flow.cpp)\n",
        "src/legs/include/legs/flow.h": HEADER,
        "src/legs/src/flow.cpp": SOURCE % body,
        "src/walker/package.xml": _depends("walker", "roscpp", "legs"),
        "src/walker/CMakeLists.txt":
            "project(walker)\nfind_package(catkin REQUIRED COMPONENTS roscpp legs)\n"
            "add_executable(walker src/walker.cpp)\n"
            "target_link_libraries(walker ${catkin_LIBRARIES})\n",
        "src/walker/src/walker.cpp": USER,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "walker/walker")
    node.said = [d for d in model.diagnostics if d.code == "CPP_CLASS_UNSEEN"]
    return node


def test_a_class_whose_library_code_makes_no_handle_behind_vendored_files(
        write_tree: Any) -> None:
    node = _walker(write_tree, "")
    assert node.said == []
    assert node.completeness == "complete", node.completeness_reasons


def test_a_class_whose_library_code_makes_a_handle_is_still_judged(write_tree: Any) -> None:
    # its file names ROS: linked, it is among the node's sources, its calls read
    node = _walker(write_tree, 'ros::NodeHandle nh("~"); double m; nh.param("mass", m, 1.0);')
    assert node.completeness == "complete", node.completeness_reasons
    assert "~mass" in [c.name for c in node.calls]
