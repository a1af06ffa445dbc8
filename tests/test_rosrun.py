"""Scripts that only rosrun's search of the package finds (ROS 1) still get analysed."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load


def test_a_launched_script_outside_scripts_folder_is_found(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\n",
        "src/pkg/test/checker.py": """
            #!/usr/bin/env python3
            import rospy
            from std_msgs.msg import String
            rospy.init_node("checker")
            rospy.Subscriber("chatter", String, lambda m: None)
            """,
        "src/pkg/test/not_executable.py": "import rospy\n",
        "src/pkg/launch/t.launch": """
            <launch>
              <test test-name="t" pkg="pkg" type="checker.py" />
              <node name="n" pkg="pkg" type="not_executable.py" />
            </launch>
            """,
        # a rostest configuration: its <test> nodes run (roslaunch leaves them out)
        "project.yaml": "project: p\nconfigurations:\n  c:\n    launch: [pkg/launch/t.launch]"
                        "\n    rostest: true\n",
    })
    os.chmod(root / "src/pkg/test/checker.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    checker = config.node("/t")
    assert checker is not None and checker.node is not None
    assert checker.node.sources == ["pkg/test/checker.py"]
    assert [(link.kind, link.name) for link in checker.links] == [("subscribe", "/chatter")]
    assert config.node("/n").node is None
    # roslaunch finds not_executable.py and refuses it: said so, not "not in the workspace"
    assert [d.code for d in config.diagnostics] == ["NODE_NOT_EXECUTABLE"]


def test_launched_scripts_are_extracted_in_the_one_batch(write_tree, monkeypatch):
    # found by rosrun's search, the script is extracted with every other node (one
    # extract_nodes call, its cache and its worker pool), not on its own afterwards
    from haros_arch import pipeline

    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\n",
        "src/pkg/test/relay": "#!/usr/bin/env python3\nimport rospy\n",
        "src/pkg/launch/r.launch": '<launch><node name="r" pkg="pkg" type="relay" /></launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/r.launch]\n",
    })
    os.chmod(root / "src/pkg/test/relay", 0o755)
    batches: list[list[str]] = []
    real = pipeline.extract_nodes

    def recording(nodes, *args, **kwargs):
        batches.append([node.name for node in nodes])
        return real(nodes, *args, **kwargs)

    monkeypatch.setattr(pipeline, "extract_nodes", recording)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert batches == [["pkg/relay"]]
    assert model.configurations[0].node("/r").node is not None


def test_a_launched_executable_that_is_not_python_is_there_but_not_read(write_tree):
    """cartographer_ros' grpc_demo_backpack_2d.launch starts ``cartographer_grpc_server.sh``
    (scripts/, executable): roslaunch finds it in the package's folder and runs it, so the
    launch does not name a missing executable (launch-missing-reference, an error); the
    tool does not read shell scripts, so its interface is unknown (NODE_NOT_READ, a
    warning). A file without its execute bit is found and refused by roslaunch
    (NODE_NOT_EXECUTABLE, panther_ros' fan_controller.py); a name that no file of the
    package has stays NODE_NOT_FOUND. Both are launch-missing-reference."""
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\n",
        "src/pkg/scripts/server.sh": "#!/bin/bash\nexec server_binary \"$@\"\n",
        "src/pkg/scripts/notes.sh": "#!/bin/bash\n",
        "src/pkg/launch/s.launch": """
            <launch>
              <node name="server" pkg="pkg" type="server.sh" />
              <node name="notes" pkg="pkg" type="notes.sh" />
              <node name="gone" pkg="pkg" type="missing_node" />
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/s.launch]\n",
    })
    os.chmod(root / "src/pkg/scripts/server.sh", 0o755)  # notes.sh: not executable
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    assert config.node("/server").node is None
    assert [(d.code, d.location.line, d.message) for d in config.diagnostics] == [
        ("NODE_NOT_READ", 2, "node type pkg/server.sh is pkg/scripts/server.sh, a program "
                             "this tool does not read (not a built target nor a Python "
                             "program); its interface is unknown"),
        ("NODE_NOT_EXECUTABLE", 3, "node type pkg/notes.sh: pkg/scripts/notes.sh is there "
                                   "but not executable, so roslaunch cannot start it; its "
                                   "interface is not read"),
        ("NODE_NOT_FOUND", 4, "node type pkg/missing_node is not in the workspace; its "
                              "interface is unknown; package pkg is in the workspace, with "
                              "no program found in its build files")]
    from haros_arch.query.catalogue import run_catalogue
    findings = [(f.rule, f.location.line) for f in run_catalogue(model)
                if f.rule == "launch-missing-reference"]
    assert findings == [("launch-missing-reference", 3), ("launch-missing-reference", 4)]
