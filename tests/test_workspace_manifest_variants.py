"""A package that keeps one manifest per ROS version and copies one to package.xml when
it builds (livox_ros_driver2 13eb05e: package_ROS1.xml, package_ROS2.xml, build.sh) is
no package until then: the scan says so (PACKAGE_MANIFEST_VARIANT, a warning naming the
folder and the manifests) instead of leaving it out silently; a folder with package.xml
beside such files is a package as before, with nothing said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.workspace import scan


def test_a_folder_with_manifests_by_ros_version_is_said(write_tree) -> None:
    root = write_tree({
        "src/livox_driver/package_ROS1.xml": package_xml("livox_driver", "catkin"),
        "src/livox_driver/package_ROS2.xml": package_xml("livox_driver", "ament_cmake"),
        "src/livox_driver/CMakeLists.txt": "project(livox_driver)\n",
        "src/livox_driver/src/driver_node.cpp": "int main() { return 0; }\n",
        "src/other/package.xml": package_xml("other", "ament_cmake"),
        "src/other/package_old.xml": package_xml("other", "catkin"),
    })
    ws = scan([str(root / "src")], {})
    assert sorted(ws.packages) == ["other"]
    said = [d for d in ws.diagnostics if d.code == "PACKAGE_MANIFEST_VARIANT"]
    assert [(d.severity, d.location.file) for d in said] == [
        ("warning", "livox_driver/package_ROS1.xml")]
    assert "folder livox_driver has package_ROS1.xml, package_ROS2.xml but no package.xml" \
        in said[0].message
