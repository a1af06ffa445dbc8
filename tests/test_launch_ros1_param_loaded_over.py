"""A ROS 1 group-level ``<param name="a/x">`` followed by a ``<rosparam ns="a">`` whose
file has ``x``: roslaunch adds both to its parameters in document order (xmlloader, then
loader.add_param of each key of the file) and keeps the later value, so the ``<param>``
is dead though it reads as the override of the file. LAUNCH_PARAM_SET_TWICE covered two
<param> tags only (fixAA's leftover). Said at the <param>, naming the key's line in the
file; not for a <rosparam> first (the usual override), nor a <param> with an if of its
own, nor a <param> of another element."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

PARAMS = """
    speed: 2.0
    limits:
      max: 5
    """

LAUNCH = """
    <launch>
      <group ns="arm">
        <param name="ctl/speed" value="1.0"/>
        <param name="ctl/limits/max" value="9" if="$(optenv FAST 0)"/>
        <param name="ctl/other" value="3"/>
        <rosparam ns="ctl" file="$(find p)/config/params.yaml"/>
        <param name="ctl/limits/max" value="7"/>
      </group>
      <group ns="arm">
        <param name="ctl2/speed" value="1.0"/>
      </group>
      <group ns="arm">
        <rosparam ns="ctl2" file="$(find p)/config/params.yaml"/>
      </group>
    </launch>
    """


def test_a_param_a_later_rosparam_loads_again_is_said(write_tree) -> None:
    root = write_tree({
        "src/p/package.xml": package_xml("p"),
        "src/p/CMakeLists.txt": "project(p)\n",
        "src/p/config/params.yaml": PARAMS,
        "src/p/launch/robot.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [p/launch/robot.launch]\n"})
    model = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(model)])
    config = json.loads(model.read_text())["configurations"][0]
    said = [(d["location"]["line"], d["message"]) for d in config["diagnostics"]
            if d["code"] == "LAUNCH_PARAM_LOADED_OVER"]
    assert said == [(3, "parameter /arm/ctl/speed set here is loaded again by a later "
                        "<rosparam> (p/config/params.yaml:1): roslaunch keeps the later "
                        "value, this one is never used")]
    # the value kept is the file's; the <param> after the <rosparam> wins (not said)
    values = {p["name"]: p.get("value") for p in config["parameters"]}
    assert values["/arm/ctl/speed"] == 2.0
    assert values["/arm/ctl/limits/max"] == 7
