// haros_arch stand-in: boost::iterator_facade (declarations only), the base a class
// derives to be an iterator from its own dereference / increment / equal (ROS 1
// rosbag_storage's View::iterator, whose MessageInstance a bag's reader asks
// ``it->getTopic()``); its operators, typed by the template's arguments
#ifndef HAROS_STANDIN_BOOST_ITERATOR_FACADE_HPP
#define HAROS_STANDIN_BOOST_ITERATOR_FACADE_HPP
#include <cstddef>
namespace boost {
struct incrementable_traversal_tag {};
struct single_pass_traversal_tag : incrementable_traversal_tag {};
struct forward_traversal_tag : single_pass_traversal_tag {};
struct bidirectional_traversal_tag : forward_traversal_tag {};
struct random_access_traversal_tag : bidirectional_traversal_tag {};
class iterator_core_access {};
template <class Derived, class Value, class CategoryOrTraversal, class Reference = Value&,
          class Difference = std::ptrdiff_t>
class iterator_facade {
public:
  typedef Value value_type;
  typedef Reference reference;
  typedef Value* pointer;
  typedef Difference difference_type;
  Reference operator*() const;
  Value* operator->() const;
  Reference operator[](Difference n) const;
  Derived& operator++();
  Derived operator++(int);
  Derived& operator--();
  Derived operator--(int);
  Derived& operator+=(Difference n);
  Derived& operator-=(Difference n);
  Derived operator+(Difference n) const;
  Derived operator-(Difference n) const;
  Difference operator-(const iterator_facade& other) const;
  bool operator==(const iterator_facade& other) const;
  bool operator!=(const iterator_facade& other) const;
  bool operator<(const iterator_facade& other) const;
};
}  // namespace boost
#endif
