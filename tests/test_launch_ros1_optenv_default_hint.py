"""A file missing at a path that holds the default of an ``$(optenv NAME default)``
whose variable is not set: cob_bringup's robot launch files name their configuration
``$(find cob_hardware_config)/robots/$(arg robot)/...``, ``robot`` defaulting to
``$(optenv ROBOT !!NO_ROBOT_SET!!)``: twelve "file does not exist" errors, true for that
run, that did not say the launch wants ROBOT set. Now they say so."""

from __future__ import annotations

from test_launch_ros1 import load_launch

LAUNCH = """<launch>
  <arg name="robot" default="$(optenv ROBOT !!NO_ROBOT_SET!!)"/>
  <arg name="pkg" default="$(optenv PKG_FOLDER pkg)"/>
  <include file="$(find pkg)/robots/$(arg robot)/upload.launch"/>
  <rosparam command="load" file="$(find pkg)/robots/$(arg robot)/config.yaml"/>
  <rosparam command="load" file="$(find pkg)/config/missing.yaml"/>
</launch>"""


def _said(model):
    return [d.message for d in model.diagnostics
            if d.code in ("LAUNCH_FILE_MISSING", "LAUNCH_BAD_VALUE")]


def test_a_missing_file_under_an_unset_optenv_default_says_so(write_tree):
    # (the robots' folder is there: the part of the path that is not is the default)
    include, param, plain = _said(load_launch(write_tree, LAUNCH, extra={
        "src/pkg/robots/cob4-2/upload.launch": "<launch/>"}))
    hint = "(the path holds '!!NO_ROBOT_SET!!', the default of $(optenv ROBOT): ROBOT " \
           "is not set here)"
    assert include.endswith("upload.launch " + hint + " does not exist"), include
    assert hint in param
    assert "optenv" not in plain  # a path that holds no such default


def test_with_the_variable_set_the_file_is_read(write_tree):
    model = load_launch(write_tree, LAUNCH, env={"ROBOT": "cob4-2"}, extra={
        "src/pkg/robots/cob4-2/upload.launch": "<launch/>",
        "src/pkg/robots/cob4-2/config.yaml": "a: 1\n"})
    assert len(_said(model)) == 1 and "missing.yaml" in _said(model)[0]
