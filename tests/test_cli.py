"""The command line as a user meets it: exit codes, messages, never a traceback."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys

from conftest import FIXTURES, ROOT, package_xml

from haros_arch.cli import main


def run(*args: str, cwd=None) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "COLUMNS": "200"}
    env.pop("HAROS_ARCH_DEBUG", None)
    return subprocess.run([sys.executable, "-m", "haros_arch.cli", *args], cwd=cwd or ROOT,
                          capture_output=True, text=True, env=env, timeout=300)


def test_extract_writes_the_json_model(tmp_path):
    out = tmp_path / "model.json"
    result = run("extract", str(FIXTURES / "paper_minimal/project.yaml"), "-o", str(out))
    assert result.returncode == 0, result.stderr
    model = json.loads(out.read_text())
    assert model["schema"] == "haros-arch/1"
    assert [t["name"] for t in model["configurations"][0]["topics"]] == ["/chatter"]
    # a summary: counts per kind, not every resource (-v lists them)
    assert "configuration minimal: 2 nodes, 1 topics, 1 services, 0 actions, " \
        "2 parameters, 5 links" in result.stdout
    assert "every node's interface is known" in result.stdout
    assert "/chatter" not in result.stdout
    verbose = run("extract", str(FIXTURES / "paper_minimal/project.yaml"), "-o", str(out),
                  "-v")
    assert "topic   /chatter" in verbose.stdout and "read by: /talker" in verbose.stdout


def test_malformed_project_file_exits_2_with_file_and_line(tmp_path):
    bad = tmp_path / "project.yaml"
    bad.write_text("project: p\nconfigurations:\n  a:\n    launch: [x\n")
    result = run("extract", str(bad))
    assert result.returncode == 2
    assert f"{bad}:5:" in result.stderr
    assert "Traceback" not in result.stderr


def test_missing_workspace_exits_2(tmp_path):
    project = tmp_path / "project.yaml"
    project.write_text("project: p\nworkspace: does_not_exist\n")
    result = run("check", str(project))
    assert result.returncode == 2
    assert "does_not_exist does not exist" in result.stderr


def test_missing_launch_file_is_a_diagnostic(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "project.yaml": """
            project: p
            configurations:
              c:
                launch: [pkg/launch/nope.launch, other_pkg/launch/a.launch]
            """,
    })
    result = run("check", str(root / "project.yaml"), "--format", "json")
    assert result.returncode == 1
    # the catalogue query launch-missing-reference turns these diagnostics into findings
    report = json.loads(result.stdout)
    found = [(f["rule"], f["location"]["line"]) for f in report["findings"]]
    assert found == [("launch-missing-reference", 4), ("launch-missing-reference", 4)]
    messages = " ".join(f["message"] for f in report["findings"])
    assert "pkg/launch/nope.launch does not exist" in messages
    assert "package other_pkg" in messages


def test_cpp_syntax_errors_are_diagnostics_and_the_rest_is_kept(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\nadd_executable(n src/n.cpp)\n",
        "src/pkg/src/n.cpp": """
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            int main(int argc, char** argv) {
              ros::init(argc, argv, "n");
              ros::NodeHandle nh;
              ros::Publisher p = nh.advertise<std_msgs::String>("out", 1);
              int x = ;
              return 0;
            }
            """,
        "src/pkg/launch/a.launch": '<launch><node name="n" pkg="pkg" type="n"/></launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    # a C++ error is information (usually our stand-in headers lack an API); that the node's
    # calls may be missing is a warning (CPP_NODE_PARTIAL): it fails --fail-on warning, not
    # --fail-on error
    lenient = run("check", str(root / "project.yaml"), "--format", "json",
                  "--fail-on", "error")
    assert lenient.returncode == 0
    partial = [d for d in json.loads(lenient.stdout)["diagnostics"]
               if d["code"] == "CPP_NODE_PARTIAL"]
    assert [d["severity"] for d in partial] == ["warning"]
    result = run("check", str(root / "project.yaml"), "--format", "json", "--fail-on", "info")
    assert result.returncode == 1
    found = json.loads(result.stdout)["diagnostics"]
    errors = [(d["code"], d["location"]["file"], d["location"]["line"]) for d in found]
    assert ("CPP_PARSE_ERROR", "pkg/src/n.cpp", 7) in errors
    extracted = run("extract", str(root / "project.yaml"), "-q")
    model = json.loads(extracted.stdout)
    assert [t["name"] for t in model["configurations"][0]["topics"]] == ["/out"]


def test_check_exit_codes_follow_fail_on(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/launch/a.launch": '<launch><nodes/></launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    assert main(["check", str(root / "project.yaml")]) == 0
    assert main(["check", str(root / "project.yaml"), "--fail-on", "warning"]) == 1


def test_explain_lists_codes(capsys):
    assert main(["explain", "LAUNCH_UNKNOWN_TAG"]) == 0
    assert "roslaunch ignores tags" in capsys.readouterr().out
    assert main(["explain", "NO_SUCH_CODE"]) == 2
    capsys.readouterr()
    # the ids of findings that are not rules of their own: what they are, and the rule
    assert main(["explain", "parameter-set-not-read-undecided"]) == 0
    text = capsys.readouterr().out
    assert "partial or unknown interface" in text and "Parameter set but never read" in text
    assert main(["explain", "query-limit"]) == 0
    assert "step budget" in capsys.readouterr().out


def test_text_that_looks_like_markup_is_printed_as_it_is(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/launch/a.launch": '<launch><node name="x" pkg="[/c1]" type="[bold]t"/>'
                                   "</launch>\n",
        "project.yaml": "project: '[red]p'\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    result = run("extract", str(root / "project.yaml"), "-o", str(root / "m.json"), "-v")
    assert result.returncode == 0, result.stderr
    assert "[red]p" in result.stdout
    assert "[/c1]/[bold]t" in result.stdout
    # the node's package is nowhere: its interface is unknown, and the summary says so
    assert "1 node(s) whose interface is not fully known (1 unknown)" in result.stdout
    assert re.search(r"/x  \?, unknown: no source", result.stdout)


def test_check_text_counts_info_diagnostics_unless_verbose(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\nadd_executable(n src/n.cpp)\n",
        "src/pkg/src/n.cpp": """
            #include <ros/ros.h>
            int main(int argc, char** argv) {
              ros::init(argc, argv, "n");
              int x = ;
              int y = ;
              return 0;
            }
            """,
        "src/pkg/launch/a.launch": '<launch><node name="n" pkg="pkg" type="n"/>\n'
                                   '<node name="m" pkg="pkg" type="missing"/></launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    compact = run("check", str(root / "project.yaml"), "--fail-on", "never")
    assert compact.returncode == 0
    # the two C++ errors (info) are counted under their code with the first place seen
    assert "2 info diagnostic(s), not listed (--verbose lists them)" in compact.stdout
    assert re.search(r"^ +2 CPP_PARSE_ERROR +first at pkg/src/n\.cpp:4:", compact.stdout, re.M)
    assert "pkg/src/n.cpp:5:" not in compact.stdout
    verbose = run("check", str(root / "project.yaml"), "--fail-on", "never", "-v")
    assert "pkg/src/n.cpp:4:" in verbose.stdout and "pkg/src/n.cpp:5:" in verbose.stdout
    assert "not listed" not in verbose.stdout


def test_the_summary_says_when_launch_includes_were_not_read(tmp_path, write_tree):
    """A configuration whose launch file includes a file the launch stage cannot read
    (an installed package's) printed "every node's interface is known", though what the
    include starts is not seen (webots_ros2's robot configurations: 0 nodes). It says how
    many includes or actions were not read; and a reason's ``file:100:`` is not taken for
    an emoji code (rviz2's model's reason printed a hundred-points emoji)."""
    root = write_tree({
        "src/app/package.xml": package_xml("app", build_type="ament_python"),
        "src/app/setup.py": "from setuptools import setup\nsetup(name='app')\n",
        "src/app/launch/app.launch.py": (
            "from launch import LaunchDescription\n"
            "from launch.actions import IncludeLaunchDescription\n"
            "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
            "from ament_index_python.packages import get_package_share_directory\n"
            "def generate_launch_description():\n"
            "    share = get_package_share_directory('vendor_sim')\n"
            "    return LaunchDescription([IncludeLaunchDescription(\n"
            "        PythonLaunchDescriptionSource(share + '/launch/sim.launch.py'))])\n"),
    })
    result = run("extract", str(root / "src"), "-o", str(tmp_path / "m.json"))
    assert result.returncode == 0, result.stderr
    assert "1 launch include(s) or action(s) not read" in result.stdout
    assert "every node's interface is known" not in result.stdout

    from haros_arch.cli import make_console

    console = make_console()
    with console.capture() as captured:
        console.print("view_controller.cpp:100: C++ error")
    assert "view_controller.cpp:100: C++ error" in captured.get()


def test_an_output_in_a_missing_folder_is_written_and_a_bad_one_refused_before_the_run(
        tmp_path):
    project = str(FIXTURES / "paper_minimal/project.yaml")
    out = tmp_path / "out" / "models" / "model.json"
    result = run("extract", project, "-o", str(out))
    assert result.returncode == 0, result.stderr
    assert json.loads(out.read_text())["schema"] == "haros-arch/1"
    # a folder, or a path below a file: refused at once, with no run and no traceback
    blocker = tmp_path / "plain-file"
    blocker.write_text("x")
    for bad, why in ((tmp_path, "it is a folder"), (blocker / "model.json", "cannot make"),
                     (blocker / "a" / "report.html", "cannot make")):
        command = "report" if str(bad).endswith(".html") else "extract"
        result = run(command, project, "-o", str(bad))
        assert result.returncode == 2
        assert f"cannot write {bad}: {why}" in result.stderr.replace("\n", "")
        assert "Traceback" not in result.stderr and "internal error" not in result.stderr
        assert "configuration" not in result.stdout + result.stderr  # nothing was run
