"""``haros-arch check``'s text lists a diagnostic said again in one file with the same
message once, at its first place, with the others as ``also at`` (subt's launch files use
an argument no one sets hundreds of times: a thousand lines of one warning); ``-v``
lists every place, and the JSON keeps every one."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

NODE = """\
#!/usr/bin/env python
import rospy
rospy.init_node("cam")
"""


def _tree(write_tree, uses: int):  # type: ignore[no-untyped-def]
    params = "\n".join(f'  <param name="p{i}" value="$(arg robot)/x{i}" />'
                       for i in range(uses))
    root = write_tree({
        "src/cams/package.xml": package_xml("cams"),
        "src/cams/CMakeLists.txt": "project(cams)\n",
        "src/cams/scripts/cam": NODE,
        "src/cams/launch/run.launch": f'<launch>\n  <arg name="robot" />\n{params}\n'
                                      '  <node pkg="cams" type="cam" name="cam" />\n</launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [cams/launch/run.launch]\n",
    })
    (root / "src/cams/scripts/cam").chmod(0o755)
    return root


def _text(root, *extra: str) -> list[str]:  # type: ignore[no-untyped-def]
    out = root / "check.txt"
    main(["check", str(root / "project.yaml"), "--format", "text", "-o", str(out),
          "--fail-on", "never", *extra])
    return out.read_text().splitlines()


def test_a_repeated_warning_is_listed_once_with_its_other_places(write_tree) -> None:
    root = _tree(write_tree, 3)
    lines = _text(root)
    said = [line for line in lines if "[LAUNCH_ARG_UNSET]" in line]
    assert len(said) == 1
    assert said[0].strip().startswith("cams/launch/run.launch:3:")
    also = lines[lines.index(said[0]) + 1].strip()
    assert also.startswith("also at: 4:") and ", 5:" in also


def test_many_places_are_cut_short(write_tree) -> None:
    root = _tree(write_tree, 12)
    lines = _text(root)
    (also,) = [line.strip() for line in lines if line.strip().startswith("also at:")]
    assert also.endswith("and 3 more")


def test_verbose_lists_every_place_and_the_json_keeps_each(write_tree) -> None:
    """One argument's uses are one diagnostic of the configuration (its ``also``:
    test_launch_arg_unset_once.py): ``-v`` lists all its places, the JSON keeps them."""
    root = _tree(write_tree, 12)
    lines = _text(root, "-v")
    said = [n for n, line in enumerate(lines) if "[LAUNCH_ARG_UNSET]" in line]
    assert len(said) == 1
    assert lines[said[0] + 1].strip() == "also at: " + ", ".join(
        f"{line}:0" for line in range(4, 15))
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    (unset,) = [d for d in report["diagnostics"] if d["code"] == "LAUNCH_ARG_UNSET"]
    assert [where["line"] for where in unset["also"]] == list(range(4, 15))
