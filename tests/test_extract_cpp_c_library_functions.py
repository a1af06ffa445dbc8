"""A lowercase C function named after a header found missing (``ogg_stream_init`` of
<ogg/ogg.h>, theora_image_transport's ogg_saver) is declared permissively, as an
upper-case prefixed one (``SDL_Init``) was: left undeclared, its error sat in a function
that calls the ROS API and made the node partial though no ROS call can hide in it. An
unqualified lowercase call of no missing library's prefix is still not declared (in a
class it may be a member of a base the parse could not read)."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.extract.cpp import synthesis
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "saver/package.xml": package_xml("saver", "catkin").replace(
        "<export>", "<depend>roscpp</depend><depend>std_msgs</depend><export>"),
    "saver/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(saver)
        find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
        add_executable(saver src/saver.cpp)
        """,
    "saver/src/saver.cpp": """
        #include <ros/ros.h>
        #include <ogg/ogg.h>
        #include <std_msgs/String.h>
        class Saver {
        public:
          Saver() {
            if (ogg_stream_init(nullptr, 0) == -1) {
              ROS_FATAL("cannot initialise the stream");
            }
            sub_ = nh_.subscribe("stream", 10, &Saver::write, this);
          }
          void write(const std_msgs::String::ConstPtr& msg) {
            ogg_stream_packetin(nullptr, msg->data.c_str());
          }
        private:
          ros::NodeHandle nh_;
          ros::Subscriber sub_;
        };
        int main(int argc, char ** argv)
        {
          ros::init(argc, argv, "saver");
          Saver saver;
          ros::spin();
        }
        """,
}


def test_a_function_of_a_missing_c_header_is_declared(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    pkg = ws.packages["saver"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [(c.kind, c.name) for c in node.calls] == [("subscribe", "stream")]
    codes = [d.code for d in found]
    assert "CPP_NODE_PARTIAL" not in codes
    assert "CPP_ERROR_NEAR_CALL" not in codes
    assert node.completeness == "complete"


PLAYER = {
    "player/package.xml": FILES["saver/package.xml"].replace("saver", "player"),
    "player/CMakeLists.txt": FILES["saver/CMakeLists.txt"].replace("saver", "player"),
    # cob_sound: <vlc/vlc.h> declares libvlc_new, libvlc_media_player_new, ...
    "player/src/player.cpp": """
        #include <ros/ros.h>
        #include <vlc/vlc.h>
        #include <std_msgs/String.h>
        class Player {
        public:
          Player() {
            nh_ = ros::NodeHandle("~");
            pub_ = nh_.advertise<std_msgs::String>("diagnostics", 1);
            inst_ = libvlc_new(0, NULL);
            player_ = libvlc_media_player_new(inst_);
          }
        private:
          ros::NodeHandle nh_;
          ros::Publisher pub_;
          libvlc_instance_t* inst_;
          libvlc_media_player_t* player_;
        };
        int main(int argc, char ** argv)
        {
          ros::init(argc, argv, "player");
          Player player;
          ros::spin();
        }
        """,
}


def test_a_function_named_lib_and_the_missing_header_is_declared(write_tree) -> None:
    """``libvlc_new`` of <vlc/vlc.h> (cob_sound): left undeclared, its error in the
    constructor that advertises made the node partial, and a remap of a name it does
    not use undecided."""
    ws = scan([str(write_tree(PLAYER))])
    pkg = ws.packages["player"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "~diagnostics")]
    assert "CPP_ERROR_NEAR_CALL" not in [d.code for d in found]
    assert node.completeness == "complete"


def test_library_prefixes_and_what_they_declare() -> None:
    assert synthesis.library_prefixes([
        "header ogg/ogg.h not found; an empty stand-in was used",
        "header urg_c/urg_sensor.h not found; an empty stand-in was used",
        "header io.h not found; an empty stand-in was used",
        "header libusb-1.0/libusb.h not found; an empty stand-in was used",
        "C++ error: something else"]) == {"ogg", "libogg", "urg", "liburg", "libusb"}
    text = b"void f() { ogg_stream_init(&s, 0); read_frame(&s); }"
    names = synthesis.Names(libraries={"ogg"})
    names.learn([("use of undeclared identifier 'ogg_stream_init'", text,
                  text.index(b"ogg_stream_init")),
                 ("use of undeclared identifier 'read_frame'", text, text.index(b"read_frame"))])
    assert "ogg_stream_init" in names.root.children
    assert "read_frame" not in names.root.children


def test_a_macro_in_capitals_ending_with_an_underscore_is_declared(write_tree) -> None:
    """mrpt_navigation's nodes check with MRPT's ``ASSERT_(x)`` / ``ASSERTMSG_(c, m)`` /
    ``ASSERT_GT_(a, b)`` from <mrpt/core/exceptions.h>: with the header missing, each
    was an undeclared name in the constructor that makes the node's calls, and the node
    partial. A called name in capitals ending with ``_`` is a function-like macro of a
    missing header: declared permissively, the node complete."""
    files = {
        "pf/package.xml": package_xml("pf", "ament_cmake").replace(
            "<export>", "<depend>rclcpp</depend><depend>std_msgs</depend><export>"),
        "pf/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.8)
            project(pf)
            find_package(rclcpp REQUIRED)
            add_executable(pf_node src/pf.cpp)
            """,
        "pf/src/pf.cpp": """
            #include <rclcpp/rclcpp.hpp>
            #include <mrpt/core/exceptions.h>
            #include <std_msgs/msg/string.hpp>
            class Pf : public rclcpp::Node {
            public:
              Pf() : rclcpp::Node("pf") {
                period_ = declare_parameter<double>("period", 0.1);
                ASSERT_(period_ > 0);
                ASSERTMSG_(period_ < 10, "too slow");
                ASSERT_GT_(period_, 0.0);
                pub_ = create_publisher<std_msgs::msg::String>("status", 10);
              }
            private:
              double period_;
              rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
            };
            int main(int argc, char ** argv) {
              rclcpp::init(argc, argv);
              rclcpp::spin(std::make_shared<Pf>());
            }
            """,
    }
    ws = scan([str(write_tree(files))])
    pkg = ws.packages["pf"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [(c.kind, c.name) for c in node.calls] == [
        ("declare", "period"), ("publish", "status")]
    codes = [d.code for d in found]
    assert "CPP_ERROR_NEAR_CALL" not in codes and "CPP_NODE_PARTIAL" not in codes
    assert node.completeness == "complete"
