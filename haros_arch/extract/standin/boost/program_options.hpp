// haros_arch stand-in: Boost.Program_options (declarations only), the command-line
// options of tools and nodes; every boost/program_options/... header stands in as this.
#ifndef HAROS_STANDIN_BOOST_PROGRAM_OPTIONS_HPP
#define HAROS_STANDIN_BOOST_PROGRAM_OPTIONS_HPP
#include <map>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>
namespace boost {
namespace program_options {
class error : public std::logic_error {
public:
  explicit error(const std::string& what);
};
class required_option : public error {
public:
  explicit required_option(const std::string& name);
};
class unknown_option : public error {
public:
  explicit unknown_option(const std::string& name);
};
class value_semantic {
public:
  virtual ~value_semantic();
};
template<class T, class Char = char> class typed_value : public value_semantic {
public:
  typed_value* default_value(const T& v);
  typed_value* default_value(const T& v, const std::string& textual);
  typed_value* implicit_value(const T& v);
  typed_value* implicit_value(const T& v, const std::string& textual);
  typed_value* value_name(const std::string& name);
  typed_value* required();
  typed_value* multitoken();
  typed_value* composing();
  typed_value* zero_tokens();
  template<class F> typed_value* notifier(F f);
};
template<class T> typed_value<T>* value();
template<class T> typed_value<T>* value(T* v);
typed_value<bool>* bool_switch();
typed_value<bool>* bool_switch(bool* v);
class option_description {
public:
  const std::string& long_name() const;
  const std::string& description() const;
};
class options_description;
class options_description_easy_init {
public:
  options_description_easy_init& operator()(const char* name, const char* description);
  options_description_easy_init& operator()(const char* name, const value_semantic* s);
  options_description_easy_init& operator()(const char* name, const value_semantic* s,
                                            const char* description);
};
class options_description {
public:
  options_description(unsigned line_length = 80, unsigned min_description_length = 40);
  options_description(const std::string& caption, unsigned line_length = 80,
                      unsigned min_description_length = 40);
  options_description_easy_init add_options();
  options_description& add(const options_description& other);
  const std::vector<std::shared_ptr<option_description>>& options() const;
};
std::ostream& operator<<(std::ostream& os, const options_description& desc);
class positional_options_description {
public:
  positional_options_description& add(const char* name, int max_count);
};
class option {
public:
  std::string string_key;
  std::vector<std::string> value;
  std::vector<std::string> original_tokens;
  bool unregistered;
};
class parsed_options {
public:
  std::vector<option> options;
};
enum collect_unrecognized_mode { include_positional, exclude_positional };
std::vector<std::string> collect_unrecognized(const std::vector<option>& options,
                                              collect_unrecognized_mode mode);
class command_line_parser {
public:
  command_line_parser(int argc, const char* const argv[]);
  command_line_parser(const std::vector<std::string>& args);
  command_line_parser& options(const options_description& desc);
  command_line_parser& positional(const positional_options_description& desc);
  command_line_parser& allow_unregistered();
  command_line_parser& style(int style);
  parsed_options run();
};
parsed_options parse_command_line(int argc, const char* const argv[],
                                  const options_description& desc, int style = 0);
parsed_options parse_config_file(std::istream& is, const options_description& desc,
                                 bool allow_unregistered = false);
parsed_options parse_config_file(const char* filename, const options_description& desc,
                                 bool allow_unregistered = false);
parsed_options parse_environment(const options_description& desc, const std::string& prefix);
class variable_value {
public:
  template<class T> const T& as() const;
  template<class T> T& as();
  bool empty() const;
  bool defaulted() const;
};
class variables_map : public std::map<std::string, variable_value> {
public:
  variables_map();
  const variable_value& operator[](const std::string& name) const;
  void notify();
  void clear();
};
void store(const parsed_options& options, variables_map& m, bool utf8 = false);
void notify(variables_map& m);
}  // namespace program_options
}  // namespace boost
#endif
