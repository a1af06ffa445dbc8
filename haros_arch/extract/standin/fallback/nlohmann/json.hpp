// haros_arch stand-in: nlohmann/json (JSON for Modern C++), declarations only, for the
// workspaces that have it installed, not as sources (kachaka's diagnostics bridge reads
// its error table with it: ``json::parse(text)``, ``element["code"].get<int>()``). No
// ROS call of its own.
#ifndef HAROS_STANDIN_NLOHMANN_JSON_HPP
#define HAROS_STANDIN_NLOHMANN_JSON_HPP
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <istream>
#include <map>
#include <ostream>
#include <string>
#include <vector>
namespace nlohmann {
namespace detail {
class exception { public: const char* what() const noexcept; const int id = 0; };
class parse_error : public exception { public: const std::size_t byte = 0; };
class invalid_iterator : public exception {};
class type_error : public exception {};
class out_of_range : public exception {};
class other_error : public exception {};
enum class value_t : std::uint8_t {
  null, object, array, string, boolean, number_integer, number_unsigned, number_float,
  binary, discarded
};
}  // namespace detail
template<class T, class SFINAE = void> struct adl_serializer {
  template<class J> static void to_json(J& j, const T& value);
  template<class J> static void from_json(const J& j, T& value);
};
template<class Dummy = void> class basic_json {
public:
  using value_t = detail::value_t;
  using exception = detail::exception;
  using parse_error = detail::parse_error;
  using invalid_iterator = detail::invalid_iterator;
  using type_error = detail::type_error;
  using out_of_range = detail::out_of_range;
  using other_error = detail::other_error;
  using size_type = std::size_t;
  using string_t = std::string;
  using boolean_t = bool;
  using number_integer_t = std::int64_t;
  using number_unsigned_t = std::uint64_t;
  using number_float_t = double;
  using object_t = std::map<std::string, basic_json>;
  using array_t = std::vector<basic_json>;
  using initializer_list_t = std::initializer_list<basic_json>;
  // an element of an object or array walked: the value, and of an object its key
  class iterator {
  public:
    basic_json& operator*() const;
    basic_json* operator->() const;
    iterator& operator++();
    iterator operator++(int);
    bool operator==(const iterator& other) const;
    bool operator!=(const iterator& other) const;
    const std::string& key() const;
    basic_json& value() const;
  };
  using const_iterator = iterator;
  // ``for (auto& item : j.items())``: each element's key() and value()
  class iteration_proxy_value {
  public:
    const std::string& key() const;
    basic_json& value() const;
  };
  class iteration_proxy {
  public:
    class proxy_iterator {
    public:
      iteration_proxy_value& operator*() const;
      iteration_proxy_value* operator->() const;
      proxy_iterator& operator++();
      bool operator==(const proxy_iterator& other) const;
      bool operator!=(const proxy_iterator& other) const;
    };
    proxy_iterator begin() const;
    proxy_iterator end() const;
  };
  basic_json();
  basic_json(std::nullptr_t);
  basic_json(value_t type);
  basic_json(const basic_json& other);
  basic_json(basic_json&& other) noexcept;
  basic_json(initializer_list_t init);
  template<class T> basic_json(const T& value);
  basic_json& operator=(basic_json other) noexcept;
  template<class Input> static basic_json parse(Input&& input, std::nullptr_t cb = nullptr,
                                                bool allow_exceptions = true,
                                                bool ignore_comments = false);
  template<class It> static basic_json parse(It first, It last);
  template<class Input> static bool accept(Input&& input, bool ignore_comments = false);
  static basic_json array(initializer_list_t init = {});
  static basic_json object(initializer_list_t init = {});
  static basic_json meta();
  basic_json& operator[](const std::string& key);
  const basic_json& operator[](const std::string& key) const;
  template<class T> basic_json& operator[](T* key);
  template<class T> const basic_json& operator[](T* key) const;
  basic_json& operator[](size_type index);
  const basic_json& operator[](size_type index) const;
  basic_json& at(const std::string& key);
  const basic_json& at(const std::string& key) const;
  basic_json& at(size_type index);
  const basic_json& at(size_type index) const;
  template<class T> T value(const std::string& key, const T& default_value) const;
  std::string value(const std::string& key, const char* default_value) const;
  template<class T> T get() const;
  template<class T> T& get_to(T& out) const;
  template<class T> T get_ref() const;
  template<class T> operator T() const;
  bool contains(const std::string& key) const;
  size_type count(const std::string& key) const;
  iterator find(const std::string& key) const;
  size_type erase(const std::string& key);
  void erase(size_type index);
  size_type size() const noexcept;
  bool empty() const noexcept;
  void clear() noexcept;
  void push_back(const basic_json& value);
  template<class... Args> basic_json& emplace_back(Args&&... args);
  void update(const basic_json& other);
  void merge_patch(const basic_json& patch);
  basic_json flatten() const;
  basic_json unflatten() const;
  basic_json& front();
  basic_json& back();
  iterator begin() const;
  iterator end() const;
  iterator cbegin() const;
  iterator cend() const;
  iteration_proxy items() const;
  std::string dump(int indent = -1, char indent_char = ' ', bool ensure_ascii = false) const;
  value_t type() const noexcept;
  const char* type_name() const noexcept;
  bool is_null() const noexcept;
  bool is_object() const noexcept;
  bool is_array() const noexcept;
  bool is_string() const noexcept;
  bool is_boolean() const noexcept;
  bool is_number() const noexcept;
  bool is_number_integer() const noexcept;
  bool is_number_unsigned() const noexcept;
  bool is_number_float() const noexcept;
  bool is_primitive() const noexcept;
  bool is_structured() const noexcept;
  bool is_discarded() const noexcept;
  friend bool operator==(const basic_json& a, const basic_json& b) noexcept;
  friend bool operator!=(const basic_json& a, const basic_json& b) noexcept;
  template<class T> friend bool operator==(const basic_json& a, const T& b) noexcept;
  template<class T> friend bool operator==(const T& a, const basic_json& b) noexcept;
  template<class T> friend bool operator!=(const basic_json& a, const T& b) noexcept;
  template<class T> friend bool operator!=(const T& a, const basic_json& b) noexcept;
  friend std::ostream& operator<<(std::ostream& out, const basic_json& j);
  friend std::istream& operator>>(std::istream& in, basic_json& j);
};
using json = basic_json<>;
using ordered_json = basic_json<>;
inline namespace literals {
inline namespace json_literals {
json operator""_json(const char* text, std::size_t length);
}  // namespace json_literals
}  // namespace literals
}  // namespace nlohmann
// a type's conversions declared by the library's macros: nothing the parse needs
#define NLOHMANN_DEFINE_TYPE_INTRUSIVE(...)
#define NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(...)
#define NLOHMANN_DEFINE_TYPE_INTRUSIVE_WITH_DEFAULT(...)
#define NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(...)
#define NLOHMANN_JSON_SERIALIZE_ENUM(...)
#endif
