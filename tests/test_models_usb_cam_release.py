"""The noetic usb_cam model is of the 0.3.7 release Noetic ships (tag 0.3.7, release
0.3.7-1), not of develop's later refactor (camera_driver.cpp, ``~intrinsic_controls/...``):
0.3.7's nodes/usb_cam_node.cpp reads brightness, contrast, saturation, sharpness, focus,
exposure, ... on the private handle. barc's
image_processing.launch (MPC-Berkeley/barc, 2018) sets ~sharpness, ~saturation and
~contrast of its usb_cam_node: with the develop model they were "set but never read"."""

from __future__ import annotations

from conftest import package_xml, unread_parameters

LAUNCH = """\
<launch>
  <node pkg="usb_cam" type="usb_cam_node" name="barc_cam">
    <param name="pixel_format" value="yuyv"/>
    <param name="sharpness" value="255"/>
    <param name="saturation" value="255"/>
    <param name="contrast" value="5"/>
    <param name="brightness" value="128"/>
    <param name="video_device" value="/dev/video6"/>
    <param name="not_a_usb_cam_parameter" value="1"/>
  </node>
</launch>
"""


def test_the_release_reads_the_camera_controls_on_its_private_handle(write_tree):
    root = write_tree({
        "src/cam/package.xml": package_xml("cam", "catkin"),
        "src/cam/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(cam)\n",
        "src/cam/launch/cam.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\nconfigurations:\n"
                        "  c: [cam/launch/cam.launch]\n",
    })
    unread = unread_parameters(root)
    # the one name no release reads stays said: the model is whole, not silenced
    assert unread == ["/barc_cam/not_a_usb_cam_parameter"]
