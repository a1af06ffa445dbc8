"""An argument of the command line that the top-level file uses without declaring it
(roslaunch makes every ``name:=value`` of its command line an argument of that file) is
as unset as one declared without a value: the text around it stays. dvrk_video's
gscam_decklink_stereo.launch includes one camera file in ``ns="$(arg rig_name)/left"``
and again in ``ns="$(arg rig_name)/right"`` with no <arg name="rig_name">: the whole
namespace was ``?`` for both, so the two cameras had one name and were a
LAUNCH_NODE_DUPLICATE error that no value of rig_name makes."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

CAMERA = """
    <launch>
      <arg name="camera_name" default="camera"/>
      <node ns="decklink" name="$(arg camera_name)" pkg="p" type="cam"/>
    </launch>
    """

STEREO = """
    <launch>
      <include file="$(dirname)/camera.launch" ns="$(arg rig_name)/left">
        <arg name="camera_name" value="$(arg rig_name)_left"/>
      </include>
      <include file="$(dirname)/camera.launch" ns="$(arg rig_name)/right">
        <arg name="camera_name" value="$(arg rig_name)_right"/>
      </include>
      <node name="view" pkg="p" type="v" args="image:=/$(arg rig_name)/left/image"/>
    </launch>
    """


def _load(write_tree, args: dict[str, str] | None = None):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/launch/main.launch": STEREO,
                       "src/pkg/launch/camera.launch": CAMERA})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/pkg/launch/main.launch"), ws, args or {}, {})


def test_an_undeclared_command_line_argument_keeps_the_text_around_it(write_tree):
    model = _load(write_tree)
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/?/left/decklink/?_left", ""), ("/?/right/decklink/?_right", ""),
        ("/view", "image:=/?/left/image")]
    codes = [d.code for d in model.diagnostics]
    assert "LAUNCH_NODE_DUPLICATE" not in codes
    assert set(codes) == {"LAUNCH_ARG_UNSET"}


def test_the_command_line_value_is_used(write_tree):
    model = _load(write_tree, {"rig_name": "jhu"})
    assert [n.name for n in model.nodes] == [
        "/jhu/left/decklink/jhu_left", "/jhu/right/decklink/jhu_right", "/view"]
    assert model.diagnostics == []
