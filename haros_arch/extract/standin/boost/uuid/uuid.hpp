// haros_arch stand-in: Boost.Uuid (declarations only), its uuid, generators, string
// conversions and hash; every boost/uuid/... header stands in as this one (fuse's
// fuse_core::UUID, robot identifiers). No ROS call.
#ifndef HAROS_STANDIN_BOOST_UUID_HPP
#define HAROS_STANDIN_BOOST_UUID_HPP
#include <cstddef>
#include <cstdint>
#include <string>
#include <ostream>
namespace boost {
namespace uuids {
struct uuid {
  typedef std::uint8_t value_type;
  typedef std::uint8_t& reference;
  typedef const std::uint8_t& const_reference;
  typedef std::uint8_t* iterator;
  typedef const std::uint8_t* const_iterator;
  typedef std::size_t size_type;
  typedef std::ptrdiff_t difference_type;
  enum variant_type { variant_ncs, variant_rfc_4122, variant_microsoft, variant_future };
  enum version_type {
    version_unknown = -1, version_time_based = 1, version_dce_security = 2,
    version_name_based_md5 = 3, version_random_number_based = 4, version_name_based_sha1 = 5
  };
  std::uint8_t data[16];
  static constexpr size_type static_size() noexcept { return 16; }
  iterator begin() noexcept;
  const_iterator begin() const noexcept;
  iterator end() noexcept;
  const_iterator end() const noexcept;
  constexpr size_type size() const noexcept { return 16; }
  bool is_nil() const noexcept;
  variant_type variant() const noexcept;
  version_type version() const noexcept;
  void swap(uuid& other) noexcept;
};
bool operator==(const uuid& a, const uuid& b) noexcept;
bool operator!=(const uuid& a, const uuid& b) noexcept;
bool operator<(const uuid& a, const uuid& b) noexcept;
bool operator>(const uuid& a, const uuid& b) noexcept;
bool operator<=(const uuid& a, const uuid& b) noexcept;
bool operator>=(const uuid& a, const uuid& b) noexcept;
void swap(uuid& a, uuid& b) noexcept;
std::size_t hash_value(const uuid& u) noexcept;
uuid nil_uuid() noexcept;
struct nil_generator { typedef uuid result_type; uuid operator()() const noexcept; };
struct string_generator {
  typedef uuid result_type;
  uuid operator()(const std::string& text) const;
  uuid operator()(const char* text) const;
  template <class It> uuid operator()(It first, It last) const;
};
class name_generator {
public:
  typedef uuid result_type;
  explicit name_generator(const uuid& namespace_uuid);
  uuid operator()(const char* name) const;
  uuid operator()(const std::string& name) const;
  uuid operator()(const void* buffer, std::size_t byte_count) const;
};
typedef name_generator name_generator_sha1;
typedef name_generator name_generator_md5;
typedef name_generator name_generator_latest;
class random_generator {
public:
  typedef uuid result_type;
  random_generator();
  uuid operator()();
};
typedef random_generator random_generator_mt19937;
template <class Engine> class basic_random_generator : public random_generator {
public:
  basic_random_generator();
  explicit basic_random_generator(Engine& engine);
};
namespace ns {
uuid dns() noexcept;
uuid url() noexcept;
uuid oid() noexcept;
uuid x500dn() noexcept;
}  // namespace ns
std::string to_string(const uuid& u);
std::wstring to_wstring(const uuid& u);
std::ostream& operator<<(std::ostream& out, const uuid& u);
std::istream& operator>>(std::istream& in, uuid& u);
}  // namespace uuids
using uuids::uuid;
}  // namespace boost
#endif
