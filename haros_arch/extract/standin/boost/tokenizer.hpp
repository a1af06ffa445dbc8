// haros_arch stand-in: boost::tokenizer (declarations only)
#ifndef HAROS_STANDIN_BOOST_TOKENIZER_HPP
#define HAROS_STANDIN_BOOST_TOKENIZER_HPP
#include <string>
namespace boost {
template<class Char = char> class char_separator {
public:
  explicit char_separator(const Char* dropped = 0, const Char* kept = 0, int empty = 0);
};
template<class Char = char> class escaped_list_separator {
public:
  explicit escaped_list_separator(Char e = '\\', Char c = ',', Char q = '"');
};
template<class F = char_separator<char>, class It = std::string::const_iterator,
         class Type = std::string>
class tokenizer {
public:
  typedef const Type* iterator;
  typedef const Type* const_iterator;
  template<class C> tokenizer(const C& c, const F& f = F());
  iterator begin() const;
  iterator end() const;
};
}  // namespace boost
#endif
