"""The stand-in ``std::unique_ptr<T[]>`` (the array specialisation) had only a pointer's
constructor, ``operator[]`` and ``get``: a class holding one as a member that its
constructor leaves empty failed to parse ("must explicitly initialize the member
'potential' which does not have a default constructor"), and the constructor, which
reads parameters and advertises, made the node partial (tuw_multi_robot's
tuw_voronoi_graph_node, whose base VoronoiPathGenerator keeps ``std::unique_ptr<float[]>
potential`` and ``reset``s it later). It now has the members the standard gives it: a
default, null and move constructor, move and null assignment, ``release``, ``reset``,
``operator bool`` and ``get_deleter``."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml


def _files() -> dict[str, str]:
    return {
        "grid/package.xml": package_xml("grid", "catkin").replace(
            "<export>", "<depend>roscpp</depend><depend>std_msgs</depend><export>"),
        "grid/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(grid)
            find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
            add_executable(grid src/grid.cpp)
            """,
        "grid/src/grid.cpp": """
            #include <memory>
            #include <utility>
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            class Potential {
            protected:
              std::unique_ptr<float[]> potential;
            };
            class Grid : public Potential {
            public:
              explicit Grid(ros::NodeHandle& n) : n_param_("~") {
                n_param_.param<int>("cells", cells_, 10);
                pub_ = n.advertise<std_msgs::String>("grid", 1);
              }
              void fill() {
                potential.reset(new float[cells_]);
                std::unique_ptr<float[]> other = std::move(potential);
                if (other) other[0] = 1.0f;
                potential = std::move(other);
                float* raw = potential.release();
                delete[] raw;
                potential = nullptr;
              }
            private:
              ros::NodeHandle n_param_;
              ros::Publisher pub_;
              int cells_;
            };
            int main(int argc, char ** argv)
            {
              ros::init(argc, argv, "grid");
              ros::NodeHandle n;
              Grid grid(n);
              grid.fill();
              ros::spin();
            }
            """,
    }


def test_a_member_array_unique_ptr_left_empty_parses(write_tree):
    ws = scan([str(write_tree(_files()))])
    pkg = ws.packages["grid"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert sorted((c.kind, c.name) for c in node.calls) == [
        ("publish", "grid"), ("read", "~cells")]
    assert [d.message for d in found if d.code in ("CPP_PARSE_ERROR",
                                                    "CPP_ERROR_NEAR_CALL")] == []
    assert node.completeness == "complete"
