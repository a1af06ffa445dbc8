"""A call made through a wrapper is under the call site's conditions and under those it
is under inside the wrapper (and inside each wrapper of a chain, the outermost first):
``make()`` that advertises a second topic only ``if (use_extra_)`` makes it only there.
The graph decides them as it decides a call's own: a member that holds a parameter
drops the link where the parameter is false."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

NODE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <string>

    class Node {
     public:
      Node() : pnh_("~") {
        pnh_.param("use_extra", use_extra_, false);
        pnh_.param("latched", latched_, false);
        main_ = make("out", 5);
        if (pnh_.hasParam("debug")) {
          debug_ = make("debug_out", 1);
        }
        chained_ = outer("chain");
      }

     private:
      ros::Publisher make(const std::string& topic, int queue) {
        if (use_extra_) {
          extra_ = nh_.advertise<std_msgs::String>(topic + "_extra", 1);
        }
        return nh_.advertise<std_msgs::String>(topic, queue);
      }
      ros::Publisher inner(const std::string& topic) {
        if (latched_) {
          return nh_.advertise<std_msgs::String>(topic, 1, true);
        } else {
          return nh_.advertise<std_msgs::String>(topic, 10);
        }
      }
      ros::Publisher outer(const std::string& topic) {
        for (int i = 0; i < 2; ++i) {
          if (use_extra_) {
            return inner(topic);
          }
        }
        return ros::Publisher();
      }
      ros::NodeHandle nh_, pnh_;
      bool use_extra_, latched_;
      ros::Publisher main_, debug_, extra_, chained_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "node");
      Node n;
      ros::spin();
    }
    """

LAUNCH = """
    <launch>
      <node pkg="wrapped" type="node" name="plain"/>
      <node pkg="wrapped" type="node" name="extra">
        <param name="use_extra" value="true"/>
      </node>
    </launch>
    """


def _workspace(write_tree):
    return write_tree({
        "src/wrapped/package.xml": package_xml("wrapped"),
        "src/wrapped/CMakeLists.txt": "project(wrapped)\nadd_executable(node src/node.cpp)\n",
        "src/wrapped/src/node.cpp": NODE,
        "src/wrapped/launch/two.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [wrapped/launch/two.launch]\n",
    })


def test_a_wrappers_own_conditions_go_with_each_call_it_makes(write_tree):
    root = _workspace(write_tree)
    result = extract_cpp([str(root / "src/wrapped/src/node.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.name, c.queue_size, tuple((k.statement, k.text) for k in c.conditions))
                   for c in result.calls if c.kind == "publish")
    assert calls == [
        ("chain", 1, (("if", "use_extra_"), ("if", "latched_"))),
        ("chain", 10, (("if", "use_extra_"), ("else", "latched_"))),
        ("debug_out", 1, (("if", 'pnh_.hasParam("debug")'),)),
        ("debug_out_extra", 1, (("if", 'pnh_.hasParam("debug")'), ("if", "use_extra_"))),
        ("out", 5, ()),
        ("out_extra", 1, (("if", "use_extra_"),)),
    ]
    # the condition is where the wrapper writes it
    extra = next(c for c in result.calls if c.name == "out_extra")
    assert [k.location.line for k in extra.conditions] == [19]


def test_the_graph_decides_them_per_instance(write_tree):
    model = analyse(load(str(_workspace(write_tree) / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")

    def published(node: str) -> set[str]:
        return {link.rosname.own for link in config.links
                if link.node.name == node and link.kind == "publish"}

    assert published("/plain") == {"out"}  # use_extra defaults to false
    assert published("/extra") == {"out", "out_extra", "chain"}
    said = [d.message for d in config.diagnostics if d.code == "CONDITION_FALSE"]
    assert any("/plain: no publish /out_extra" in m and "use_extra_" in m for m in said)


NODE2 = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    template<typename NodeT>
    void declare_once(NodeT node, const std::string & name, const rclcpp::ParameterValue & v)
    {
      if (!node->has_parameter(name)) {
        node->declare_parameter(name, v);
      }
    }

    class Once : public rclcpp::Node {
     public:
      Once() : Node("once") {
        if (!this->has_parameter("direct")) {
          this->declare_parameter("direct", 1);
        }
        if (!has_parameter("other")) {
          declare_parameter("guarded", 1);
        }
        declare_once(this, "wrapped", rclcpp::ParameterValue(2));
      }
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Once>());
    }
    """


def test_a_declaration_unless_declared_is_no_condition(write_tree):
    """``if (!node->has_parameter(n)) node->declare_parameter(n, v)``: the parameter is
    declared after it either way (rclcpp throws on a second declaration), written in
    the node or in a wrapper; a test of another parameter stays a condition."""
    root = write_tree({
        "src/once/package.xml": package_xml("once", "ament_cmake"),
        "src/once/CMakeLists.txt": "project(once)\nadd_executable(once src/once.cpp)\n",
        "src/once/src/once.cpp": NODE2,
    })
    result = extract_cpp([str(root / "src/once/src/once.cpp")], scan([str(root)]),
                         cache_dir=None)
    declared = {c.name: [k.text for k in c.conditions] for c in result.calls
                if c.kind == "declare"}
    assert declared == {"direct": [], "guarded": ['!has_parameter("other")'],
                        "wrapped": []}


MOVER = """
    #include <ros/ros.h>
    #include <string>

    void move_parameter(ros::NodeHandle& old_h, ros::NodeHandle& new_h,
                        const std::string& name, bool should_delete = true, int level = 1)
    {
      if (!old_h.hasParam(name))
        return;
      XmlRpc::XmlRpcValue value;
      old_h.getParam(name, value);
      new_h.setParam(name, value);
      if (should_delete) old_h.deleteParam(name);
      if (level > 2 && should_delete) new_h.deleteParam(name + "_old");
    }

    void reset_parameter(ros::NodeHandle& h, const std::string& name, bool keep)
    {
      keep = keep || h.hasParam("keep_all");
      if (!keep) h.deleteParam(name);
    }

    int main(int argc, char** argv)
    {
      ros::init(argc, argv, "mover");
      ros::NodeHandle nh, layer(nh, "layer");
      move_parameter(nh, layer, "moved");
      move_parameter(nh, layer, "copied", false);
      move_parameter(nh, layer, "deep", true, 3);
      reset_parameter(nh, "reset", false);
    }
    """


def test_a_condition_on_the_wrappers_parameter_is_decided_at_each_call_site(write_tree):
    """``if (should_delete)`` in the wrapper: the call site's literal (or the
    parameter's default) decides it, as the graph decides a condition; a parameter the
    wrapper assigns itself is not taken from the call site."""
    root = write_tree({
        "src/mover/package.xml": package_xml("mover"),
        "src/mover/CMakeLists.txt": "project(mover)\nadd_executable(mover src/mover.cpp)\n",
        "src/mover/src/mover.cpp": MOVER,
    })
    result = extract_cpp([str(root / "src/mover/src/mover.cpp")], scan([str(root)]),
                         cache_dir=None)
    deleted = {c.name: tuple(k.text for k in c.conditions) for c in result.calls
               if c.kind == "write" and c.deletes}
    # (after ``if (!old_h.hasParam(name)) return;``: under its else)
    moved = ("!old_h.hasParam(name)",)
    assert deleted == {"moved": moved, "deep": moved, "layer/deep_old": moved,
                       "reset": ("!keep",)}
