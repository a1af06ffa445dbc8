// haros_arch stand-in: boost serialization (declarations only). Every header of the
// library includes this one: a class reads as it is written, its serialize() members
// are templates on the archive (never instantiated here).
#ifndef HAROS_STANDIN_BOOST_SERIALIZATION_HPP
#define HAROS_STANDIN_BOOST_SERIALIZATION_HPP
#include <cstddef>
#include <string>
namespace boost {
namespace serialization {
class access;
template<class T> struct nvp {
  const char * name;
  T * value;
};
template<class T> nvp<T> make_nvp(const char * name, T & value);
template<class Base, class Derived> Base & base_object(Derived & derived);
template<class Base, class Derived> const Base & base_object(const Derived & derived);
template<class T> struct array_wrapper {
  T * address;
  std::size_t count;
};
template<class T> array_wrapper<T> make_array(T * address, std::size_t count);
template<class T> struct version { static const unsigned int value = 0; };
}  // namespace serialization
namespace archive {
enum archive_flags { no_header = 1, no_codecvt = 2, no_xml_tag_checking = 4, no_tracking = 8 };
class archive_exception : public std::exception {
public:
  explicit archive_exception(int code, const char * e1 = nullptr, const char * e2 = nullptr);
  const char * what() const noexcept override;
};
class haros_archive {
public:
  template<class Stream> explicit haros_archive(Stream & stream, unsigned int flags = 0);
  template<class T> haros_archive & operator&(const T & value);
  template<class T> haros_archive & operator<<(const T & value);
  template<class T> haros_archive & operator>>(T & value);
  template<class T> void register_type(T * = nullptr);
};
class binary_oarchive : public haros_archive { using haros_archive::haros_archive; };
class binary_iarchive : public haros_archive { using haros_archive::haros_archive; };
class text_oarchive : public haros_archive { using haros_archive::haros_archive; };
class text_iarchive : public haros_archive { using haros_archive::haros_archive; };
class xml_oarchive : public haros_archive { using haros_archive::haros_archive; };
class xml_iarchive : public haros_archive { using haros_archive::haros_archive; };
}  // namespace archive
}  // namespace boost
#define BOOST_SERIALIZATION_NVP(name) ::boost::serialization::make_nvp(#name, name)
#define BOOST_SERIALIZATION_BASE_OBJECT_NVP(name) \
  ::boost::serialization::make_nvp(#name, ::boost::serialization::base_object<name>(*this))
#define BOOST_CLASS_EXPORT(T)
#define BOOST_CLASS_EXPORT_KEY(T)
#define BOOST_CLASS_EXPORT_KEY2(T, K)
#define BOOST_CLASS_EXPORT_GUID(T, K)
#define BOOST_CLASS_EXPORT_IMPLEMENT(T)
#define BOOST_CLASS_VERSION(T, N)
#define BOOST_CLASS_TRACKING(T, N)
#define BOOST_SERIALIZATION_ASSUME_ABSTRACT(T)
#define BOOST_SERIALIZATION_SPLIT_MEMBER()
#define BOOST_SERIALIZATION_SPLIT_FREE(T)
#endif
