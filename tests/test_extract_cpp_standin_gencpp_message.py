"""A message header that gencpp generated and a package keeps in its source (robocup_
catkin_ws_2024's serial_mcu: ``include/serial_mcu/Motor_msg.h`` beside its node) parses:
it specialises roscpp's message traits, its serializer (``ROS_DECLARE_ALLINONE_
SERIALIZER``) and printer for its ``Motor_msg_<ContainerAllocator>`` struct, whose
vector fields take ``ContainerAllocator::template rebind<int32_t>::other``. The stand-ins
declared none of these: every specialisation was an error, the class holding such a
message invalid, and its node partial (``start()`` of its QThread base an error beside
the node's subscriptions). The header below is written in gencpp's form, cut to one
scalar and one vector field."""

from __future__ import annotations

from standin_gap_checks import assert_call_found, ros1_main

GENERATED = """
#include <string>
#include <vector>
#include <ros/types.h>
#include <ros/serialization.h>
#include <ros/builtin_message_traits.h>
#include <ros/message_operations.h>
namespace serial_mcu {
template <class ContainerAllocator>
struct Motor_msg_ {
  typedef Motor_msg_<ContainerAllocator> Type;
  Motor_msg_() : length(0), id() {}
  Motor_msg_(const ContainerAllocator& _alloc) : length(0), id(_alloc) { (void)_alloc; }
  typedef int32_t _length_type;
  _length_type length;
  typedef std::vector<int32_t, typename ContainerAllocator::template rebind<int32_t>::other>
      _id_type;
  _id_type id;
  typedef boost::shared_ptr< ::serial_mcu::Motor_msg_<ContainerAllocator> > Ptr;
  typedef boost::shared_ptr< ::serial_mcu::Motor_msg_<ContainerAllocator> const> ConstPtr;
};
typedef ::serial_mcu::Motor_msg_<std::allocator<void> > Motor_msg;
typedef boost::shared_ptr< ::serial_mcu::Motor_msg const> Motor_msgConstPtr;
template<typename ContainerAllocator>
std::ostream& operator<<(std::ostream& s, const ::serial_mcu::Motor_msg_<ContainerAllocator>& v)
{
  ros::message_operations::Printer< ::serial_mcu::Motor_msg_<ContainerAllocator> >::stream(
      s, "", v);
  return s;
}
}  // namespace serial_mcu
namespace ros {
namespace message_traits {
template <class ContainerAllocator>
struct IsFixedSize< ::serial_mcu::Motor_msg_<ContainerAllocator> > : FalseType {};
template <class ContainerAllocator>
struct IsMessage< ::serial_mcu::Motor_msg_<ContainerAllocator> > : TrueType {};
template <class ContainerAllocator>
struct HasHeader< ::serial_mcu::Motor_msg_<ContainerAllocator> > : FalseType {};
template<class ContainerAllocator>
struct MD5Sum< ::serial_mcu::Motor_msg_<ContainerAllocator> > {
  static const char* value() { return "0123456789abcdef0123456789abcdef"; }
  static const char* value(const ::serial_mcu::Motor_msg_<ContainerAllocator>&) {
    return value(); }
  static const uint64_t static_value1 = 0x0123456789abcdefULL;
};
template<class ContainerAllocator>
struct DataType< ::serial_mcu::Motor_msg_<ContainerAllocator> > {
  static const char* value() { return "serial_mcu/Motor_msg"; }
  static const char* value(const ::serial_mcu::Motor_msg_<ContainerAllocator>&) {
    return value(); }
};
template<class ContainerAllocator>
struct Definition< ::serial_mcu::Motor_msg_<ContainerAllocator> > {
  static const char* value() { return "int32 length\\nint32[] id\\n"; }
  static const char* value(const ::serial_mcu::Motor_msg_<ContainerAllocator>&) {
    return value(); }
};
}  // namespace message_traits
}  // namespace ros
namespace ros {
namespace serialization {
template<class ContainerAllocator> struct Serializer< ::serial_mcu::Motor_msg_<ContainerAllocator> >
{
  template<typename Stream, typename T> inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.length);
    stream.next(m.id);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
}  // namespace serialization
}  // namespace ros
namespace ros {
namespace message_operations {
template<class ContainerAllocator>
struct Printer< ::serial_mcu::Motor_msg_<ContainerAllocator> >
{
  template<typename Stream> static void stream(
      Stream& s, const std::string& indent, const ::serial_mcu::Motor_msg_<ContainerAllocator>& v)
  {
    s << indent << "length: ";
    Printer<int32_t>::stream(s, indent + "  ", v.length);
    for (size_t i = 0; i < v.id.size(); ++i)
    {
      s << indent << "  id[" << i << "]: ";
      Printer<int32_t>::stream(s, indent + "  ", v.id[i]);
    }
  }
};
}  // namespace message_operations
}  // namespace ros
struct Holder {
  serial_mcu::Motor_msg motor;
  void handle(const serial_mcu::Motor_msg::ConstPtr& msg) { motor = *msg; }
};
"""

BODY = """
  Holder holder;
  ros::Subscriber sub = nh.subscribe("motor", 10, &Holder::handle, &holder);
  std::cout << holder.motor;
  uint32_t size = ros::serialization::serializationLength(holder.motor);
"""


def test_a_kept_gencpp_message_header_parses(tmp_path) -> None:
    assert_call_found(tmp_path, ros1_main("#include <iostream>\n" + GENERATED, BODY))
