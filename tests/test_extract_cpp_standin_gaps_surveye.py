"""Stand-in gaps seen on real ROS 2 code (bench/README, helper surveyE): each left a C++
error in a function of a node, which made the node partial where that function calls the
ROS API (EduArt's edu_robot, pf-robotics' kachaka-api)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros2_main

CASES = {
    # Eigen's complete orthogonal decomposition and its pseudo-inverse (edu_robot's
    # universal bots invert their kinematic matrix so in initialize)
    "complete_orthogonal_decomposition": (
        "#include <Eigen/Dense>\n",
        "  Eigen::MatrixXf kinematic(4, 3);\n"
        "  Eigen::MatrixXf inverse = kinematic.completeOrthogonalDecomposition().pseudoInverse();\n"
        "  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(Eigen::MatrixXd(3, 3));\n"
        "  auto rank = cod.rank();\n"),
    # a plane rotation times a vector (edu_robot's odometry estimator)
    "rotation2d_times_vector": (
        "#include <Eigen/Geometry>\n",
        "  const Eigen::Vector2f velocity(1.0f, 0.0f);\n"
        "  const Eigen::Vector2f direction = Eigen::Rotation2Df(0.5f) * velocity;\n"
        "  Eigen::Rotation2Dd turn =\n"
        "      Eigen::Rotation2Dd(0.1) * Eigen::Rotation2Dd(0.2).inverse();\n"),
    # a map filled with the elements of another's range (edu_robot's diagnostics)
    "map_range_insert": (
        "#include <map>\n#include <string>\n",
        "  std::map<std::string, int> entries, more;\n"
        "  entries.insert(more.begin(), more.end());\n"),
    # cv::Mat's MatSize member, a two-index ptr, and cv_bridge's compressed image copy
    # (kachaka's hand recognition node reads a network's output and its image so)
    "mat_size_and_compressed_copy": (
        "#include <cv_bridge/cv_bridge.hpp>\n#include <sensor_msgs/msg/compressed_image.hpp>\n",
        "  cv::Mat result;\n"
        "  const int height = result.size[2];\n"
        "  cv::Size whole = result.size();\n"
        "  float* row = reinterpret_cast<float*>(result.ptr(0, height));\n"
        "  sensor_msgs::msg::CompressedImage::ConstSharedPtr msg;\n"
        "  cv::Mat image = cv_bridge::toCvCopy(msg, \"bgr8\")->image;\n"
        "  cv::Mat other = cv_bridge::toCvCopy(*msg)->image;\n"),
    # nlohmann/json, installed, not in the workspace (kachaka's diagnostics bridge reads
    # its error table so before it makes its topic bridge): the header was missing, and
    # ``element["code"].get<int>()`` of a name declared permissively an error
    "nlohmann_json": (
        "#include <map>\n#include <fstream>\n#include <nlohmann/json.hpp>\n"
        "using json = nlohmann::json;\n"
        "struct Pose { double x; NLOHMANN_DEFINE_TYPE_INTRUSIVE(Pose, x) };\n",
        "  json table = json::parse(std::string(\"[]\"));\n"
        "  std::map<std::string, json> by_code;\n"
        "  for (auto& element : table) {\n"
        "    auto code = std::to_string(element[\"code\"].get<int>());\n"
        "    by_code[code] = element;\n"
        "  }\n"
        "  std::ifstream file(\"config.json\");\n"
        "  json config;\n"
        "  file >> config;\n"
        "  std::string topic = config.value(\"topic\", \"out\");\n"
        "  double rate = config.value(\"rate\", 10.0);\n"
        "  std::string name = config[\"name\"];\n"
        "  if (config.contains(\"frames\") && config[\"frames\"].is_array()) {\n"
        "    for (const auto& item : config[\"frames\"].items()) {\n"
        "      std::string key = item.key();\n"
        "      int n = item.value().get<int>();\n"
        "    }\n"
        "  }\n"
        "  json reply = {{\"ok\", true}, {\"rate\", rate}};\n"
        "  reply[\"names\"].push_back(name);\n"
        "  std::string text = reply.dump(2);\n"
        "  try { json::parse(text); } catch (const json::parse_error& e) { e.what(); }\n"),
    # SocketCAN (``linux/can.h``, ``linux/can/raw.h``) and ``net/if.h``'s interface
    # request: edu_robot's CAN gateway opens its bus so (26 errors, the headers missing)
    "socketcan": (
        "#include <cstring>\n#include <unistd.h>\n#include <sys/ioctl.h>\n"
        "#include <sys/socket.h>\n#include <net/if.h>\n#include <linux/can.h>\n"
        "#include <linux/can/raw.h>\n#include <linux/can/error.h>\n",
        "  int fd = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);\n"
        "  int enable = 1;\n"
        "  ::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &enable, sizeof(enable));\n"
        "  ifreq ifr;\n"
        "  std::strcpy(ifr.ifr_name, \"can0\");\n"
        "  ::ioctl(fd, SIOCGIFINDEX, &ifr);\n"
        "  sockaddr_can addr;\n"
        "  addr.can_family = AF_CAN;\n"
        "  addr.can_ifindex = ifr.ifr_ifindex;\n"
        "  ::bind(fd, (sockaddr *)&addr, sizeof(addr));\n"
        "  can_frame frame;\n"
        "  frame.can_id = 0x123 | CAN_EFF_FLAG;\n"
        "  frame.can_dlc = 8;\n"
        "  std::memset(frame.data, 0, CAN_MAX_DLEN);\n"
        "  ::write(fd, &frame, sizeof(can_frame));\n"
        "  canfd_frame fd_frame;\n"
        "  fd_frame.len = 64;\n"
        "  ::send(fd, &fd_frame, sizeof(canfd_frame), 0);\n"
        "  can_filter filter{0x100, CAN_SFF_MASK};\n"
        "  ::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, &filter, sizeof(filter));\n"
        "  unsigned int index = if_nametoindex(\"can0\");\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros2_main(include, body), "ament_cmake", "jazzy")
