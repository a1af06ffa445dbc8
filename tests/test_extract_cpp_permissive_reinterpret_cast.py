"""``reinterpret_cast`` of a value of code the parse does not read: the value is the
permissive ``haros_any`` (a class), and C++ casts no class to a pointer, so clang says
``reinterpret_cast from 'haros_any' to 'QGLMap *' is not allowed``. mapviz's
multires_view_node.cpp:106 (``reinterpret_cast<QGLMap*>(vendor_view::current())``, Qt's
QMainWindow a header the parse lacks) is in Initialize, which reads ``image_path``
(:99), and the node was partial. The error spoils only the cast's value, one nobody
knows anyway; outside the statement of a ROS call it hides none (a call lost after it
is still found by its line, CPP_CALL_MISSED). Inside one, the node stays partial."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml


def _files(statement: str) -> dict[str, str]:
    return {
        "viewer/package.xml": package_xml("viewer", "catkin").replace(
            "<export>", "<depend>roscpp</depend><depend>std_msgs</depend><export>"),
        "viewer/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(viewer)
            find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
            add_executable(viewer src/viewer.cpp)
            """,
        "viewer/src/viewer.cpp": """
            #include <string>
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            #include <QMainWindow>
            #include <vendor_view/view.h>
            struct Map { void setPath(const std::string &) {} };
            class Viewer : public QMainWindow {
            public:
              void initialize();
            private:
              ros::NodeHandle node_;
              ros::Publisher pub_;
            };
            void Viewer::initialize() {
              std::string path;
              node_.param("image_path", path, std::string(""));
              """ + statement + """
              pub_ = node_.advertise<std_msgs::String>("status", 1);
            }
            int main(int argc, char ** argv)
            {
              ros::init(argc, argv, "viewer");
              Viewer viewer;
              viewer.initialize();
              ros::spin();
            }
            """,
    }


def _node(write_tree, statement: str):
    ws = scan([str(write_tree(_files(statement)))])
    pkg = ws.packages["viewer"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    return pkg.nodes[0], [d.code for d in found]


def test_a_cast_of_an_unknown_value_hides_no_call(write_tree):
    node, codes = _node(write_tree, """
              Map* map = reinterpret_cast<Map*>(vendor_view::current());
              map->setPath(path);""")
    assert sorted((c.kind, c.name) for c in node.calls) == [
        ("publish", "status"), ("read", "image_path")]
    assert "CPP_ERROR_NEAR_CALL" not in codes
    assert node.completeness == "complete"


def test_in_a_ros_call_the_node_stays_partial(write_tree):
    # (guard) the cast in the statement of a ROS call: that call may be lost with it
    node, codes = _node(write_tree, """
              node_.param(*reinterpret_cast<std::string*>(vendor_view::current()), path,
                          std::string(""));""")
    assert "CPP_ERROR_NEAR_CALL" in codes
    assert node.completeness == "partial"
