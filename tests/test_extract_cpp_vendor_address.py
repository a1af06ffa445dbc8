"""The address of a value of a vendor type the parse does not know (its header missing,
its names declared permissively by ``synthesis``) given to the code's own function that
takes a pointer of a known type: the call is a call of that function, and the ROS calls
it makes are made with the arguments it is given. realsense-ros's
``readAndSetDynamicParam(nh1, ..., "left", ..., &(auto_exposure_roi.min_x))`` takes an
``int *``, ``auto_exposure_roi`` of librealsense's ``rs2::region_of_interest``: clang
kept each call as a recovery expression (``haros_any *`` converts to no ``int *``), and
the one read of the function stayed ``?/?`` (any parameter, global too) where the
callers name ``<camera>/<module>/auto_exposure_roi/left`` and its three siblings."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <vendor/sdk.hpp>
class Camera {
 public:
  explicit Camera(ros::NodeHandle& nh) : nh_(nh) {}
  void setup() {
    vendor::device device = vendor::first_device();
    vendor::sensor sensor = device.first_sensor();
    vendor::region roi = sensor.region();
    ros::NodeHandle roi_nh(nh_, "auto_exposure_roi");
    readBound(roi_nh, "left", &(roi.min_x));
    readBound(roi_nh, "right", &(roi.max_x));
    bool all = false;
    readBound(roi_nh, "top", all ? &(roi.min_y) : 0);
  }
  void readBound(ros::NodeHandle& nh, const std::string& name, int* value) {
    int read = 0;
    nh.param(name, read, 0);
    if (value) *value = read;
  }
  ros::NodeHandle nh_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "camera");
  ros::NodeHandle pnh("~");
  Camera camera(pnh);
  camera.setup();
}
"""


def test_a_vendor_value_s_address_given_to_the_code_s_function(write_tree) -> None:
    root = write_tree({"cam/package.xml": package_xml("cam", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "cam/src/camera.cpp": SOURCE})
    result = extract_cpp([str(root / "cam" / "src" / "camera.cpp")], scan([str(root)]),
                         cache_dir=None)
    reads = sorted((c.name, c.location.line) for c in result.calls if c.kind == "read")
    assert reads == [("~auto_exposure_roi/left", 11), ("~auto_exposure_roi/right", 12),
                     ("~auto_exposure_roi/top", 14)]
    codes = {d.code for d in result.diagnostics}
    assert "vendor" in str([d.message for d in result.diagnostics
                            if d.code == "CPP_NAMES_DECLARED"])  # the names were declared
    assert not codes & {"CPP_CALL_MISSED", "CPP_PARSE_ERROR"}
