"""An argument an included file requires and its include does not pass is said once per
file that requires it, at the first use, with the other uses as ``also``, as an unset
argument is (``said_once``): each use of it was one more error for one thing to fix."""

from __future__ import annotations

import json
from pathlib import Path

from conftest import package_xml

from haros_arch.cli import main

NODE = """\
#!/usr/bin/env python
import rospy
rospy.init_node("cam")
"""

TOP = """\
<launch>
  <include file="$(find cams)/launch/part.launch" />
  <include file="$(find cams)/launch/other.launch" />
  <node pkg="cams" type="cam" name="cam" />
</launch>
"""

PART = """\
<launch>
  <arg name="robot" />
  <param name="a" value="$(arg robot)/a" />
  <param name="b" value="$(arg robot)/b" />
  <param name="c" value="$(arg robot)/c" />
</launch>
"""

OTHER = """\
<launch>
  <param name="z" value="$(arg gone)/z" />
</launch>
"""


def test_a_required_argument_is_said_once_per_file_with_its_uses(write_tree) -> None:
    root: Path = write_tree({
        "src/cams/package.xml": package_xml("cams"),
        "src/cams/CMakeLists.txt": "project(cams)\n",
        "src/cams/scripts/cam": NODE,
        "src/cams/launch/run.launch": TOP,
        "src/cams/launch/part.launch": PART,
        "src/cams/launch/other.launch": OTHER,
        "project.yaml": "project: p\nconfigurations:\n  c: [cams/launch/run.launch]\n",
    })
    (root / "src/cams/scripts/cam").chmod(0o755)
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    said = json.loads(out.read_text())["diagnostics"]

    def places(code: str) -> list[list[tuple[object, object]]]:
        return [[(w["file"], w["line"]) for w in (d["location"], *d.get("also", ()))]
                for d in said if d["code"] == code]

    assert sorted(places("LAUNCH_ARG_REQUIRED")) == [
        [("cams/launch/other.launch", 2)],
        [("cams/launch/part.launch", 3), ("cams/launch/part.launch", 4),
         ("cams/launch/part.launch", 5)]]
