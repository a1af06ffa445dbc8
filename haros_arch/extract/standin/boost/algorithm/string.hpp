// haros_arch stand-in: Boost.StringAlgo (every boost/algorithm/string/... header stands in
// as this one), declarations only; the names are in boost::algorithm and, as boost's
// using-declarations have them, in boost. The trailing ``L...`` is the optional
// std::locale the case-aware functions take
#ifndef HAROS_STANDIN_BOOST_ALGORITHM_STRING_HPP
#define HAROS_STANDIN_BOOST_ALGORITHM_STRING_HPP
#include <string>
#include <vector>
namespace boost {
namespace algorithm {
enum token_compress_mode_type { token_compress_on, token_compress_off };
struct haros_predicate { template<class C> bool operator()(C c) const; };
haros_predicate is_any_of(const char* set);
template<class S> haros_predicate is_any_of(const S& set);
haros_predicate is_space();
haros_predicate is_digit();
haros_predicate is_alpha();
haros_predicate is_alnum();
haros_predicate is_upper();
haros_predicate is_lower();
haros_predicate is_punct();
haros_predicate is_from_range(char from, char to);
template<class Seq, class In, class P>
Seq& split(Seq& result, In& input, P predicate,
           token_compress_mode_type mode = token_compress_off);
template<class S, class... L> void trim(S& s, const L&... locale);
template<class S, class... L> void trim_left(S& s, const L&... locale);
template<class S, class... L> void trim_right(S& s, const L&... locale);
template<class S, class... L> S trim_copy(const S& s, const L&... locale);
template<class S, class... L> S trim_left_copy(const S& s, const L&... locale);
template<class S, class... L> S trim_right_copy(const S& s, const L&... locale);
template<class S, class P> void trim_if(S& s, P predicate);
template<class S, class P> S trim_copy_if(const S& s, P predicate);
template<class S, class... L> void to_lower(S& s, const L&... locale);
template<class S, class... L> void to_upper(S& s, const L&... locale);
template<class S, class... L> S to_lower_copy(const S& s, const L&... locale);
template<class S, class... L> S to_upper_copy(const S& s, const L&... locale);
template<class A, class B> bool starts_with(const A& a, const B& b);
template<class A, class B> bool ends_with(const A& a, const B& b);
template<class A, class B> bool contains(const A& a, const B& b);
template<class A, class B> bool equals(const A& a, const B& b);
template<class A, class B, class... L>
bool istarts_with(const A& a, const B& b, const L&... locale);
template<class A, class B, class... L>
bool iends_with(const A& a, const B& b, const L&... locale);
template<class A, class B, class... L>
bool icontains(const A& a, const B& b, const L&... locale);
template<class A, class B, class... L>
bool iequals(const A& a, const B& b, const L&... locale);
template<class Seq, class S> std::string join(const Seq& input, const S& separator);
// <boost/algorithm/string/regex.hpp> (the regex's own type is Boost.Regex's)
template<class Seq, class In, class R, class... F>
Seq& split_regex(Seq& result, const In& input, const R& regex, F... flags);
template<class S, class F, class R> void replace_all(S& s, const F& search, const R& with);
template<class S, class F, class R> S replace_all_copy(const S& s, const F& search,
                                                      const R& with);
template<class S, class F, class R> void replace_first(S& s, const F& search, const R& with);
template<class S, class F, class R> S replace_first_copy(const S& s, const F& search,
                                                        const R& with);
template<class S, class F> void erase_all(S& s, const F& search);
template<class S, class F> S erase_all_copy(const S& s, const F& search);
template<class S, class F> void erase_first(S& s, const F& search);
}  // namespace algorithm
using algorithm::token_compress_on;
using algorithm::token_compress_off;
using algorithm::is_any_of;
using algorithm::is_space;
using algorithm::is_digit;
using algorithm::is_alpha;
using algorithm::is_alnum;
using algorithm::is_upper;
using algorithm::is_lower;
using algorithm::is_punct;
using algorithm::is_from_range;
using algorithm::split;
using algorithm::trim;
using algorithm::trim_left;
using algorithm::trim_right;
using algorithm::trim_copy;
using algorithm::trim_left_copy;
using algorithm::trim_right_copy;
using algorithm::trim_if;
using algorithm::trim_copy_if;
using algorithm::to_lower;
using algorithm::to_upper;
using algorithm::to_lower_copy;
using algorithm::to_upper_copy;
using algorithm::starts_with;
using algorithm::ends_with;
using algorithm::contains;
using algorithm::equals;
using algorithm::istarts_with;
using algorithm::iends_with;
using algorithm::icontains;
using algorithm::iequals;
using algorithm::join;
using algorithm::split_regex;
using algorithm::replace_all;
using algorithm::replace_all_copy;
using algorithm::replace_first;
using algorithm::replace_first_copy;
using algorithm::erase_all;
using algorithm::erase_all_copy;
using algorithm::erase_first;
}  // namespace boost
#endif
