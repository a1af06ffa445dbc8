from __future__ import annotations

import pytest

from haros_arch.project import ProjectError, load


def load_text(tmp_path, text):
    path = tmp_path / "project.yaml"
    path.write_text(text)
    return load(str(path))


def test_haros_project_file_loads_as_is(tmp_path):
    (tmp_path / "src").mkdir()
    project = load_text(tmp_path, """%YAML 1.1
---
project: Fictibot
packages:
  - fictibot_drivers
  - fictibot_controller
repositories:
  fictibot:
    type: git
    url: https://example.org/fictibot.git
configurations:
  multiplex:
    launch:
      - minimal_robot/launch/minimal_robot.launch
      - fictibot_controller/launch/multiplexer.launch
    user_data:
      haros_tutorial:
        ignore_nodes: [/rosout]
    hints:
      /fictibot_driver:
        publishers:
          - topic: /wheel_cmd
            msg_type: std_msgs/Int32
  short: [minimal_robot/launch/minimal_robot.launch]
nodes:
  fictibot_drivers/fictibot_driver:
    rosname: fictibot_driver
rules:
  custom_rule:
    name: A rule
    description: Something
    query: "nodes"
""")
    assert project.name == "Fictibot"
    assert project.packages == ["fictibot_drivers", "fictibot_controller"]
    assert [c.name for c in project.configurations] == ["multiplex", "short"]
    multiplex = project.configurations[0]
    assert multiplex.launch[1] == "fictibot_controller/launch/multiplexer.launch"
    assert multiplex.hints["/fictibot_driver"]["publishers"][0]["topic"] == "/wheel_cmd"
    assert multiplex.user_data["haros_tutorial"]["ignore_nodes"] == ["/rosout"]
    assert project.nodes["fictibot_drivers/fictibot_driver"]["rosname"] == "fictibot_driver"
    assert project.workspace == [str(tmp_path / "src")]


def test_our_keys_args_environment_workspace_and_list_form(tmp_path):
    project = load_text(tmp_path, """
project: p
workspace: [ws_a, ../ws_b]
environment: {ROBOT: r1}
configurations:
  - name: sim
    launch: pkg/launch/sim.launch
    args: {use_sim: true, rate: 10, name: bob}
    environment: {GAZEBO: "1"}
queries:
  - {id: q1, query: "nodes"}
""")
    assert project.workspace == [str(tmp_path / "ws_a"), str(tmp_path.parent / "ws_b")]
    sim = project.configurations[0]
    assert sim.launch == ["pkg/launch/sim.launch"]
    assert sim.args == {"use_sim": "true", "rate": "10", "name": "bob"}
    assert sim.environment == {"GAZEBO": "1"}
    assert project.environment == {"ROBOT": "r1"}
    assert project.queries == [{"id": "q1", "query": "nodes"}]


def test_workspace_defaults_to_project_folder_without_src(tmp_path):
    project = load_text(tmp_path, "project: p\n")
    assert project.workspace == [str(tmp_path)]


@pytest.mark.parametrize(("text", "line", "words"), [
    ("project: p\nfoo: 1\n", 2, "unknown key 'foo'"),
    ("project: [\n", 2, "invalid YAML"),
    ("project: p\nconfigurations:\n  a:\n    lunch: [x]\n", 4, "unknown key 'lunch'"),
    ("project: p\nconfigurations:\n  a:\n    launch: {x: 1}\n", 4, "list of strings"),
    ("project: p\nconfigurations:\n  a:\n    args: [1]\n", 4, "must be a mapping"),
    ("project: p\nconfigurations:\n  a:\n    hints: {}\n", 3, "names no launch files"),
    ("project: p\nconfigurations: [{launch: [x]}]\n", 2, "needs a 'name'"),
    ("project: p\nconfigurations:\n  a:\n    launch: [x]\n    rostest: yes please\n", 5,
     "true or false"),
    ("- just\n- a list\n", 1, "must be a mapping"),
    ("project: {a: 1}\n", 1, "must be a string"),
    ("project: p\nconfigurations: {a: [x], a: [y]}\n", 2, "defined twice"),
    ("", 1, "empty"),
])
def test_bad_project_files_name_file_and_line(tmp_path, text, line, words):
    with pytest.raises(ProjectError) as caught:
        load_text(tmp_path, text)
    assert caught.value.line == line
    assert words in caught.value.message
    assert str(caught.value).startswith(f"{tmp_path / 'project.yaml'}:{line}:")


def test_missing_project_file(tmp_path):
    with pytest.raises(ProjectError) as caught:
        load(str(tmp_path / "none.yaml"))
    assert "cannot read" in str(caught.value)


def test_yaml_tags_that_would_run_code_are_refused(tmp_path):
    with pytest.raises(ProjectError) as caught:
        load_text(tmp_path, "project: !!python/object/apply:os.system ['true']\n")
    assert caught.value.line == 1


def test_yaml_tags_inside_free_form_sections_are_refused(tmp_path):
    with pytest.raises(ProjectError) as caught:
        load_text(tmp_path, "project: p\nnodes:\n  x: !!python/object/apply:os.system ['true']\n")
    assert caught.value.line == 3
    assert "invalid value" in caught.value.message
