"""A name a C++ node takes from a command-line option parsed with getopt / getopt_long
(pr2_ethercat's ``case 'r': g_options.rosparam_ = optarg;`` in a ``switch`` over
``getopt_long(argc, argv, "hi:usx:r:", long_options, &index)``, the parameter read in
another function) carries the option's flags and the program's options
(``PrimitiveCall.name_option``, ``name_getopt``), and the graph takes its value from the
instance's ``args`` by getopt's rules: ``-r X``, ``-rX``, ``-ur X``, ``--rosparam X``,
``--rosparam=X``, an unambiguous prefix, the last one given. Not given: the constant the
code wrote before the loop; a null pointer there names nothing (``std::string`` of it
throws). What getopt's table cannot tell (an option the program does not take) and a
variable written elsewhere stay unknown."""

from __future__ import annotations

import json
import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph.conditions import getopt_option
from haros_arch.model.runtime import NodeInstance
from haros_arch.models.format import dumps, from_document
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

LOOP = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <getopt.h>
#include <string>

static struct {
  char* rosparam_;
  char* xml_;
  bool stats_;
} g_options;

std::string g_desc;

void control() {
  ros::NodeHandle node;
  if (g_options.rosparam_ != NULL) {
    ros::param::get(g_options.rosparam_, g_desc);
  } else {
    node.getParam(g_options.xml_, g_desc);
  }
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "loop");
  g_options.xml_ = NULL;
  g_options.rosparam_ = NULL;
  const char* topic = "chatter";
  while (1) {
    static struct option long_options[] = {
      {"stats", no_argument, 0, 's'},
      {"xml", required_argument, 0, 'x'},
      {"rosparam", required_argument, 0, 'r'},
      {"topic", required_argument, 0, 't'},
      {0, 0, 0, 0},
    };
    int index = 0;
    int c = getopt_long(argc, argv, "sx:r:t:", long_options, &index);
    if (c == -1) break;
    switch (c) {
      case 's':
        g_options.stats_ = true;
        break;
      case 'x':
        g_options.xml_ = optarg;
        break;
      case 'r':
        g_options.rosparam_ = optarg;
        break;
      case 't':
        topic = optarg;
        break;
    }
  }
  ros::NodeHandle n;
  ros::Publisher pub = n.advertise<std_msgs::String>(topic, 1);
  control();
  return 0;
}
"""

# a variable getopt's loop sets that another function writes too: not known; a
# std::string built empty and set from optarg: the option, unknown when not given
ELSEWHERE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <unistd.h>
#include <string>

char* g_topic = NULL;
std::string g_frame;

void fallback() { g_topic = (char*)"other"; }

int main(int argc, char** argv) {
  ros::init(argc, argv, "elsewhere");
  int c;
  while ((c = getopt(argc, argv, "t:f:")) != -1) {
    switch (c) {
      case 't': g_topic = optarg; break;
      case 'f': g_frame = optarg; break;
      default: return 1;
    }
  }
  fallback();
  ros::NodeHandle n;
  ros::Publisher pub = n.advertise<std_msgs::String>(g_topic, 1);
  ros::Publisher frame = n.advertise<std_msgs::String>(g_frame + "/frame", 1);
  return 0;
}
"""

LAUNCH = """<launch>
  <node pkg="opt" type="loop" name="short" args="-r robot_description -t a"/>
  <node pkg="opt" type="loop" name="glued" args="-s -rdesc -tb"/>
  <node pkg="opt" type="loop" name="bundled" args="-sr desc -x ignored"/>
  <node pkg="opt" type="loop" name="long" args="--rosparam=desc --topic c"/>
  <node pkg="opt" type="loop" name="prefix" args="--rosp desc --to d"/>
  <node pkg="opt" type="loop" name="last" args="-r one -r two x:=y"/>
  <node pkg="opt" type="loop" name="xml" args="-x /urdf"/>
  <node pkg="opt" type="loop" name="neither"/>
  <node pkg="opt" type="loop" name="unknown" args="-q -r desc"/>
  <node pkg="opt" type="loop" name="ended" args="-- -r desc"/>
  <node pkg="opt" type="elsewhere" name="elsewhere" args="-t e -f base"/>
  <node pkg="opt" type="elsewhere" name="no_frame"/>
</launch>
"""


def _tree(write_tree):
    return write_tree({
        "src/opt/package.xml": package_xml("opt"),
        "src/opt/CMakeLists.txt": "project(opt)\nadd_executable(loop src/loop.cpp)\n"
                                  "add_executable(elsewhere src/elsewhere.cpp)\n",
        "src/opt/src/loop.cpp": LOOP,
        "src/opt/src/elsewhere.cpp": ELSEWHERE,
        "src/opt/launch/opt.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [opt/launch/opt.launch]\n",
    })


SPEC = "sx:r:t: stats xml: rosparam: topic:"


def test_the_extractor_marks_names_of_getopt_options(write_tree) -> None:
    root = _tree(write_tree)
    ws = scan([str(root)])
    loop = extract_cpp([str(root / "src/opt/src/loop.cpp")], ws, cache_dir=None)
    assert not [d for d in loop.diagnostics if d.code == "CPP_PARSE_ERROR"]
    assert {(c.kind, c.name, c.name_option, c.name_getopt, c.name_option_default,
             c.name_option_null) for c in loop.calls} == {
        ("read", "?", "-r --rosparam", SPEC, None, True),
        ("read", "?", "-x --xml", SPEC, None, True),
        ("publish", "?", "-t --topic", SPEC, "chatter", False)}
    other = extract_cpp([str(root / "src/opt/src/elsewhere.cpp")], ws, cache_dir=None)
    assert [(c.name, c.name_option, c.name_getopt) for c in other.calls] == [
        ("?", None, None), ("?/frame", "-f", "t:f:")]


def test_the_graph_names_them_with_the_launch_arguments(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    names = {(link.node.name, link.kind, link.rosname.full) for link in config.links
             if link.kind in ("publish", "read")}
    assert names == {
        ("/short", "read", "/robot_description"), ("/short", "publish", "/a"),
        ("/glued", "read", "/desc"), ("/glued", "publish", "/b"),
        # -sr desc: s takes no argument, r takes desc; -x's read names /ignored
        ("/bundled", "read", "/desc"), ("/bundled", "read", "/ignored"),
        ("/bundled", "publish", "/chatter"),
        ("/long", "read", "/desc"), ("/long", "publish", "/c"),
        ("/prefix", "read", "/desc"), ("/prefix", "publish", "/d"),
        # the last one given; ros::init took x:=y off before getopt
        ("/last", "read", "/two"), ("/last", "publish", "/chatter"),
        # -r not given: its null pointer names no read
        ("/xml", "read", "/urdf"), ("/xml", "publish", "/chatter"),
        ("/neither", "publish", "/chatter"),
        # an option the program does not take: getopt's reading not known
        ("/unknown", "read", "?"), ("/unknown", "publish", "?"),
        # after --, no option
        ("/ended", "publish", "/chatter"),
        # written elsewhere too: unknown
        ("/elsewhere", "publish", "?"), ("/elsewhere", "publish", "/base/frame"),
        ("/no_frame", "publish", "?"), ("/no_frame", "publish", "?/frame"),
    }


def test_a_model_file_carries_the_getopt_fields() -> None:
    document = {"schema": "haros-arch-model/1", "package": "opt", "nodes": [
        {"executable": "loop", "calls": [
            {"kind": "read", "name": "?", "name_option": "-r --rosparam",
             "name_getopt": SPEC, "name_option_null": True}]}]}
    again = from_document(json.loads(dumps(from_document(document))))
    call = again.nodes[0].calls[0]
    assert (call.name_option, call.name_getopt, call.name_option_null) == (
        "-r --rosparam", SPEC, True)


def test_getopt_rules_on_the_words_alone() -> None:
    def value(args: str, ros_version: int = 1, spec: str = SPEC,
              default: str | None = None) -> str | None:
        instance = NodeInstance(name="/n", args=args, ros_version=ros_version)
        return getopt_option(instance, "-r --rosparam", spec, default)

    assert value("-s -r a") == "a"
    assert value("--ros b") == "b"  # a prefix of rosparam alone
    assert value("-x") is None  # -x's argument missing: getopt's error
    assert value("-t", default="d") is None
    assert value("", default="d") == "d"
    assert value("extra -r a more") == "a"  # GNU getopt moves the other words last
    assert value("extra -r a", spec="+" + SPEC) is None  # ...not with a leading +
    assert value("--rosparam=a", spec="sx:r:t: --?") is None  # long table not read
    assert value("$(arg x) -r a") is None  # arguments not known statically
    # long options only (an empty optstring), and a model file's empty options
    assert value("--rosparam a", spec=" rosparam:") == "a"
    assert value("-r a", spec=" rosparam:") is None
    assert value("-r a", spec="") is None
    # ROS 2: getopt also reads launch_ros' --ros-args words, not told here
    assert value("-r a", ros_version=2) is None
