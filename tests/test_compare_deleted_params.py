"""Deleted parameters: the extractors mark deleting writes, the JSON carries them, and
compare does not count a parameter as set when it ends up deleted."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.api import NODE_HANDLE, ROSCPP
from haros_arch.extract.python import extract_python
from haros_arch.extract.python.rospy import ROWS
from haros_arch.live.compare import compare
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.workspace import scan


def test_api_rows_that_delete() -> None:
    assert ROWS[("rospy", "delete_param")].deletes
    assert not ROWS[("rospy", "set_param")].deletes
    assert ROSCPP[(NODE_HANDLE, "deleteParam")].deletes
    assert ROSCPP[("ros::param", "del")].deletes
    assert not ROSCPP[(NODE_HANDLE, "setParam")].deletes
    assert not ROSCPP[("ros::param", "set")].deletes


CPP_NODE = """
#include <ros/ros.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "cleaner");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  nh.setParam("mode", 1);
  nh.deleteParam("mode");
  pnh.deleteParam("scratch");
  ros::param::del("/global_flag");
  ros::param::set("/kept", true);
  return 0;
}
"""


def test_cpp_delete_calls_are_marked(write_tree) -> None:
    root = write_tree({"src/demo/package.xml": package_xml("demo"),
                       "src/demo/CMakeLists.txt": "project(demo)\n",
                       "src/demo/src/cleaner.cpp": CPP_NODE})
    result = extract_cpp([str(root / "src/demo/src/cleaner.cpp")], scan([str(root)]),
                         cache_dir=None)
    writes = [(c.name, c.deletes, c.location.line) for c in result.calls
              if c.kind == "write"]
    assert writes == [("mode", False, 7), ("mode", True, 8), ("~scratch", True, 9),
                      ("/global_flag", True, 10), ("/kept", False, 11)]


PY_NODE = """
#!/usr/bin/env python3
import rospy

def main():
    rospy.init_node("param_user")
    rospy.set_param("to_delete", "x")
    rospy.set_param("kept", 1)
    if rospy.has_param("to_delete"):
        rospy.delete_param("to_delete")
    rospy.delete_param("launch_only")
    rospy.delete_param("then_set")
    rospy.set_param("then_set", 2)

main()
"""

LAUNCH = """
<launch>
  <group ns="ns">
    <param name="to_delete" value="from launch" />
    <param name="launch_only" value="from launch" />
    <param name="untouched" value="from launch" />
    <node name="param_user" pkg="pkg" type="param_user.py" />
  </group>
</launch>
"""


def test_python_delete_param_end_to_end(write_tree) -> None:
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\n",
        "src/pkg/scripts/param_user.py": PY_NODE,
        "src/pkg/launch/a.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    os.chmod(root / "src/pkg/scripts/param_user.py", 0o755)
    calls = extract_python([str(root / "src/pkg/scripts/param_user.py")],
                           scan([str(root)]), package="pkg").calls
    assert [(c.name, c.deletes) for c in calls if c.kind == "write"] == [
        ("to_delete", False), ("kept", False), ("to_delete", True), ("launch_only", True),
        ("then_set", True), ("then_set", False)]

    data = model_to_data(analyse(load(str(root / "project.yaml")), {"PATH": ""}))
    links = data["configurations"][0]["links"]
    writes = {(link["name"], link["location"]["line"]): link["deletes"]
              for link in links if link["kind"] == "write"}
    assert writes == {("/ns/to_delete", 6): False, ("/ns/kept", 7): False,
                      ("/ns/to_delete", 9): True, ("/ns/launch_only", 10): True,
                      ("/ns/then_set", 11): True, ("/ns/then_set", 12): False}
    assert all("deletes" not in link for link in links if link["kind"] != "write")

    # what the master holds once the node has run: launch-set and node-set, minus deleted
    live = {"nodes": ["/ns/param_user"], "topics": [], "services": [], "parameters": [
        {"name": "/ns/kept"}, {"name": "/ns/then_set"}, {"name": "/ns/untouched"}]}
    score = {s.kind: s for s in compare(data, live).scores}["parameters"]
    assert score.ours == {"/ns/kept", "/ns/then_set", "/ns/untouched"}
    assert score.precision == score.recall == 1.0


def _config(writes: list[dict[str, object]], launch_set: list[str]) -> dict[str, object]:
    names = sorted({str(w["name"]) for w in writes} | set(launch_set))
    parameters = [{"name": n, "writers": (["<launch>"] if n in launch_set else [])
                   + [str(w["node"]) for w in writes if w["name"] == n]} for n in names]
    return {"configurations": [{"name": "c", "nodes": [], "topics": [], "services": [],
                                "parameters": parameters,
                                "links": [{"kind": "write", **w} for w in writes]}]}


def _write(node: str, name: str, line: int, deletes: bool, file: str = "a.py"):
    return {"node": node, "name": name, "deletes": deletes,
            "location": {"file": file, "line": line, "column": 1}}


def _ours(model: dict[str, object]) -> set[str]:
    live = {"nodes": [], "topics": [], "services": [], "parameters": []}
    return {s.kind: s for s in compare(model, live).scores}["parameters"].ours


def test_only_deleting_writers_and_no_launch_is_not_set() -> None:
    assert _ours(_config([_write("/a", "/p", 3, True)], [])) == set()


def test_launch_set_then_deleted_by_a_node_is_not_set() -> None:
    assert _ours(_config([_write("/a", "/p", 3, True)], ["/p"])) == set()


def test_a_node_that_sets_after_another_deletes_keeps_it() -> None:
    model = _config([_write("/a", "/p", 3, True), _write("/b", "/p", 9, False)], [])
    assert _ours(model) == {"/p"}


def test_writes_in_several_files_keep_it_set() -> None:
    model = _config([_write("/a", "/p", 9, False, "a.py"),
                     _write("/a", "/p", 3, True, "b.py")], [])
    assert _ours(model) == {"/p"}


def test_deleting_a_namespace_deletes_its_leaves() -> None:
    model = _config([_write("/a", "/gains", 3, True)], ["/gains/P", "/gains/I", "/other"])
    assert _ours(model) == {"/other"}


def test_models_without_the_field_count_writes_as_sets() -> None:
    model = _config([{"node": "/a", "name": "/p"}], [])
    assert _ours(model) == {"/p"}
