"""A call qualified by a class or namespace that none of a wrapper's namesakes is in is
no site of that wrapper: ros_canopen's ``canopen::create(nh, name, ...)`` advertises, and
``TypeGuard::create<T>()`` in a function the parse could not read whole made the node
partial (``CPP_CALL_MISSED``, ``CPP_ERROR_NEAR_CALL``) though it calls no ROS API."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp, recall
from haros_arch.workspace import Workspace

UNIT = r"""
#include <ros/ros.h>
#include <std_msgs/Int32.h>
#include <string>
namespace canopen {
class TypeGuard {
 public:
  template <typename T> static TypeGuard create() { return TypeGuard(sizeof(T)); }
  explicit TypeGuard(int size) : size_(size) {}
  bool operator==(const TypeGuard& other) const { return size_ == other.size_; }
 private:
  int size_;
};
template <typename T> class Offset {
 public:
  static bool same(const TypeGuard& guard) {
    if (TypeGuard::create<T>() == guard) {
      return true;
    }
    throw_missing_thing(guard);
    return false;
  }
};
template <int N>
static ros::Publisher create(ros::NodeHandle& nh, const std::string& name) {
  return nh.advertise<std_msgs::Int32>(name, N);
}
}  // namespace canopen
int main(int argc, char** argv) {
  ros::init(argc, argv, "q");
  ros::NodeHandle nh;
  ros::Publisher p = canopen::create<1>(nh, "out");
  ros::spin();
}
"""


def test_a_class_s_namesake_of_a_free_wrapper_hides_no_call(tmp_path):
    source = tmp_path / "q.cpp"
    source.write_text(UNIT)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
    codes = {d.code for d in result.diagnostics}
    assert "CPP_CALL_MISSED" not in codes
    assert "CPP_ERROR_NEAR_CALL" not in codes


def test_the_wrapper_s_own_namespace_or_none_still_marks_a_site():
    qualifiers = {("create", ""), ("create", "canopen")}
    text = "\n".join([
        "  x = TypeGuard::create<T>();",           # another class's: no site
        "  p = canopen::create<1>(nh, topic);",    # the wrapper's namespace
        "  p = create<1>(nh, topic);",             # unqualified
        "  q = Other::create(nh, topic);",         # another namespace: no site
    ])
    sites = recall.call_sites(text, ["create"], [], None, qualifiers)
    assert [s.line for s in sites] == [2, 3]
    # a name a method also has may be written through an alias: every qualifier counts
    assert [s.line for s in recall.call_sites(text, ["create"], [], None)] == [1, 2, 3, 4]
