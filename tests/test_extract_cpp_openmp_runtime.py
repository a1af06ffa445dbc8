"""OpenMP's runtime functions called where the unit has no ``<omp.h>`` of its own
(bench/README, survey Z46: hdl_global_localization's RANSAC gets it through PCL's
headers in a real build): ``omp_get_max_threads()`` and ``omp_get_thread_num()`` have no
argument through which lookup could find a permissive friend, so they stayed undeclared,
errors in a function that reads parameters, and the node partial. They are the
compiler's runtime, declared as values like a missing C library's functions."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <random>
#include <vector>

int main(int argc, char** argv) {
  ros::init(argc, argv, "ransac");
  ros::NodeHandle pnh("~");
  std::vector<std::mt19937> mts(omp_get_max_threads());
#pragma omp parallel for
  for (int i = 0; i < 8; i++) {
    auto& mt = mts[omp_get_thread_num()];
  }
  int n = pnh.param<int>("max_iterations", 64);
  ros::Publisher pub = pnh.advertise<std_msgs::String>("result", 1);
  ros::spin();
}
"""


def test_openmp_runtime_calls_without_its_header(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("ransac"))
    source = tmp_path / "node.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    declared = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert len(declared) == 1 and "omp_get_max_threads" in declared[0]
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("read", "~max_iterations", 14), ("publish", "~result", 15)]
