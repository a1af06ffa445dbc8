"""A name that is each word of a string parameter: costmap_2d reads its
``observation_sources`` and walks it word by word (``std::stringstream ss(sources);
while (ss >> source)``), moving each source's old parameters (``move_parameter(nh,
obstacles, source)``, a wrapper taking the word by value) and naming one subscription per
source. The calls were named ``?`` (any parameter of the node, so move_base's every
setting was undecided); they now carry the parameter (``name_param``) and ``WORDS``
(``name_each``), and the graph makes one call per word of the value the configuration
gives it, or of the code's default (none for an empty one)."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.model.source import WORDS
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import Workspace

SOURCE = """#include <ros/ros.h>
#include <sstream>
#include <string>
#include <std_msgs/String.h>

void cb(const std_msgs::String::ConstPtr&) {}

void move_parameter(ros::NodeHandle& old_h, ros::NodeHandle& new_h, std::string name)
{
  if (!old_h.hasParam(name))
    return;
  XmlRpc::XmlRpcValue value;
  old_h.getParam(name, value);
  new_h.setParam(name, value);
  old_h.deleteParam(name);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("~");
  ros::NodeHandle obstacles(nh, "obstacle_layer");
  std::string s;
  nh.param("observation_sources", s, std::string(""));
  std::stringstream ss(s);
  std::string source;
  while (ss >> source)
  {
    move_parameter(nh, obstacles, source);
    ros::Subscriber sub = nh.subscribe(source + "/points", 1, cb);
  }
  return 0;
}
"""


def test_each_word_of_a_string_parameter_names_the_calls_of_the_loop(tmp_path) -> None:
    (tmp_path / "n.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "n.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    got = sorted((c.location.line, c.kind, c.name, c.name_param, c.name_each,
                  tuple(x.statement for x in c.conditions)) for c in result.calls)
    each = ("~observation_sources", WORDS, ("for each",))
    # the copy and the delete follow ``if (!old_h.hasParam(name)) return;``: its else
    copied = ("~observation_sources", WORDS, ("for each", "else"))
    assert got == [(24, "read", "~observation_sources", None, None, ()),
                   (29, "read", "~?", *each), (29, "write", "~?", *copied),
                   (29, "write", "~obstacle_layer/?", *copied),
                   (30, "subscribe", "~?/points", *each)]


MODEL = {
    "schema": "haros-arch-model/2", "package": "cm", "distro": "noetic", "nodes": [{
        "package": "cm", "executable": "cm", "rosname": "cm", "calls": [
            {"kind": "read", "name": "~observation_sources", "type": "string",
             "has_default": True, "default": ""},
            {"kind": "read", "name": "~?", "name_param": "~observation_sources",
             "name_each": WORDS},
            {"kind": "write", "name": "~obstacle_layer/?",
             "name_param": "~observation_sources", "name_each": WORDS},
            {"kind": "subscribe", "name": "~?/points", "type": "std_msgs/String",
             "name_param": "~observation_sources", "name_each": WORDS}]}]}

LAUNCH = """
<launch>
  <node pkg="cm" type="cm" name="costmap">
    <param name="observation_sources" value="scan  bump"/>
    <rosparam>scan: {data_type: LaserScan}</rosparam>
  </node>
  <node pkg="cm" type="cm" name="plain"/>
</launch>
"""


def test_the_graph_makes_one_call_per_word(write_tree) -> None:
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/cm.launch": LAUNCH,
        "models/cm.json": json.dumps(MODEL),
        "project.yaml": "project: p\nmodels: [models]\n"
                        "configurations:\n  c:\n    launch: [robot/launch/cm.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    links = {n.name: sorted((link.kind, link.name) for link in n.links)
             for n in config.nodes}
    assert links["/costmap"] == [
        ("read", "/costmap/bump"), ("read", "/costmap/observation_sources"),
        ("read", "/costmap/scan"), ("subscribe", "/costmap/bump/points"),
        ("subscribe", "/costmap/scan/points"), ("write", "/costmap/obstacle_layer/bump"),
        ("write", "/costmap/obstacle_layer/scan")]
    # nothing sets it: the code's default, an empty string, walks no word
    assert links["/plain"] == [("read", "/plain/observation_sources")]
    # the source's settings are read (as a part of ~scan): not "set but never read"
    scan = next(p for p in config.parameters if p.name == "/costmap/scan/data_type")
    assert scan.read_as_part_of is not None
    assert scan.read_as_part_of.name == "/costmap/scan"


HEADER = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

class Map
{
public:
  explicit Map(const std::string& name);
  void cb(const std_msgs::String::ConstPtr&) {}
  ros::Subscriber sub_;
};
"""

CLASS = """#include "cm.h"

Map::Map(const std::string& name)
{
  ros::NodeHandle nh("~/" + name);
  std::string topic;
  nh.param("topic", topic, std::string("map"));
  sub_ = nh.subscribe(topic, 1, &Map::cb, this);
}
"""

MAIN = """#include "cm.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "maps");
  Map global("global");
  Map local("local");
  ros::spin();
  return 0;
}
"""


def test_the_parameter_that_names_a_call_takes_the_same_caller_as_its_name(
        tmp_path) -> None:
    """move_base builds two Costmap2DROS, ``global_costmap`` and ``local_costmap``, in
    another file than the class: each subscription is named by the parameter of its own
    costmap (``~global/topic``), as its name is filled from the same call site; it was
    ``~?/topic`` for both (the callers pass two names), so no launch value reached it."""
    for name, text in (("cm.h", HEADER), ("cm.cpp", CLASS), ("main.cpp", MAIN)):
        (tmp_path / name).write_text(text)
    result = extract_cpp([str(tmp_path / "main.cpp"), str(tmp_path / "cm.cpp")],
                         Workspace(root=str(tmp_path)), cache_dir=None)
    assert sorted((c.kind, c.name, c.name_param) for c in result.calls) == [
        ("read", "~global/topic", None), ("read", "~local/topic", None),
        ("subscribe", "~global/?", "~global/topic"),
        ("subscribe", "~local/?", "~local/topic")]
