"""dynamic_reconfigure (ROS 1): a package's ``cfg/*.cfg`` is read (never run) for the
``<Name>Config.h`` it generates: the config's fields parse, and a ``Server`` of it reads
each of its parameters under its handle's namespace, with the .cfg default (it writes
them back as read, which no call says: "set by the node" would undecide conditions).
A parameter a launch file sets there that the .cfg does not declare is then not read
(before, everything under a server's namespace was undecided). The sources are
fixtures/cpp/reconfigure."""

from __future__ import annotations

import json
import os

from haros_arch.cli import main
from haros_arch.extract.cpp import extract_cpp, reconfigure
from haros_arch.workspace import scan
from tests.conftest import package_xml

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURES = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "reconfigure")


def _fixture(name: str) -> str:
    with open(os.path.join(FIXTURES, name), encoding="utf-8") as handle:
        return handle.read()


def _tree(write_tree, cfg: str, launch: str = "") -> object:
    files = {"tracker/package.xml": package_xml("tracker", "catkin"),
             "tracker/CMakeLists.txt": (
                 "cmake_minimum_required(VERSION 3.0.2)\nproject(tracker)\n"
                 "find_package(catkin REQUIRED COMPONENTS roscpp dynamic_reconfigure)\n"
                 "generate_dynamic_reconfigure_options(cfg/Tracker.cfg)\n"
                 "catkin_package()\nadd_executable(tracker_node src/tracker.cpp)\n"),
             "tracker/src/tracker.cpp": _fixture("tracker.cpp"),
             "tracker/cfg/Tracker.cfg": cfg}
    if launch:
        files["tracker/launch/tracker.launch"] = launch
    return write_tree(files)


def test_a_server_reads_the_parameters_of_its_cfg(write_tree) -> None:
    root = _tree(write_tree, _fixture("Tracker.cfg"))
    result = extract_cpp([str(root / "tracker" / "src" / "tracker.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = [(c.kind, c.name, c.type, c.default, c.handle_namespace) for c in result.calls
             if c.kind in ("read", "write")]
    assert calls == [
        ("read", "~rate", "double", 10.0, "~"), ("read", "~frame_id", "str", "base_link", "~"),
        ("read", "~mode", "int", 0, "~"), ("read", "~use_filter", "bool", True, "~"),
        # offset_x and offset_y are named in a loop: some parameters are not known
        ("read", "~?", None, None, "~")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_RECONFIGURE_PARTIAL" in codes
    # the fields and the enum's constant parse; only the field named in a loop does not
    errors = [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
    assert errors == ["C++ error: no member named 'offset_x' in 'tracker::TrackerConfig'"]


def test_reading_a_cfg_runs_nothing_and_survives_bad_input(tmp_path) -> None:
    marker = tmp_path / "ran"
    text = (f"import os\nos.system('touch {marker}')\n"
            "gen = ParameterGenerator()\ngen.add('speed', double_t, 0, 'd', 1.5, 0, 3)\n"
            "gen.add(name='on', paramtype=bool_t, level=0, description='d', default=False)\n"
            "exit(gen.generate('p', 'n', 'Speed'))\n")
    config, problems = reconfigure.read_cfg("Speed.cfg", text, "p")
    assert not marker.exists() and problems == []
    assert config is not None and config.name == "Speed" and not config.partial
    assert config.parameters == [("speed", "double_t", 1.5), ("on", "bool_t", False)]
    config, problems = reconfigure.read_cfg("Bad.cfg", "gen.add('x', double_t,\n", "p")
    assert config is None and [p.code for p in problems] == ["RECONFIGURE_CFG_INVALID"]
    assert problems[0].location.line == 1  # the call never closed
    config, problems = reconfigure.read_cfg("None.cfg", "gen = ParameterGenerator()\n", "p")
    assert config is None and problems == []


def test_a_generator_handed_to_another_function_makes_the_config_partial() -> None:
    # navigation's DWAPlanner.cfg: add_generic_localplanner_params(gen), from a module
    text = ("from local_planner_limits import add_generic_localplanner_params\n"
            "gen = ParameterGenerator()\nadd_generic_localplanner_params(gen)\n"
            "gen.add('sim_time', double_t, 0, 'd', 1.7, 0)\n"
            "exit(gen.generate('dwa', 'dwa', 'DWAPlanner'))\n")
    config, _ = reconfigure.read_cfg("DWAPlanner.cfg", text, "dwa")
    assert config is not None and config.partial
    assert config.parameters == [("sim_time", "double_t", 1.7)]
    group = text.replace("add_generic_localplanner_params(gen)",
                         "limits = gen.add_group('limits')\nextra(limits)")
    config, _ = reconfigure.read_cfg("DWAPlanner.cfg", group, "dwa")
    assert config is not None and config.partial
    plain = text.replace("add_generic_localplanner_params(gen)\n", "")
    config, _ = reconfigure.read_cfg("DWAPlanner.cfg", plain, "dwa")
    assert config is not None and not config.partial


def _check(root) -> dict:
    out = root / "check.json"
    main(["check", str(root), "--format", "json", "-o", str(out), "--fail-on", "never"])
    return json.loads(out.read_text())


LAUNCH = """<launch>
  <node pkg="tracker" type="tracker_node" name="tracker">
    <param name="rate" value="20.0"/>
    <param name="use_filtre" value="false"/>
    <param name="planner/rate" value="2.0"/>
  </node>
</launch>
"""


def test_a_parameter_the_cfg_does_not_declare_is_not_read(write_tree) -> None:
    complete = _fixture("Tracker.cfg").replace(
        'for axis in ["x", "y"]:\n    gen.add("offset_" + axis, double_t, 0, "an offset", 0.0)\n',
        'gen.add("offset_x", double_t, 0, "an offset", 0.0)\n')
    report = _check(_tree(write_tree, complete, LAUNCH))
    findings = [(f["rule"], f["entities"]) for f in report["findings"]
                if f["rule"].startswith("parameter-set-not-read")]
    # right under the server's namespace its reads decide; deeper, the server reads
    # nothing (the generated code reads its config's fields under its handle's
    # namespace alone) and the node's code, read whole, reads no planner/rate either
    # (move_base's server on ~ and its costmaps' parameters: costmap_2d's code, in
    # move_base's model, reads those)
    assert sorted(findings) == [
        ("parameter-set-not-read", ["parameter:/tracker/planner/rate"]),
        ("parameter-set-not-read", ["parameter:/tracker/use_filtre"])]


def test_a_partial_cfg_leaves_its_namespace_undecided(write_tree) -> None:
    report = _check(_tree(write_tree, _fixture("Tracker.cfg"), LAUNCH))
    rules = [f["rule"] for f in report["findings"]
             if f["rule"].startswith("parameter-set-not-read")]
    assert rules == ["parameter-set-not-read-undecided"]


def test_a_condition_over_a_parameter_the_server_reads_stays_decided(write_tree) -> None:
    # amcl: use_map_topic is a field of AMCL.cfg and the code reads it; a launch file
    # that does not set it keeps the default (false), so /map is never subscribed. The
    # server writes its parameters back as it read them: no write that would undecide it
    source = _fixture("tracker.cpp").replace(
        '    pub_ = nh_.advertise<std_msgs::Float64>("rate", 1);\n',
        '    pub_ = nh_.advertise<std_msgs::Float64>("rate", 1);\n'
        '    pnh_.param("use_filter", use_filter_, false);\n'
        '    if (use_filter_) {\n'
        '      sub_ = nh_.subscribe("filtered", 1, &Tracker::onFiltered, this);\n'
        '    }\n').replace(
        "  ros::Publisher pub_;\n",
        "  ros::Publisher pub_;\n  ros::Subscriber sub_;\n  bool use_filter_ = false;\n"
        "  void onFiltered(const std_msgs::Float64ConstPtr& msg) {}\n")
    root = _tree(write_tree, _fixture("Tracker.cfg"), LAUNCH)
    (root / "tracker" / "src" / "tracker.cpp").write_text(source)
    report = _check(root)
    assert not [f for f in report["findings"] if "filtered" in f["message"]]


def test_a_config_named_in_lowercase_is_synthesised(write_tree) -> None:
    """yocs_cmd_vel_mux's reload.cfg ends with gen.generate(PACKAGE, node, "reload"), so
    dynamic_reconfigure writes <yocs_cmd_vel_mux/reloadConfig.h>; only a header named with
    a capital was taken for a config (or a message), so this one was an empty stand-in,
    the server's parameters were unread and `config.yaml_cfg_data` an error in the
    callback that makes the node's subscriptions."""
    cfg = ("PACKAGE = 'mux'\nfrom dynamic_reconfigure.parameter_generator_catkin import *\n"
           "gen = ParameterGenerator()\n"
           "gen.add('yaml_cfg_file', str_t, 0, 'path', '')\n"
           "exit(gen.generate(PACKAGE, 'mux_reload', 'reload'))\n")
    source = ('#include <ros/ros.h>\n#include <dynamic_reconfigure/server.h>\n'
              '#include <mux/reloadConfig.h>\n'
              'void cb(mux::reloadConfig &config, uint32_t) {\n'
              '  ros::NodeHandle nh;\n'
              '  if (config.yaml_cfg_file.size() > 0) nh.subscribe("input", 1, &cb2);\n}\n'
              'int main(int argc, char **argv) {\n  ros::init(argc, argv, "mux");\n'
              '  ros::NodeHandle pnh("~");\n'
              '  dynamic_reconfigure::Server<mux::reloadConfig> server(pnh);\n'
              '  server.setCallback(&cb);\n  return 0;\n}\n')
    source = source.replace('nh.subscribe("input", 1, &cb2)',
                            'nh.advertise<std_msgs::String>("output", 1)').replace(
        "#include <ros/ros.h>\n", "#include <ros/ros.h>\n#include <std_msgs/String.h>\n")
    root = write_tree({
        "mux/package.xml": package_xml("mux", "catkin"),
        "mux/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(mux)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp dynamic_reconfigure)\n"
            "generate_dynamic_reconfigure_options(cfg/reload.cfg)\n"
            "catkin_package()\nadd_executable(mux_node src/mux.cpp)\n"),
        "mux/src/mux.cpp": source,
        "mux/cfg/reload.cfg": cfg})
    result = extract_cpp([str(root / "mux" / "src" / "mux.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = [(c.kind, c.name) for c in result.calls]
    assert ("read", "~yaml_cfg_file") in calls and ("publish", "output") in calls
    codes = [d.code for d in result.diagnostics]
    assert "CPP_INCLUDE_MISSING" not in codes and "CPP_PARSE_ERROR" not in codes


def test_a_generator_handed_to_a_workspace_module_gets_its_parameters(write_tree) -> None:
    # navigation's DWAPlanner.cfg hands its generator to base_local_planner's
    # add_generic_localplanner_params (src/local_planner_limits/__init__.py, installed by
    # catkin_python_setup): its adds are the config's (max_vel_x, xy_goal_tolerance, ...)
    cfg = _fixture("Tracker.cfg").replace(
        'for axis in ["x", "y"]:\n    gen.add("offset_" + axis, double_t, 0, "an offset", 0.0)\n',
        "add_limits(gen)\n").replace(
        "gen = ParameterGenerator()",
        "from limits_params import add_limits\ngen = ParameterGenerator()")
    assert "add_limits(gen)" in cfg and "import add_limits" in cfg
    root = _tree(write_tree, cfg)
    limits = {
        "limits/package.xml": package_xml("limits", "catkin"),
        "limits/src/limits_params/__init__.py": (
            "from dynamic_reconfigure.parameter_generator_catkin import double_t\n\n\n"
            "def add_limits(gen):\n"
            "    gen.add('max_vel_x', double_t, 0, 'the fastest', 0.55)\n"
            "    gen.add('offset_x', double_t, 0, 'an offset', 0.0)\n")}
    write_tree(limits)
    result = extract_cpp([str(root / "tracker" / "src" / "tracker.cpp")], scan([str(root)]),
                         cache_dir=None)
    reads = [(c.name, c.default) for c in result.calls if c.kind == "read"]
    assert ("~max_vel_x", 0.55) in reads and ("~offset_x", 0.0) in reads
    assert not any("?" in name for name, _ in reads)
    codes = [d.code for d in result.diagnostics]
    assert "CPP_RECONFIGURE_PARTIAL" not in codes and "CPP_PARSE_ERROR" not in codes


def test_a_generator_handed_on_again_or_to_an_unknown_function_stays_partial(tmp_path
                                                                            ) -> None:
    module = tmp_path / "helpers.py"
    module.write_text("def add_on(gen):\n    more(gen)\n\n\n"
                      "def add_one(group):\n    group.add('a', double_t, 0, 'a', 1.0)\n")
    head = ("from helpers import add_on, add_one\ngen = ParameterGenerator()\n")
    tail = "exit(gen.generate('p', 'n', 'Name'))\n"

    def read(call: str) -> reconfigure.Config:
        config, _ = reconfigure.read_cfg("Name.cfg", head + call + tail, "p",
                                         lambda name: str(module) if name == "helpers"
                                         else None)
        assert config is not None
        return config

    handed_on = read("add_on(gen)\n")
    assert handed_on.partial and handed_on.parameters == []
    followed = read("add_one(group=gen)\n")
    assert not followed.partial and followed.parameters == [("a", "double_t", 1.0)]
    assert read("unknown(gen)\n").partial


def test_a_cfg_in_a_folder_below_cfg_makes_its_config(write_tree) -> None:
    """bebop_driver generates its config from ``cfg/autogenerated/BebopArdrone3.cfg``
    (``generate_dynamic_reconfigure_options`` takes any path of the package): the header
    is still ``<pkg/NameConfig.h>``. Only ``cfg/*.cfg`` was read, so the config was known
    only by name, its server read nothing and each field the code used was an error (44
    in bebop's setting callbacks). A module the .cfg imports is looked for beside it."""
    cfg = _fixture("Tracker.cfg").replace(
        'for axis in ["x", "y"]:\n    gen.add("offset_" + axis, double_t, 0, "an offset", 0.0)\n',
        "add_limits(gen)\n").replace(
        "gen = ParameterGenerator()",
        "from limits_params import add_limits\ngen = ParameterGenerator()")
    assert "add_limits(gen)" in cfg
    root = _tree(write_tree, cfg)
    os.makedirs(root / "tracker" / "cfg" / "generated" / "limits_params")
    os.rename(root / "tracker" / "cfg" / "Tracker.cfg",
              root / "tracker" / "cfg" / "generated" / "Tracker.cfg")
    (root / "tracker" / "cfg" / "generated" / "limits_params" / "__init__.py").write_text(
        "from dynamic_reconfigure.parameter_generator_catkin import double_t\n\n\n"
        "def add_limits(gen):\n"
        "    gen.add('offset_x', double_t, 0, 'an offset', 0.0)\n")
    result = extract_cpp([str(root / "tracker" / "src" / "tracker.cpp")], scan([str(root)]),
                         cache_dir=None)
    reads = [(c.name, c.default) for c in result.calls if c.kind == "read"]
    assert reads == [("~rate", 10.0), ("~frame_id", "base_link"), ("~mode", 0),
                     ("~use_filter", True), ("~offset_x", 0.0)]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_RECONFIGURE_PARTIAL" not in codes


def test_a_config_in_the_namespace_its_cfg_names(write_tree) -> None:
    """PX4-Avoidance's local_planner/cfg/LocalPlannerNode.cfg sets ``PACKAGE = "avoidance"``
    and ends with gen.generate(PACKAGE, "avoidance", "LocalPlannerNode"): dynamic_reconfigure
    writes <local_planner/LocalPlannerNodeConfig.h> with ``avoidance::LocalPlannerNodeConfig``
    (the namespace is generate's first argument). The class was synthesised in namespace
    local_planner: the nodelet's ``avoidance::LocalPlannerNodeConfig`` was a class not read
    (CPP_CLASS_UNSEEN), the node partial and its server's parameters unread."""
    cfg = ('PACKAGE = "avoidance"\nfrom dynamic_reconfigure.parameter_generator_catkin import *\n'
           "gen = ParameterGenerator()\n"
           "gen.add('max_speed', double_t, 0, 'speed', 3.0)\n"
           'exit(gen.generate(PACKAGE, "avoidance", "LocalPlannerNode"))\n')
    source = ('#include <ros/ros.h>\n#include <dynamic_reconfigure/server.h>\n'
              '#include <local_planner/LocalPlannerNodeConfig.h>\n'
              'void cb(avoidance::LocalPlannerNodeConfig &config, uint32_t) {}\n'
              'int main(int argc, char **argv) {\n  ros::init(argc, argv, "planner");\n'
              '  ros::NodeHandle pnh("~");\n'
              '  dynamic_reconfigure::Server<avoidance::LocalPlannerNodeConfig> server(pnh);\n'
              '  server.setCallback(&cb);\n  return 0;\n}\n')
    root = write_tree({
        "local_planner/package.xml": package_xml("local_planner", "catkin"),
        "local_planner/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(local_planner)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp dynamic_reconfigure)\n"
            "generate_dynamic_reconfigure_options(cfg/LocalPlannerNode.cfg)\n"
            "catkin_package()\nadd_executable(planner src/planner.cpp)\n"),
        "local_planner/src/planner.cpp": source,
        "local_planner/cfg/LocalPlannerNode.cfg": cfg})
    result = extract_cpp([str(root / "local_planner" / "src" / "planner.cpp")],
                         scan([str(root)]), cache_dir=None)
    assert ("read", "~max_speed") in [(c.kind, c.name) for c in result.calls]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_CLASS_UNSEEN" not in codes and "CPP_PARSE_ERROR" not in codes


def test_a_cfg_the_cmake_file_names_outside_cfg_makes_its_config(write_tree) -> None:
    """moveit_ros_planning keeps its .cfg files beside each library
    (``trajectory_execution_manager/cfg/TrajectoryExecutionDynamicReconfigure.cfg``) and
    hands their paths to ``generate_dynamic_reconfigure_options``: only ``cfg/`` was
    read, so move_group's trajectory execution server read none of its parameters
    (``~trajectory_execution/allowed_execution_duration_scaling``). A path the CMake
    file builds from other variables, or outside the package, is not followed."""
    root = _tree(write_tree, _fixture("Tracker.cfg"))
    os.makedirs(root / "tracker" / "manager" / "cfg")
    os.rename(root / "tracker" / "cfg" / "Tracker.cfg",
              root / "tracker" / "manager" / "cfg" / "Tracker.cfg")
    cmake = root / "tracker" / "CMakeLists.txt"
    cmake.write_text(cmake.read_text().replace(
        "generate_dynamic_reconfigure_options(cfg/Tracker.cfg)",
        "# generate_dynamic_reconfigure_options(old/Old.cfg)\n"
        'generate_dynamic_reconfigure_options(\n  "${CMAKE_CURRENT_SOURCE_DIR}/manager/cfg/'
        'Tracker.cfg"\n  ${OTHER}/More.cfg ../outside/Out.cfg)'))
    result = extract_cpp([str(root / "tracker" / "src" / "tracker.cpp")], scan([str(root)]),
                         cache_dir=None)
    reads = [(c.name, c.default) for c in result.calls if c.kind == "read"]
    assert reads[:4] == [("~rate", 10.0), ("~frame_id", "base_link"), ("~mode", 0),
                         ("~use_filter", True)]
    assert [d.message for d in result.diagnostics if d.code == "CPP_INCLUDE_MISSING"] == []
