"""The ROS 2 distribution a workspace's own files name (``distro_guess``), used for its
interface models and the rclcpp its C++ is read against when neither a project
``distro:`` nor ROS_DISTRO says one: vector_pursuit_controller (its README: "ROS2
Humble") sets nav2's Humble lookup names, ``nav2_navfn_planner/NavfnPlanner``, which
Jazzy's models do not export: 6 PLUGIN_NOT_FOUND under the Jazzy default, none under
Humble's."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.distro_guess import guess
from haros_arch.pipeline import Options, analyse, source_distro
from haros_arch.project import load


def test_the_git_branch_decides_first(write_tree) -> None:
    root = write_tree({"repo/.git/HEAD": "ref: refs/heads/ros2-humble\n",
                       "repo/Dockerfile": "FROM ros:jazzy\n"})
    assert guess([str(root / "repo")])[0] == "humble"
    # a worktree's .git file; a branch naming no distribution leaves it to the files
    root = write_tree({"wt/.git": "gitdir: ../gitdir\n", "gitdir/HEAD": "ref: refs/heads/jazzy\n",
                       "main/.git/HEAD": "ref: refs/heads/main\n",
                       "main/.github/workflows/ci.yml": "env:\n  ROS_DISTRO: humble\n"})
    assert guess([str(root / "wt")])[0] == "jazzy"
    distro, why, _ = guess([str(root / "main")])
    assert distro == "humble" and ".github/workflows/ci.yml" in why
    # a workspace whose src/<repo> is the checkout
    root = write_tree({"ws/src/repo/.git/HEAD": "ref: refs/heads/humble-devel\n",
                       "ws/src/repo/pkg/package.xml": "<package/>"})
    assert guess([str(root / "ws")])[:3:2] == ("humble", True)


def test_build_files_then_readme_and_what_several_names_give(write_tree) -> None:
    root = write_tree({"a/.github/workflows/ci.yml": "matrix:\n  distro: [humble, jazzy]\n",
                       "a/README.md": "Works on ROS 2 Foxy.\n"})
    assert guess([str(root / "a")])[:3:2] == ("jazzy", False)  # the default, among others
    root = write_tree({"b/.github/workflows/ci.yml": "distro: [humble, iron, rolling]\n"})
    assert guess([str(root / "b")])[0] == "humble"  # the other release with models
    # a release without models of its own is no guess (its stand-ins would make every
    # modelled node partial): one older than Humble takes Humble's, the nearest after it,
    # and its rclcpp is not Humble's (sole: False); a newer one keeps the default
    root = write_tree({"c/ci.repos": "version: foxy\n", "c/docker/Dockerfile": "FROM ros:foxy\n"})
    distro, why, sole = guess([str(root / "c")])
    assert (distro, sole) == ("humble", False) and "foxy (2x)" in why and "nearest" in why
    root = write_tree({"g/.github/workflows/ci.yml": "distro: [rolling, kilted]\n"})
    assert guess([str(root / "g")]) is None
    root = write_tree({"f/.github/workflows/ci.yml": "distro: [iron, rolling]\n"})
    assert guess([str(root / "f")])[0] == "iron"
    root = write_tree({"d/README.md": "This ROS2 Humble package ... (not for ROS 1 Noetic)\n"})
    distro, why, _ = guess([str(root / "d")])
    assert distro == "humble" and "README" in why
    root = write_tree({"e/README.md": "A humble little robot.\n", "e/pkg/package.xml": "x"})
    assert guess([str(root / "e")]) is None  # prose without "ROS 2 <name>": no guess


PARAMS = """
planner_server:
  ros__parameters:
    planner_plugins: ["GridBased"]
    GridBased:
      plugin: "nav2_navfn_planner/NavfnPlanner"
      tolerance: 0.5
"""

LAUNCH = """
<launch>
  <node pkg="nav2_planner" exec="planner_server" name="planner_server">
    <param from="$(find-pkg-share demo)/config/nav.yaml"/>
  </node>
</launch>
"""


def _analysed(write_tree, extra: dict[str, str], env: dict[str, str] | None = None):
    root = write_tree({
        "src/demo/package.xml": package_xml("demo", "ament_cmake").replace(
            "</package>", "<exec_depend>nav2_planner</exec_depend></package>"),
        "src/demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\n"
            "install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n"
            "ament_package()\n"),
        "src/demo/config/nav.yaml": PARAMS,
        "src/demo/launch/nav.launch.xml": LAUNCH,
        "project.yaml": ("project: p\nworkspace: [src]\n"
                         "configurations:\n  c: [demo/launch/nav.launch.xml]\n"),
        **extra})
    project = load(str(root / "project.yaml"))
    run_env = {"PATH": os.environ.get("PATH", ""), **(env or {})}
    model = analyse(project, run_env, Options(cache_dir=None))
    (config,) = model.configurations
    return project, config, run_env


def _said(config, code: str) -> list[str]:
    return [d.message for d in config.diagnostics if d.code == code]


def test_a_humble_tree_takes_humble_s_models(write_tree) -> None:
    project, config, env = _analysed(write_tree, {"src/demo/README.md": "For ROS 2 Humble.\n"})
    assert not _said(config, "PLUGIN_NOT_FOUND")
    (note,) = _said(config, "MODEL_DISTRO")
    assert "humble" in note and "README" in note
    assert source_distro(project, env) == "humble"


def test_a_foxy_tree_takes_humble_s_models_not_its_rclcpp(write_tree) -> None:
    # clober's foxy-devel: Foxy's nav2 lookup names, read against Jazzy's models, made a
    # false PLUGIN_NOT_FOUND and bt_navigator parameters "set but not read"
    project, config, env = _analysed(write_tree, {"src/demo/README.md": "For ROS 2 Foxy.\n"})
    assert not _said(config, "PLUGIN_NOT_FOUND")
    (note,) = _said(config, "MODEL_DISTRO")
    assert "humble" in note and "foxy" in note
    assert source_distro(project, env) is None  # its version tests stay undecided


def test_without_a_sign_or_with_ros_distro_set_no_guess(write_tree) -> None:
    project, config, env = _analysed(write_tree, {})
    assert _said(config, "PLUGIN_NOT_FOUND")  # Jazzy's nav2 exports no such lookup name
    assert "jazzy" in _said(config, "MODEL_DISTRO")[0]
    assert source_distro(project, env) is None
    project, config, env = _analysed(write_tree, {"src/demo/README.md": "For ROS 2 Humble.\n"},
                                     env={"ROS_DISTRO": "jazzy"})
    assert _said(config, "PLUGIN_NOT_FOUND")
    assert "ROS_DISTRO" in _said(config, "MODEL_DISTRO")[0]


def test_init_says_the_guess_without_setting_it(write_tree, tmp_path) -> None:
    from haros_arch.cli import main

    root = write_tree({
        "ws/src/demo/package.xml": package_xml("demo", "ament_cmake"),
        "ws/src/demo/launch/a.launch.xml": "<launch><node pkg='demo' exec='a'/></launch>\n",
        "ws/src/demo/Dockerfile": "FROM ros:humble-ros-base\n"})
    target = tmp_path / "project.yaml"
    assert main(["init", str(root / "ws"), "-o", str(target)]) == 0
    text = target.read_text()
    assert "# distro: humble  # guessed from its build and CI files" in text
    assert load(str(target)).distro is None


def test_the_c_plus_plus_is_read_for_a_release_only_when_it_is_the_one_named(write_tree):
    project, _config, env = _analysed(write_tree, {
        "src/demo/.github/workflows/ci.yml": "matrix: {distro: [humble, rolling]}\n"})
    assert source_distro(project, env) is None  # models humble's, version tests undecided


def test_a_folder_s_notes_say_the_guess(write_tree) -> None:
    from haros_arch.autoproject import choose

    root = write_tree({
        "ws/src/demo/package.xml": package_xml("demo", "ament_cmake"),
        "ws/src/demo/launch/a.launch.xml": "<launch><node pkg='demo' exec='a'/></launch>\n",
        "ws/src/demo/README.md": "A ROS2 Humble package.\n"})
    notes = choose(str(root / "ws"), environment={}).notes
    assert any(n.startswith("ROS 2 release humble, guessed from its README") for n in notes)
    notes = choose(str(root / "ws"), environment={"ROS_DISTRO": "jazzy"}).notes
    assert not any("ROS 2 release" in n for n in notes)


def test_a_tree_of_catkin_packages_alone_is_told_no_ros2_release(write_tree) -> None:
    # kr_autonomous_flight, ROS 1, whose README names Jazzy: the note said "ROS 2 release
    # jazzy, guessed from its README" of a tree no ROS 2 model or rclcpp is read for
    from haros_arch.autoproject import choose

    root = write_tree({
        "ws/src/demo/package.xml": package_xml("demo", "catkin"),
        "ws/src/demo/launch/a.launch": "<launch><node pkg='demo' type='a' name='a'/></launch>\n",
        "ws/src/demo/README.md": "Ported to ROS 2 Jazzy on another branch.\n"})
    notes = choose(str(root / "ws"), environment={}).notes
    assert not any("ROS 2 release" in n for n in notes), notes


def test_a_fifo_among_the_files_read_is_not_opened(tmp_path) -> None:
    # a hostile tree: a FIFO named Dockerfile (or README) would block an open() forever
    (tmp_path / "ws" / "pkg").mkdir(parents=True)
    os.mkfifo(tmp_path / "ws" / "Dockerfile")
    (tmp_path / "ws" / "README.md").write_text("Built for ROS 2 Humble.\n")
    distro, why, _ = guess([str(tmp_path / "ws")])
    assert distro == "humble" and "README" in why


MERGIFY = """pull_request_rules:
  - name: backport to jazzy at reviewers discretion
    conditions:
      - label=backport-jazzy
    actions:
      backport:
        branches:
          - jazzy
"""


def test_a_backport_bot_s_branches_are_not_what_the_tree_is_built_for(write_tree) -> None:
    # pb2025_sentry_nav: its Dockerfile and CI are humble's, its mergify.yml copies
    # changes to a jazzy branch; nav2's Humble lookup names in its parameters
    root = write_tree({"a/Dockerfile": "FROM ros:humble-ros-base\n",
                       "a/.github/workflows/ci.yml": "env:\n  ROS_DISTRO: humble\n",
                       "a/.github/mergify.yml": MERGIFY})
    distro, why, _ = guess([str(root / "a")])
    assert distro == "humble" and "jazzy" not in why
    # the configuration alone names no release the tree is built for
    root = write_tree({"b/.github/mergify.yml": MERGIFY, "b/pkg/package.xml": "x"})
    assert guess([str(root / "b")]) is None


def test_the_build_files_beside_the_src_folder_chosen_as_workspace(write_tree) -> None:
    # control_quadrupeds_soft_contacts: `check REPO` takes REPO/src as the workspace,
    # while the Dockerfile that names the release (`ARG BASE_TAG=iron-desktop`, then
    # `FROM osrf/ros:${BASE_TAG}`) sits beside src/: read, the tree is Iron's, not the
    # default Jazzy's (whose catalogue has no gazebo_msgs for its C++ to read)
    root = write_tree({"repo/Dockerfile": "ARG BASE_TAG=iron-desktop\n"
                                          "FROM osrf/ros:${BASE_TAG}\n",
                       "repo/src/pkg/package.xml": "<package/>",
                       "repo/src/pkg/README.md": "A package.\n"})
    distro, why, sole = guess([str(root / "repo" / "src")])
    assert (distro, sole) == ("iron", True) and "Dockerfile" in why
    # only the folder above a root named src: another root's parent is not read
    root = write_tree({"other/Dockerfile": "FROM ros:humble\n",
                       "other/ws/pkg/package.xml": "<package/>"})
    assert guess([str(root / "other" / "ws")]) is None


DISTRO_LAUNCH = """
import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    exe = 'servo_node_main' if os.environ.get('ROS_DISTRO') == 'humble' else 'servo_node'
    return LaunchDescription([Node(package='demo', executable=exe, name='servo')])
"""


def _distro_launch(write_tree, tree: str, ci: str, env: dict[str, str] | None = None):
    # a folder per tree: the guess is kept per folder for the process
    root = write_tree({
        f"{tree}/src/demo/package.xml": package_xml("demo", "ament_cmake"),
        f"{tree}/src/demo/launch/servo.launch.py": DISTRO_LAUNCH,
        f"{tree}/src/demo/.github/workflows/ci.yml": ci,
        f"{tree}/project.yaml": ("project: p\nworkspace: [src]\n"
                                 "configurations:\n  c: [demo/launch/servo.launch.py]\n")})
    project = load(str(root / tree / "project.yaml"))
    run_env = {"PATH": os.environ.get("PATH", ""), **(env or {})}
    (config,) = analyse(project, run_env, Options(cache_dir=None)).configurations
    return config


def _node_types(config) -> list[str]:
    """The node types the launch file asked for (the package builds none of them)."""
    return [d.message.split()[2] for d in config.diagnostics if d.code == "NODE_NOT_FOUND"]


def test_a_ros2_launch_file_runs_under_the_one_release_the_files_name(write_tree) -> None:
    # reseq_ros2's arm.launch.py picks moveit_servo's executable by ROS_DISTRO; its CI
    # names Humble alone, the release its C++ is read for: its launch files run where
    # Humble's setup script set ROS_DISTRO, so the node is servo_node_main, not `?`
    config = _distro_launch(write_tree, "one", "env:\n  ROS_DISTRO: humble\n")
    assert _node_types(config) == ["demo/servo_node_main"]
    # several releases named: not known which
    config = _distro_launch(write_tree, "several", "matrix:\n  distro: [humble, jazzy]\n")
    assert _node_types(config) == []
    assert "NODE_TYPE_UNKNOWN" in [d.code for d in config.diagnostics]
    # the run's own ROS_DISTRO wins over the guess
    config = _distro_launch(write_tree, "shell", "env:\n  ROS_DISTRO: humble\n",
                            {"ROS_DISTRO": "jazzy"})
    assert _node_types(config) == ["demo/servo_node"]
