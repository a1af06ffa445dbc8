"""A name, or a condition, made of a field of each element of a ROS 1 list parameter in
turn: costmap_2d reads ``plugins`` (an XmlRpcValue array of structs), and for each
element ``copyParentParameters(static_cast<std::string>(plugins[i]["name"]), type, nh)``
copies the costmap's old parameters into ``<name>/`` under ``if (plugin_type ==
"costmap_2d::StaticLayer")`` and the like, ``plugin_type`` the element's ``type``. The
copies were ``~global_costmap/?/map_topic`` under conditions the graph could not
decide, so every parameter of every move_base configuration set at a costmap's level
was undecided. Each call is now one per element of the list the launch file gives, its
conditions decided with that element's fields."""

from __future__ import annotations

import json

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.cache import conditions_of_text, conditions_text
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.model.conditions import Condition
from haros_arch.model.load import conditions as load_conditions
from haros_arch.model.values import Unknown
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

COSTMAP = """
#include <string>
#include <vector>
#include <ros/ros.h>
#include <std_msgs/String.h>

void move_parameter(ros::NodeHandle& old_h, ros::NodeHandle& new_h, std::string name,
                    bool should_delete = true)
{
  if (!old_h.hasParam(name))
    return;
  XmlRpc::XmlRpcValue value;
  old_h.getParam(name, value);
  new_h.setParam(name, value);
  if (should_delete) old_h.deleteParam(name);
}

class Costmap {
 public:
  Costmap(const std::string& name) {
    ros::NodeHandle private_nh("~/" + name);
    if (private_nh.hasParam("plugins"))
    {
      XmlRpc::XmlRpcValue my_list;
      private_nh.getParam("plugins", my_list);
      for (int32_t i = 0; i < my_list.size(); ++i)
      {
        std::string pname = static_cast<std::string>(my_list[i]["name"]);
        std::string type = static_cast<std::string>(my_list[i]["type"]);
        copyParentParameters(pname, type, private_nh);
        ros::NodeHandle layer(private_nh, pname);
        ros::Publisher p = layer.advertise<std_msgs::String>("out", 1);
        ros::Publisher q = private_nh.advertise<std_msgs::String>(
            static_cast<std::string>(my_list[i]["topic"]), 1);
      }
    }
    std::vector<std::string> names;
    private_nh.getParam("names", names);
    for (size_t i = 0; i < names.size(); ++i) {
      ros::NodeHandle each(private_nh, names[i]);
      ros::Publisher s = each.advertise<std_msgs::String>("state", 1);
    }
  }
  void copyParentParameters(const std::string& plugin_name, const std::string& plugin_type,
                            ros::NodeHandle& nh)
  {
    ros::NodeHandle target_layer(nh, plugin_name);
    if (plugin_type == "costmap_2d::StaticLayer")
    {
      move_parameter(nh, target_layer, "map_topic", false);
    }
    else if (plugin_type == "costmap_2d::InflationLayer")
    {
      move_parameter(nh, target_layer, "inflation_radius", false);
    }
  }
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "mb");
  Costmap g("global_costmap");
  ros::spin();
}
"""

PLUGINS = [{"name": "static", "type": "costmap_2d::StaticLayer", "topic": "a"},
           {"name": "obst", "type": "costmap_2d::ObstacleLayer", "topic": "b"}]


def _calls(write_tree):
    root = write_tree({"m/package.xml": package_xml("m", "catkin"),
                       "m/src/costmap.cpp": COSTMAP})
    result = extract_cpp([str(root / "m" / "src" / "costmap.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    return result.calls


def _graph(calls, params):
    node = Node("m", "costmap", calls=list(calls))
    return build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/mb", "m", "costmap", ros_version=1)],
        params=[ParamDecl(name, value) for name, value in params]),
        Workspace(root="/nowhere"), {node.name: node})


def test_names_from_a_field_of_each_element(write_tree) -> None:
    calls = _calls(write_tree)
    named = sorted({(c.kind, c.name, c.name_param, c.name_each) for c in calls
                    if c.kind in ("publish", "write")})
    assert named == [
        ("publish", "~global_costmap/?", "~global_costmap/plugins", "topic"),
        ("publish", "~global_costmap/?/out", "~global_costmap/plugins", "name"),
        ("publish", "~global_costmap/?/state", "~global_costmap/names", "."),
        ("write", "~global_costmap/?/inflation_radius", "~global_costmap/plugins", "name"),
        ("write", "~global_costmap/?/map_topic", "~global_costmap/plugins", "name")]
    copied = [c for c in calls if c.kind == "read" and c.name == "~global_costmap/map_topic"]
    assert copied
    tested = [k for c in copied for k in c.conditions if "plugin_type" in k.text]
    assert tested and all(k.elements == (("plugin_type", "~global_costmap/plugins", "type"),)
                          for k in tested)


def test_conditions_decided_per_element(write_tree) -> None:
    config = _graph(_calls(write_tree), [
        ("/mb/global_costmap/plugins", PLUGINS), ("/mb/global_costmap/names", ["x"]),
        ("/mb/global_costmap/map_topic", "map"),
        ("/mb/global_costmap/inflation_radius", 0.3)])
    links = {(k.kind, k.rosname.full, bool(k.conditions)) for k in config.links
             if k.kind in ("publish", "read", "write")
             and not k.rosname.full.endswith("/plugins") and not k.rosname.full.endswith(
                 "/names")}
    assert links == {
        ("publish", "/mb/global_costmap/static/out", False),
        ("publish", "/mb/global_costmap/obst/out", False),
        ("publish", "/mb/global_costmap/a", False),
        ("publish", "/mb/global_costmap/b", False),
        ("publish", "/mb/global_costmap/x/state", False),
        # the static layer's turn copies map_topic; no turn copies inflation_radius
        ("read", "/mb/global_costmap/map_topic", False),
        ("write", "/mb/global_costmap/static/map_topic", False)}
    said = [d.message for d in config.diagnostics if d.code == "CONDITION_FALSE"]
    # the read made in the static layer's turn is there: no word of the other turn's
    assert not any("no read /mb/global_costmap/map_topic " in m for m in said)
    assert any("no read /mb/global_costmap/inflation_radius " in m for m in said)
    assert any("no write /mb/global_costmap/obst/map_topic " in m for m in said)


def test_list_not_known_leaves_the_calls_undecided(write_tree) -> None:
    # set, to a value the launch file does not tell (a substitution not known)
    config = _graph(_calls(write_tree), [("/mb/global_costmap/plugins", Unknown("$(x)")),
                                         ("/mb/global_costmap/map_topic", "map")])
    reads = [k for k in config.links if k.kind == "read"
             and k.rosname.full == "/mb/global_costmap/map_topic"]
    assert reads and all(any("plugin_type" in c.text for c in k.conditions) for k in reads)


def test_element_conditions_read_back_from_a_saved_model() -> None:
    data = json.loads(json.dumps([{
        "text": 'plugin_type == "costmap_2d::StaticLayer"', "statement": "if",
        "elements": [["plugin_type", "~plugins", "type"]],
        "constants": [["level", 1], ["kind", "a"]]}]))
    (condition,) = load_conditions(data)
    assert condition.elements == (("plugin_type", "~plugins", "type"),)
    assert condition.constants == (("level", 1), ("kind", "a"))


HEADER = """
#include <string>
#include <ros/ros.h>
class Costmap {
 public:
  Costmap(const std::string& name);
  void copyParentParameters(const std::string& plugin_name, const std::string& plugin_type,
                            ros::NodeHandle& nh);
};
"""


def test_list_read_on_a_handle_another_file_names(write_tree) -> None:
    # the costmap is a library class, its name given by the node's file (move_base's
    # ``new Costmap2DROS("global_costmap", tf_)``): the list's name, and so the names of
    # the copies and the lists of their conditions, are filled from that file's value
    library = COSTMAP.split("int main")[0]
    library = library.replace("class Costmap {\n public:\n  Costmap(const std::string& name) {",
                              '#include "m/costmap.h"\nCostmap::Costmap(const std::string& name) {')
    library = library.replace("  void copyParentParameters(", "void Costmap::copyParentParameters(")
    library = library.rstrip().removesuffix("};")
    main = '#include "m/costmap.h"\nint main' + COSTMAP.split("int main")[1]
    root = write_tree({"m/package.xml": package_xml("m", "catkin"),
                       "m/include/m/costmap.h": HEADER, "m/src/costmap.cpp": library,
                       "m/src/node.cpp": main})
    result = extract_cpp([str(root / "m" / "src" / f) for f in ("costmap.cpp", "node.cpp")],
                         scan([str(root)]), cache_dir=None, jobs=1)
    writes = sorted((c.name, c.name_param, c.name_each) for c in result.calls
                    if c.kind == "write")
    assert writes == [
        ("~global_costmap/?/inflation_radius", "~global_costmap/plugins", "name"),
        ("~global_costmap/?/map_topic", "~global_costmap/plugins", "name")]
    tested = [k for c in result.calls for k in c.conditions if "plugin_type" in k.text]
    assert tested and all(k.elements == (("plugin_type", "~global_costmap/plugins", "type"),)
                          for k in tested)
    config = _graph(result.calls, [("/mb/global_costmap/plugins", PLUGINS),
                                   ("/mb/global_costmap/map_topic", "map")])
    copies = {(k.kind, k.rosname.full) for k in config.links if k.kind in ("read", "write")
              and k.rosname.full.endswith(("map_topic", "inflation_radius"))}
    assert copies == {("read", "/mb/global_costmap/map_topic"),
                      ("write", "/mb/global_costmap/static/map_topic")}
    # move_parameter copies only what is set (``if (!old_h.hasParam(name)) return;``)
    config = _graph(result.calls, [("/mb/global_costmap/plugins", PLUGINS)])
    assert not [k for k in config.links if k.kind == "write"]


def test_element_conditions_kept_by_the_unit_cache() -> None:
    condition = Condition('plugin_type == "a"', elements=(("plugin_type", "~plugins", "type"),),
                          constants=(("level", 1),))
    assert conditions_of_text(conditions_text([condition])) == (condition,)


MIGRATED = """
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "mb");
  ros::NodeHandle nh("~");
  if (!nh.hasParam("plugins"))
  {
    nh.setParam("plugins", std::string("old"));
  }
  if (nh.hasParam("plugins"))
  {
    ros::Publisher p = nh.advertise<std_msgs::String>("out", 1);
  }
  ros::spin();
}
"""


def test_a_test_of_presence_after_the_node_may_have_set_it(write_tree) -> None:
    # costmap_2d migrates old parameters into ``plugins`` when it is not set, then tests
    # it again: set by the launch file (and deleted by nothing), it is there whatever
    # the node wrote; not set by it, the second test stays undecided
    root = write_tree({"m/package.xml": package_xml("m", "catkin"),
                       "m/src/costmap.cpp": MIGRATED})
    calls = extract_cpp([str(root / "m" / "src" / "costmap.cpp")], scan([str(root)]),
                        cache_dir=None, jobs=1).calls
    given = _graph(calls, [("/mb/plugins", PLUGINS)])
    (out,) = [k for k in given.links if k.kind == "publish"]
    assert out.rosname.full == "/mb/out" and not out.conditions
    unset = _graph(calls, [])
    (out,) = [k for k in unset.links if k.kind == "publish"]
    assert [c.text for c in out.conditions] == ['nh.hasParam("plugins")']
