"""The calls a constructor makes exist where the class is constructed: they carry the
conditions of its construction sites in the file, as a wrapper's calls carry those of
its call site (hector_mapping's HectorDrawings, made only ``if (p_pub_drawings)``,
advertises ``visualization_marker`` in its constructor), and, for a constructor defined
in a file that constructs its class nowhere, those the node's other files construct it
under (sick_tim310 makes the SickTimCommonMockup of sick_tim_common_mockup.cpp, which
subscribes ``datagram``, only ``if (subscribe_datagram)``)."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

DRAWINGS = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class Drawings {
public:
  Drawings()
  {
    ros::NodeHandle nh;
    pub_ = nh.advertise<std_msgs::String>("marker", 1);
  }
private:
  ros::Publisher pub_;
};
"""

NODE = """
#include "drawings.h"
class Mapping {
public:
  Mapping()
  {
    ros::NodeHandle pnh("~");
    pnh.param("pub_drawings", drawings_on_, false);
    pnh.param("levels", levels_, 2);
    if (drawings_on_) {
      drawings_ = new Drawings();
    }
    for (int i = 0; i < levels_; ++i) {
      if (i == 0) {
        first_ = new Level();
      } else {
        other_ = new Level();
      }
    }
  }
private:
  bool drawings_on_;
  int levels_;
  Drawings * drawings_ = nullptr;
  struct Level {
    Level() { ros::NodeHandle nh; pub_ = nh.advertise<std_msgs::String>("level", 1); }
    ros::Publisher pub_;
  };
  Level * first_ = nullptr;
  Level * other_ = nullptr;
};
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "mapping");
  Mapping mapping;
  Drawings * always = nullptr;
  if (argc > 3) {
    always = new Drawings();
  }
}
"""


def _conditions(root: Path, source: str) -> dict[str, list[str]]:
    result = extract_cpp([str(root / "mapping" / "src" / source)], scan([str(root)]),
                         cache_dir=None)
    return {c.name: [f"{k.statement} {k.text}" for k in c.conditions]
            for c in result.calls if c.kind == "publish"}


def test_a_constructor_s_calls_carry_its_construction_s_conditions(write_tree) -> None:
    root = write_tree({"mapping/package.xml": package_xml("mapping"),
                       "mapping/src/drawings.h": DRAWINGS,
                       "mapping/src/mapping.cpp": NODE,
                       # (it names the class: what a unit does not name is not walked
                       # there, ``extract.cpp.reach``)
                       "mapping/src/alone.cpp": '#include "drawings.h"\n'
                                                'void keep(Drawings * drawings);\n'})
    found = _conditions(root, "mapping.cpp")
    # made under two different conditions: none of them is the constructor's; made
    # under two branches of one loop: the loop's is
    assert found["marker"] == []
    assert found["level"] == ["for int i = 0; i < levels_; ++i"]
    # a file that names the class but constructs it nowhere: its calls as they are
    assert _conditions(root, "alone.cpp") == {"marker": []}


def test_the_one_construction_s_condition(write_tree) -> None:
    root = write_tree({"mapping/package.xml": package_xml("mapping"),
                       "mapping/src/drawings.h": DRAWINGS,
                       "mapping/src/mapping.cpp": NODE.replace(
                           "    always = new Drawings();\n", "")})
    assert _conditions(root, "mapping.cpp")["marker"] == ["if drawings_on_"]


MOCKUP_H = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class Scanner {
public:
  virtual ~Scanner() {}
};
class Mockup : public Scanner {
public:
  Mockup();
private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  void datagramCB(const std_msgs::String::ConstPtr & msg) {}
};
class Device : public Scanner {
public:
  explicit Device(int number);
};
"""

MOCKUP_CPP = """
#include "mockup.h"
Mockup::Mockup()
{
  sub_ = nh_.subscribe("datagram", 1, &Mockup::datagramCB, this);
}
"""

SCANNER_MAIN = """
#include "mockup.h"
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "scanner");
  ros::NodeHandle pnh("~");
  bool subscribe_datagram;
  pnh.param("subscribe_datagram", subscribe_datagram, false);
  Scanner * s = nullptr;
  while (ros::ok()) {
    if (subscribe_datagram)
      s = new Mockup();
    else
      s = new Device(0);
    delete s;
  }
}
"""


def _node(write_tree, main: str) -> dict[str, list[str]]:
    root = write_tree({"scanner/package.xml": package_xml("scanner"),
                       "scanner/src/mockup.h": MOCKUP_H,
                       "scanner/src/mockup.cpp": MOCKUP_CPP,
                       "scanner/src/main.cpp": main})
    result = extract_cpp([str(root / "scanner" / "src" / "main.cpp"),
                          str(root / "scanner" / "src" / "mockup.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert all(getattr(c, "built_in", None) is None for c in result.calls)
    return {c.name: [f"{k.statement} {k.text}" for k in c.conditions]
            for c in result.calls if c.kind == "subscribe"}


def test_the_construction_s_condition_in_another_file(write_tree) -> None:
    found = _node(write_tree, SCANNER_MAIN)
    assert found["datagram"] == ["while ros::ok()", "if subscribe_datagram"]


def test_a_construction_in_another_file_without_condition(write_tree) -> None:
    # also made before the loop, unconditionally: the calls as they are
    found = _node(write_tree, SCANNER_MAIN.replace(
        "  Scanner * s = nullptr;\n", "  Scanner * s = new Mockup();\n"))
    assert found["datagram"] == []


SETUP_H = MOCKUP_H.replace("  Mockup();\n", "  Mockup();\n  void setup();\n")
SETUP_CPP = """
#include "mockup.h"
Mockup::Mockup()
{
  setup();
}
void Mockup::setup()
{
  sub_ = nh_.subscribe("datagram", 1, &Mockup::datagramCB, this);
}
"""


def _setup_node(write_tree, main: str, one_file: bool = False) -> dict[str, list[str]]:
    files = {"scanner/package.xml": package_xml("scanner"),
             "scanner/src/mockup.h": SETUP_H,
             "scanner/src/main.cpp": main + (SETUP_CPP.replace('#include "mockup.h"', "")
                                             if one_file else "")}
    if not one_file:
        files["scanner/src/mockup.cpp"] = SETUP_CPP
    root = write_tree(files)
    sources = [str(root / "scanner" / "src" / name)
               for name in ("main.cpp", *(() if one_file else ("mockup.cpp",)))]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None)
    return {c.name: [f"{k.statement} {k.text}" for k in c.conditions]
            for c in result.calls if c.kind == "subscribe"}


def test_the_calls_of_a_method_the_constructor_calls_carry_the_construction_s_condition(
        write_tree) -> None:
    """OrbbecSDK_ROS2's driver builds its OBLidarNode only ``if (device_type_ ==
    "lidar")``; the lidar's constructor calls ``setupTopics()``, which makes its
    publishers: they were said to exist in a camera's configuration too. (The loop
    around the construction is no condition of them, as of any function's calls.)"""
    assert _setup_node(write_tree, SCANNER_MAIN)["datagram"] == ["if subscribe_datagram"]
    assert _setup_node(write_tree, SCANNER_MAIN, one_file=True)["datagram"] == [
        "if subscribe_datagram"]


def test_a_method_the_constructor_calls_of_a_class_also_built_unconditionally(
        write_tree) -> None:
    main = SCANNER_MAIN.replace("  Scanner * s = nullptr;\n", "  Scanner * s = new Mockup();\n")
    assert _setup_node(write_tree, main)["datagram"] == []
    assert _setup_node(write_tree, main, one_file=True)["datagram"] == []


SMOOTHERS_H = """
#include <rclcpp/rclcpp.hpp>
class Smoother { public: virtual ~Smoother() = default; };
class L2 : public Smoother { public: explicit L2(rclcpp::Node & node); double w_; };
class Jerk : public Smoother { public: explicit Jerk(rclcpp::Node & node); double w_; };
"""

SMOOTHERS_CPP = """
#include "smoothers.h"
L2::L2(rclcpp::Node & node) { w_ = node.declare_parameter<double>("pseudo_jerk_weight"); }
Jerk::Jerk(rclcpp::Node & node) { w_ = node.declare_parameter<double>("jerk_weight"); }
"""

INFO_H = """
#include <rclcpp/rclcpp.hpp>
namespace vehicle { class Info { public: explicit Info(rclcpp::Node & node); double length; }; }
"""

SMOOTHER_NODE = """
#include <memory>
#include <vehicle/info.h>
#include "smoothers.h"
enum class Algorithm { JERK, L2 };
Algorithm algorithm(const std::string & name)
{
  return name == "l2" ? Algorithm::L2 : Algorithm::JERK;
}
class Node : public rclcpp::Node {
public:
  Node() : rclcpp::Node("smoother") {
    length_ = vehicle::Info(*this).length;
    switch (algorithm(declare_parameter<std::string>("algorithm_type"))) {
      case Algorithm::JERK: { smoother_ = std::make_shared<Jerk>(*this); break; }
      case Algorithm::L2: { smoother_ = std::make_shared<L2>(*this); break; }
    }
  }
  double length_;
  std::shared_ptr<Smoother> smoother_;
};
"""


def test_the_construction_s_condition_with_the_node_handed_to_another_package(
        write_tree) -> None:
    """The node handed to a class of another package whose code is not read
    (``CPP_NODE_PASSED``, Autoware's ``VehicleInfoUtils(*this)``) may build what that
    package can name, not the node's own package's classes: each smoother's
    declarations keep the ``case`` it is built in (autoware_velocity_smoother built one
    of four smoothers by its ``algorithm_type``; all four declared their parameters
    unconditionally)."""
    root = write_tree({
        "smoother/package.xml": package_xml("smoother", "ament_cmake").replace(
            "<export>", "<depend>rclcpp</depend><depend>vehicle</depend><export>"),
        "smoother/src/smoothers.h": SMOOTHERS_H,
        "smoother/src/smoothers.cpp": SMOOTHERS_CPP,
        "smoother/src/node.cpp": SMOOTHER_NODE,
        "vehicle/package.xml": package_xml("vehicle", "ament_cmake"),
        "vehicle/include/vehicle/info.h": INFO_H})
    result = extract_cpp([str(root / "smoother" / "src" / "node.cpp"),
                          str(root / "smoother" / "src" / "smoothers.cpp")],
                         scan([str(root)]), cache_dir=None)
    assert "CPP_NODE_PASSED" in [d.code for d in result.diagnostics]
    found = {c.name: [k.statement for k in c.conditions]
             for c in result.calls if c.kind == "declare"}
    assert found == {"algorithm_type": [], "pseudo_jerk_weight": ["switch"],
                     "jerk_weight": ["switch"]}
