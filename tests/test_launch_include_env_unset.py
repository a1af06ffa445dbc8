"""A ROS 1 include whose path is unknown only because an environment variable it names
is not set in the configuration (katana_driver's katana.launch: ``$(find
katana)/launch/$(env KATANA_TYPE).launch``) has one cause, said once where the variable
is read (``LAUNCH_UNKNOWN_VALUE``, info: the configuration's environment may set it), not
again as a construct not read (``LAUNCH_UNSUPPORTED`` warning). The include stays one not
read. A path also unknown for another reason (an argument with no value) is still a
warning."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

DIRECT = ('<launch>\n'
          '  <include file="$(find pkg)/launch/$(env ARM_TYPE).launch"/>\n'
          '</launch>\n')
THROUGH_ARG = ('<launch>\n'
               '  <arg name="sensor" default="$(env ROBOT_SENSOR)"/>\n'
               '  <arg name="amcl" default="$(find pkg)/launch/$(arg sensor)_amcl.launch"/>\n'
               '  <include file="$(arg amcl)"/>\n'
               '</launch>\n')
MIXED = ('<launch>\n'
         '  <arg name="world"/>\n'
         '  <include file="$(find pkg)/launch/$(env ARM_TYPE)_$(arg world).launch"/>\n'
         '</launch>\n')
ARM = ('<launch><node name="arm" pkg="pkg" type="arm_node"/></launch>\n')


def said(model):
    return sorted((d.code, d.severity, d.location.line) for d in model.diagnostics
                  if d.code in ("LAUNCH_UNKNOWN_VALUE", "LAUNCH_UNSUPPORTED",
                                "LAUNCH_ARG_UNSET"))


def test_an_include_unknown_only_through_an_unset_variable_is_said_once(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/launch/direct.launch": DIRECT,
                       "src/pkg/launch/through_arg.launch": THROUGH_ARG,
                       "src/pkg/launch/mixed.launch": MIXED,
                       "src/pkg/launch/katana_300.launch": ARM})
    ws = scan([str(root / "src")], {})
    direct = load(str(root / "src/pkg/launch/direct.launch"), ws, {}, {})
    assert said(direct) == [("LAUNCH_UNKNOWN_VALUE", "info", 2)]
    assert "ARM_TYPE" in direct.diagnostics[0].message
    assert len(direct.unread_includes) == 1 and not direct.nodes
    through = load(str(root / "src/pkg/launch/through_arg.launch"), ws, {}, {})
    assert said(through) == [("LAUNCH_UNKNOWN_VALUE", "info", 2)]
    assert len(through.unread_includes) == 1
    # an argument with no value is a mistake of its own: the include is still a warning
    mixed = load(str(root / "src/pkg/launch/mixed.launch"), ws, {}, {})
    assert ("LAUNCH_UNSUPPORTED", "warning", 3) in said(mixed)
    # set, the variable names the file, which is read
    known = load(str(root / "src/pkg/launch/direct.launch"), ws, {},
                 {"ARM_TYPE": "katana_300"})
    assert said(known) == [] and [n.name for n in known.nodes] == ["/arm"]


ROS2_DIRECT = ('<launch>\n'
               '  <include file="$(find-pkg-share pkg)/launch/$(env ARM_TYPE).launch.xml"/>\n'
               '</launch>\n')
ROS2_THROUGH_ARG = (
    '<launch>\n'
    '  <arg name="sensor" default="$(env ROBOT_SENSOR)"/>\n'
    '  <include file="$(find-pkg-share pkg)/launch/$(var sensor)_amcl.launch.xml"/>\n'
    '</launch>\n')
ROS2_YAML = ('launch:\n'
             '- include:\n'
             '    file: "$(find-pkg-share pkg)/launch/$(env ARM_TYPE).launch.xml"\n')
ROS2_MIXED = ('<launch>\n'
              '  <include file="$(find-pkg-share pkg)/launch/'
              '$(env ARM_TYPE)_$(command x).launch.xml"/>\n'
              '</launch>\n')
ROS2_ARM = '<launch><node pkg="pkg" exec="arm_node" name="arm"/></launch>\n'


def test_ros_2_an_include_unknown_only_through_an_unset_variable_names_it(write_tree):
    """ROS 2's ``$(env NAME)`` with no default, unset: the include said only
    ``included file .../?.launch.xml is not known statically`` (LAUNCH_UNSUPPORTED
    warning), which did not name the variable; now one info that names it, as ROS 1's."""
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/launch/direct.launch.xml": ROS2_DIRECT,
                       "src/pkg/launch/through_arg.launch.xml": ROS2_THROUGH_ARG,
                       "src/pkg/launch/direct.launch.yaml": ROS2_YAML,
                       "src/pkg/launch/mixed.launch.xml": ROS2_MIXED,
                       "src/pkg/launch/katana.launch.xml": ROS2_ARM})
    ws = scan([str(root / "src")], {})
    for name, variable in (("direct.launch.xml", "ARM_TYPE"),
                           ("through_arg.launch.xml", "ROBOT_SENSOR"),
                           ("direct.launch.yaml", "ARM_TYPE")):
        model = load(str(root / "src/pkg/launch" / name), ws, {}, {})
        line = 3 if name == "through_arg.launch.xml" else 2
        assert said(model) == [("LAUNCH_UNKNOWN_VALUE", "info", line)], name
        (message,) = [d.message for d in model.diagnostics
                      if d.code == "LAUNCH_UNKNOWN_VALUE"]
        assert f"environment variable {variable} is not set" in message
        assert not model.nodes
    # unknown for another cause too: still the warning
    mixed = load(str(root / "src/pkg/launch/mixed.launch.xml"), ws, {}, {})
    assert ("LAUNCH_UNSUPPORTED", "warning", 2) in said(mixed)
    known = load(str(root / "src/pkg/launch/direct.launch.xml"), ws, {},
                 {"ARM_TYPE": "katana"})
    assert said(known) == [] and [n.name for n in known.nodes] == ["/arm"]
