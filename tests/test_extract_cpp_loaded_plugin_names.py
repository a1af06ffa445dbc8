"""A host's calls named by each plugin it loaded: a loop over the container in which
the host keeps its plugin objects, naming a call with the name each object returns.
navigation2's Costmap2DROS (from 1.3) walks ``layered_costmap_->getPlugins()`` and
makes a ``Costmap2DPublisher`` (another file) per layer, on the topic
``layer->getName()``; that publisher was wholly ``?``, so every absence check about a
costmap or map topic of a nav2 system stayed undecided. The extraction marks the
call (``PrimitiveCall.name_each`` ``LOADED``: the container's accessor and the
element's method); the graph makes it once per plugin the host row says the
instance keeps there, named by the plugin's name (``graph.build.element_calls``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.model.source import LOADED
from haros_arch.workspace import scan
from tests.conftest import package_xml

STACK_H = """
#pragma once
#include <memory>
#include <string>
#include <vector>
namespace demo {
class Layer {
public:
  virtual ~Layer() {}
  void initialize(const std::string & name) { name_ = name; }
  std::string getName() const { return name_; }
  std::string getTopic() const { return topic_; }
protected:
  std::string name_;
  std::string topic_;
};
class Costed : public Layer {};
class Stack {
public:
  std::vector<std::shared_ptr<Layer>> * getLayers() { return &layers_; }
  std::vector<std::shared_ptr<Layer>> & others() { return others_; }
private:
  std::vector<std::shared_ptr<Layer>> layers_;
  std::vector<std::shared_ptr<Layer>> others_;
};
}  // namespace demo
"""

PUB_H = """
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/int32.hpp>
namespace demo {
class Pub {
public:
  Pub(rclcpp::Node * node, const std::string & topic);
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
};
}  // namespace demo
"""

PUB = """
#include "demo/pub.hpp"
namespace demo {
Pub::Pub(rclcpp::Node * node, const std::string & topic)
{
  pub_ = node->create_publisher<std_msgs::msg::Int32>(topic, 1);
}
}  // namespace demo
"""

HOST = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/int32.hpp>
#include "demo/stack.hpp"
#include "demo/pub.hpp"
class Host : public rclcpp::Node {
public:
  Host() : rclcpp::Node("host") {
    auto layers = stack_->getLayers();
    for (auto & layer : *layers) {
      pubs_.push_back(std::make_unique<demo::Pub>(this, layer->getName()));
      own_.push_back(create_publisher<std_msgs::msg::Int32>(layer->getName() + "_raw", 1));
      topics_.push_back(create_publisher<std_msgs::msg::Int32>(layer->getTopic(), 1));
      auto costed = std::dynamic_pointer_cast<demo::Costed>(layer);
      if (costed != nullptr) {
        pubs_.push_back(std::make_unique<demo::Pub>(this, layer->getName() + "/c"));
      }
      if (auto held = std::dynamic_pointer_cast<demo::Costed>(layer)) {
        pubs_.push_back(std::make_unique<demo::Pub>(this, layer->getName() + "/d"));
      }
    }
    for (auto & other : stack_->others()) {
      pubs_.push_back(std::make_unique<demo::Pub>(this, other->getName() + "/o"));
    }
  }
  std::unique_ptr<demo::Stack> stack_;
  std::vector<std::unique_ptr<demo::Pub>> pubs_;
  std::vector<rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr> own_, topics_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Host>());
}
"""


def test_a_name_each_kept_plugin_returns_is_marked(write_tree) -> None:
    root = write_tree({"demo/package.xml": package_xml("demo", "ament_cmake"),
                       "demo/include/demo/stack.hpp": STACK_H,
                       "demo/include/demo/pub.hpp": PUB_H,
                       "demo/src/pub.cpp": PUB, "demo/src/host.cpp": HOST})
    result = extract_cpp([str(root / "demo" / "src" / "host.cpp"),
                          str(root / "demo" / "src" / "pub.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    made = sorted((c.name, c.name_param, c.name_each) for c in result.calls
                  if c.kind == "publish" and not c.name.startswith("~"))
    layers = f"{LOADED}demo::Stack::getLayers demo::Layer::getName"
    others = f"{LOADED}demo::Stack::others demo::Layer::getName"
    assert made == [
        ("?", None, layers),  # through another file's constructor
        # another method of the element: marked with it (the host row names the one
        # that returns the plugin's name)
        ("?", None, f"{LOADED}demo::Stack::getLayers demo::Layer::getTopic"),
        ("?/c", None, f"{layers} demo::Costed"),  # only a layer of that class
        ("?/d", None, f"{layers} demo::Costed"),  # (the test's own declaration)
        ("?/o", None, others),
        ("?_raw", None, layers),  # made in the loop itself
    ], made


CLASSES = {"nav2_costmap_2d::StaticLayer": "class CostmapLayer : public Layer {};\n"
                                            "class StaticLayer : public CostmapLayer {};\n",
           "nav2_costmap_2d::InflationLayer": "class InflationLayer : public Layer {};\n",
           "nav2_costmap_2d::KeepoutFilter": "class KeepoutFilter : public Layer {};\n"}


def _costmap_links(decl, params, calls, root=None):
    from haros_arch.graph import build
    from haros_arch.launch.model import LaunchModel, ParamDecl
    from haros_arch.model import Configuration, Location, Node, PrimitiveCall
    from haros_arch.workspace import Workspace

    def plugin(cls, *made):
        sources = []
        if root is not None:  # the class's declaration, with its bases
            source = root / (cls.rsplit(":", 1)[-1] + ".cpp")
            source.write_text("namespace nav2_costmap_2d {\n" + CLASSES[cls] + "}\n")
            sources.append(str(source))
        return Node("nav2_costmap_2d", cls, "plugin", calls=list(made), plugin_class=cls,
                    sources=sources)

    where = Location("nav2_costmap_2d", "nav2_costmap_2d/src/costmap_2d_ros.cpp", 9, 3)
    costmap = Node("nav2_costmap_2d", "nav2_costmap_2d", calls=[
        PrimitiveCall(kind, name, "nav_msgs/msg/OccupancyGrid", location=where,
                      name_each=each) for kind, name, each in calls])
    layers = [plugin("nav2_costmap_2d::StaticLayer"), plugin("nav2_costmap_2d::KeepoutFilter"),
              plugin("nav2_costmap_2d::InflationLayer")]
    launch = LaunchModel(nodes=[decl], params=[ParamDecl(name, value) for name, value in params])
    config = build(Configuration("c"), launch, Workspace(root=str(root or "/nowhere")),
                   {n.name: n for n in [costmap, *layers]})
    return sorted((link.kind, link.resource.name, tuple(c.text for c in link.conditions))
                  for link in config.links if link.kind == "publish")


PER_LAYER = f"{LOADED}nav2_costmap_2d::LayeredCostmap::getPlugins nav2_costmap_2d::Layer::getName"
CALLS = [("publish", "?", PER_LAYER), ("publish", "?_raw", PER_LAYER),
         ("publish", "costmap", None),
         # another method of the layer, another container: not what the row says
         ("publish", "?", f"{LOADED}nav2_costmap_2d::LayeredCostmap::getPlugins "
                          "nav2_costmap_2d::Layer::getTopic"),
         ("publish", "?", f"{LOADED}nav2_costmap_2d::Other::getPlugins "
                          "nav2_costmap_2d::Layer::getName")]


def test_a_costmap_publishes_one_topic_per_layer_it_loads() -> None:
    from haros_arch.launch.model import NodeDecl
    decl = NodeDecl("/planner_server", "nav2_planner", "planner_server", ros_version=2)
    costmap = "/global_costmap/global_costmap"
    params = [(f"{costmap}/plugins", ["static_layer", "inflation_layer"]),
              (f"{costmap}/static_layer.plugin", "nav2_costmap_2d::StaticLayer"),
              (f"{costmap}/inflation_layer.plugin", "nav2_costmap_2d::InflationLayer"),
              (f"{costmap}/filters", ["keepout_filter"]),
              (f"{costmap}/keepout_filter.plugin", "nav2_costmap_2d::KeepoutFilter")]
    assert _costmap_links(decl, params, CALLS) == [
        ("publish", "/global_costmap/costmap", ()),
        ("publish", "/global_costmap/inflation_layer", ()),
        ("publish", "/global_costmap/inflation_layer_raw", ()),
        ("publish", "/global_costmap/static_layer", ()),
        ("publish", "/global_costmap/static_layer_raw", ()),
        ("publish", "?", ()), ("publish", "?", ()),  # (a name beginning unknown may be global)
    ]
    # no layer: no such topic
    assert _costmap_links(decl, [(f"{costmap}/plugins", [])], CALLS[:3]) == [
        ("publish", "/global_costmap/costmap", ())]


def test_a_standalone_costmap_names_its_layers_topics_too() -> None:
    from haros_arch.launch.model import NodeDecl
    decl = NodeDecl("/costmap/costmap", "nav2_costmap_2d", "nav2_costmap_2d", ros_version=2,
                    namespace="/costmap/")
    # without ``plugins``: the default layers
    assert _costmap_links(decl, [], CALLS[:1]) == [
        ("publish", "/costmap/inflation_layer", ()), ("publish", "/costmap/obstacle_layer", ()),
        ("publish", "/costmap/static_layer", ())]


def test_only_the_layers_of_the_class_the_loop_tests_publish(tmp_path) -> None:
    # Costmap2DROS publishes a layer only ``if (costmap_layer != nullptr)``, of
    # ``std::dynamic_pointer_cast<CostmapLayer>(layer)``: the inflation layer is none
    from haros_arch.launch.model import NodeDecl
    decl = NodeDecl("/costmap/costmap", "nav2_costmap_2d", "nav2_costmap_2d", ros_version=2,
                    namespace="/costmap/")
    params = [("/costmap/costmap/plugins", ["static_layer", "inflation_layer"]),
              ("/costmap/costmap/static_layer.plugin", "nav2_costmap_2d::StaticLayer"),
              ("/costmap/costmap/inflation_layer.plugin", "nav2_costmap_2d::InflationLayer")]
    tested = [("publish", "?", f"{PER_LAYER} nav2_costmap_2d::CostmapLayer")]
    assert _costmap_links(decl, params, tested, tmp_path) == [
        ("publish", "/costmap/static_layer", ())]
    # classes whose bases are not known: each made under the test, undecided
    assert _costmap_links(decl, params, tested) == [
        ("publish", "/costmap/inflation_layer",
         ("inflation_layer is a nav2_costmap_2d::CostmapLayer",)),
        ("publish", "/costmap/static_layer",
         ("static_layer is a nav2_costmap_2d::CostmapLayer",))]
