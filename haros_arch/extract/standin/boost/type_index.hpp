// haros_arch stand-in: Boost.TypeIndex (declarations only), a type's name at run time;
// every boost/type_index/... header stands in as this one (fuse's classes name their
// type with ``boost::typeindex::stl_type_index::type_id<T>().pretty_name()``). No ROS
// call.
#ifndef HAROS_STANDIN_BOOST_TYPE_INDEX_HPP
#define HAROS_STANDIN_BOOST_TYPE_INDEX_HPP
#include <cstddef>
#include <string>
namespace boost {
namespace typeindex {
class stl_type_index {
public:
  stl_type_index() noexcept;
  const char* raw_name() const noexcept;
  const char* name() const noexcept;
  std::string pretty_name() const;
  std::size_t hash_code() const noexcept;
  bool equal(const stl_type_index& other) const noexcept;
  bool before(const stl_type_index& other) const noexcept;
  template <class T> static stl_type_index type_id() noexcept;
  template <class T> static stl_type_index type_id_with_cvr() noexcept;
  template <class T> static stl_type_index type_id_runtime(const T& value) noexcept;
};
bool operator==(const stl_type_index& a, const stl_type_index& b) noexcept;
bool operator!=(const stl_type_index& a, const stl_type_index& b) noexcept;
bool operator<(const stl_type_index& a, const stl_type_index& b) noexcept;
typedef stl_type_index type_index;
typedef stl_type_index ctti_type_index;
template <class T> type_index type_id() noexcept;
template <class T> type_index type_id_with_cvr() noexcept;
template <class T> type_index type_id_runtime(const T& value) noexcept;
}  // namespace typeindex
}  // namespace boost
#endif
