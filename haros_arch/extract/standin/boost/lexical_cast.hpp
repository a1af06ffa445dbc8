// haros_arch stand-in: boost::lexical_cast (declarations only): gazebo_plugins'
// ``GazeboRosUtils::getParameter`` logs its default with it, beside a ROS call
#ifndef HAROS_STANDIN_BOOST_LEXICAL_CAST_HPP
#define HAROS_STANDIN_BOOST_LEXICAL_CAST_HPP
#include <string>
#include <typeinfo>
namespace boost {
class bad_lexical_cast : public std::bad_cast {
public:
  bad_lexical_cast();
  const char* what() const noexcept;
};
template<class Target, class Source> Target lexical_cast(const Source& arg);
template<class Target> Target lexical_cast(const char* chars, std::size_t count);
}  // namespace boost
#endif
