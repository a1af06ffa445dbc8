// haros_arch stand-in: the C++ standard library parts node code uses (declarations only).
// Every standard header name includes this one file: it is small enough to parse in a
// few milliseconds, and code that forgot an #include still parses.
#ifndef HAROS_STANDIN_STD_H
#define HAROS_STANDIN_STD_H
#include "haros_libc.h"
// the permissive class names unknown to the parse are declared as (synthesis.py): a
// string takes one (or a class derived from it) as it is, where its conversion to
// anything makes every assignment and constructor of a string a candidate, ambiguous
// (``name = config.name`` of a dynamic_reconfigure Config whose header is missing)
struct haros_any;
// <wchar.h>'s wide strings (rapidjson's internal/strfunc.h measures them with
// std::wcslen: livox_ros_driver2's JSON configuration)
size_t wcslen(const wchar_t* s);
int wcscmp(const wchar_t* a, const wchar_t* b);
int wcsncmp(const wchar_t* a, const wchar_t* b, size_t n);
wchar_t* wcscpy(wchar_t* d, const wchar_t* s);
wchar_t* wcsncpy(wchar_t* d, const wchar_t* s, size_t n);
namespace std {
using ::wcslen; using ::wcscmp; using ::wcsncmp; using ::wcscpy; using ::wcsncpy;
using ::size_t; using ::ptrdiff_t; using ::int8_t; using ::int16_t; using ::int32_t;
using ::int64_t; using ::uint8_t; using ::uint16_t; using ::uint32_t; using ::uint64_t;
using ::intptr_t; using ::uintptr_t; using ::intmax_t; using ::uintmax_t;
using ::printf; using ::fprintf; using ::snprintf; using ::sprintf; using ::FILE;
using ::getenv; using ::exit; using ::abort; using ::atoi; using ::atof; using ::strtol;
using ::strtod; using ::malloc; using ::free; using ::memcpy; using ::memset;
using ::strlen; using ::strcmp; using ::strncmp; using ::strncpy; using ::strcpy; using ::rand; using ::srand; using ::time; using ::time_t;
using ::sqrt; using ::pow; using ::exp; using ::log; using ::log10; using ::sin;
using ::cos; using ::tan; using ::asin; using ::acos; using ::atan; using ::atan2;
using ::fabs; using ::floor; using ::ceil; using ::round; using ::trunc; using ::fmod;
using ::hypot; using ::copysign; using ::fmin; using ::fmax; using ::lround;
using ::isnan; using ::isinf; using ::isfinite; using ::signal; using ::float_t;
using ::double_t;
using ::memcmp; using ::memmove; using ::vsnprintf;
// the rest of <cstring> (cartographer_ros' and yasmin's std::strrchr of a file's path)
using ::strcat; using ::strncat; using ::strchr; using ::strrchr; using ::strstr;
using ::strtok; using ::strpbrk; using ::strspn; using ::strcspn; using ::memchr;
bool signbit(float x); bool signbit(double x); bool signbit(long double x);
template<class I> bool signbit(I x);  // an integer, as a double
using ::strerror; using ::isalpha; using ::isdigit; using ::isspace; using ::isalnum;
using ::isupper; using ::islower; using ::ispunct; using ::isxdigit; using ::toupper;
using ::tolower; using ::hypotf; using ::nan; using ::nanf;
using ::tm; using ::localtime; using ::gmtime; using ::mktime; using ::strftime;
using ::fopen; using ::fclose; using ::fread; using ::fwrite; using ::fgets; using ::fputs;
using ::fflush; using ::fgetc; using ::fputc; using ::fscanf; using ::sscanf; using ::feof;
using ::ferror; using ::fseek; using ::ftell; using ::rewind; using ::remove; using ::rename;
using ::puts; using ::perror; using ::calloc; using ::realloc; using ::raise;
using ::atol; using ::atoll; using ::strtoul; using ::strtoll; using ::strtoull;
using ::strtof; using ::strtold; using ::labs; using ::llabs; using ::div_t; using ::ldiv_t;
using ::lldiv_t; using ::div; using ::ldiv; using ::lldiv; using ::qsort; using ::bsearch;
using ::clock_t; using ::clock; using ::difftime; using ::system;
using ::sinh; using ::cosh; using ::tanh; using ::asinh; using ::acosh; using ::atanh;
using ::log2; using ::exp2; using ::log1p; using ::expm1; using ::cbrt; using ::remainder;
using ::rint; using ::nearbyint; using ::lrint; using ::llround; using ::llrint; using ::fdim;
using ::fma; using ::erf; using ::erfc; using ::tgamma; using ::lgamma; using ::frexp;
using ::ldexp; using ::modf; using ::scalbn;
double hypot(double x, double y, double z);
float hypot(float x, float y, float z);
typedef decltype(nullptr) nullptr_t;
float sqrt(float x);
float fabs(float x);
float abs(float x);
double abs(double x);
long abs(long x);
// the C library's: ``using std::abs;`` at namespace scope names the same function
// (pure_pursuit_controller's), not a second one of that signature
using ::abs;
float atan2(float y, float x);
float sin(float x);
float cos(float x);

// <initializer_list>, <type_traits>, <utility>
template<class E> class initializer_list {
  const E* b_;
  size_t n_;
public:
  constexpr initializer_list() noexcept;
  constexpr size_t size() const noexcept;
  constexpr const E* begin() const noexcept;
  constexpr const E* end() const noexcept;
};
template<class T, T v> struct integral_constant {
  static constexpr T value = v;
  typedef T value_type;
  constexpr operator T() const noexcept { return v; }
};
typedef integral_constant<bool, true> true_type;
typedef integral_constant<bool, false> false_type;
template<class A, class B> struct is_same : false_type {};
template<class A> struct is_same<A, A> : true_type {};
template<bool B, class T = void> struct enable_if {};
template<class T> struct enable_if<true, T> { typedef T type; };
template<bool B, class T = void> using enable_if_t = typename enable_if<B, T>::type;
template<bool B, class T, class F> struct conditional { typedef T type; };
template<class T, class F> struct conditional<false, T, F> { typedef F type; };
template<class T> struct remove_pointer { typedef T type; };
template<class T> struct remove_pointer<T*> { typedef T type; };
template<class T> struct remove_pointer<T* const> { typedef T type; };
template<class T> using remove_pointer_t = typename remove_pointer<T>::type;
template<class T> struct remove_reference { typedef T type; };
template<class T> struct remove_reference<T&> { typedef T type; };
template<class T> struct remove_reference<T&&> { typedef T type; };
template<class T> using remove_reference_t = typename remove_reference<T>::type;
template<class T> struct remove_const { typedef T type; };
template<class T> struct remove_const<const T> { typedef T type; };
template<class T> struct decay { typedef typename remove_const<typename remove_reference<T>::type>::type type; };
template<class T> using decay_t = typename decay<T>::type;
template<class T> struct is_arithmetic : integral_constant<bool, __is_arithmetic(T)> {};
template<class T> struct is_integral : integral_constant<bool, __is_integral(T)> {};
template<class T> struct is_floating_point : integral_constant<bool, __is_floating_point(T)> {};
template<class B, class D> struct is_base_of : integral_constant<bool, __is_base_of(B, D)> {};
template<class...> using void_t = void;
template<class T> struct is_pointer : false_type {};
template<class T> struct is_pointer<T*> : true_type {};
template<class T> struct is_null_pointer : is_same<decltype(nullptr), typename remove_const<T>::type> {};
template<class T> constexpr bool is_null_pointer_v = is_null_pointer<T>::value;
template<class A, class B> constexpr bool is_same_v = is_same<A, B>::value;
template<class B, class D> constexpr bool is_base_of_v = __is_base_of(B, D);
template<class T> constexpr bool is_pointer_v = is_pointer<T>::value;
template<class T> constexpr bool is_arithmetic_v = __is_arithmetic(T);
template<class T> constexpr bool is_integral_v = __is_integral(T);
template<class T> constexpr bool is_floating_point_v = __is_floating_point(T);
template<class T> constexpr bool is_enum_v = __is_enum(T);
template<class T> struct is_class : integral_constant<bool, __is_class(T)> {};
template<class T> constexpr bool is_class_v = __is_class(T);
template<class F, class T> struct is_convertible : integral_constant<bool, __is_convertible_to(F, T)> {};
template<class F, class T> constexpr bool is_convertible_v = __is_convertible_to(F, T);
template<class... B> struct conjunction : true_type {};
template<class B, class... R> struct conjunction<B, R...>
  : conditional<bool(B::value), conjunction<R...>, B>::type {};
template<class... B> constexpr bool conjunction_v = conjunction<B...>::value;
template<class... B> struct disjunction : false_type {};
template<class B, class... R> struct disjunction<B, R...>
  : conditional<bool(B::value), B, disjunction<R...>>::type {};
template<class... B> constexpr bool disjunction_v = disjunction<B...>::value;
template<class B> struct negation : integral_constant<bool, !bool(B::value)> {};
template<class B> constexpr bool negation_v = !bool(B::value);
template<class T> struct is_enum : integral_constant<bool, __is_enum(T)> {};
template<class T> struct underlying_type { typedef __underlying_type(T) type; };
template<class T> using underlying_type_t = typename underlying_type<T>::type;
// <cmath> of an integer: computed in double, as the library's overloads for integral
// types (std::sqrt(dx * dx + dy * dy) of ints is not ambiguous between float and double)
#define HAROS_INTEGRAL_MATH(NAME) \
  template<class T, class = typename enable_if<__is_integral(T)>::type> double NAME(T x);
HAROS_INTEGRAL_MATH(sqrt) HAROS_INTEGRAL_MATH(cbrt) HAROS_INTEGRAL_MATH(exp)
HAROS_INTEGRAL_MATH(log) HAROS_INTEGRAL_MATH(log2) HAROS_INTEGRAL_MATH(log10)
HAROS_INTEGRAL_MATH(floor) HAROS_INTEGRAL_MATH(ceil) HAROS_INTEGRAL_MATH(round)
HAROS_INTEGRAL_MATH(sin) HAROS_INTEGRAL_MATH(cos) HAROS_INTEGRAL_MATH(tan)
HAROS_INTEGRAL_MATH(atan) HAROS_INTEGRAL_MATH(fabs)
#undef HAROS_INTEGRAL_MATH
template<class A, class B, class = typename enable_if<__is_integral(A) && __is_integral(B)>::type>
double pow(A x, B y);
template<class A, class B, class = typename enable_if<__is_integral(A) && __is_integral(B)>::type>
double hypot(A x, B y);
// and of two arithmetic types that are not both the same floating type: computed in the
// promoted type, as the library's template (terrain_analysis' ``atan2(z - minZ, dis)`` of a
// double and a float is no ambiguity between the float and the double overloads)
template<class A, class B, class = typename enable_if<__is_arithmetic(A) && __is_arithmetic(B)
  && !(__is_same(A, B) && __is_floating_point(A))>::type>
double atan2(A y, B x);
// <complex>: a point as a complex number (consai_ros2's geometry_tools.hpp keeps a
// frame's center and rotation as std::complex<double> members)
template<class T> class complex {
public:
  typedef T value_type;
  constexpr complex(const T& re = T(), const T& im = T());
  template<class U> constexpr complex(const complex<U>& other);
  constexpr T real() const; constexpr T imag() const;
  void real(T value); void imag(T value);
  complex& operator=(const T& x);
  complex& operator+=(const T& x); complex& operator-=(const T& x);
  complex& operator*=(const T& x); complex& operator/=(const T& x);
  template<class U> complex& operator+=(const complex<U>& x);
  template<class U> complex& operator-=(const complex<U>& x);
  template<class U> complex& operator*=(const complex<U>& x);
  template<class U> complex& operator/=(const complex<U>& x);
};
#define HAROS_COMPLEX_BINARY(OP) \
  template<class T> complex<T> operator OP(const complex<T>& a, const complex<T>& b); \
  template<class T> complex<T> operator OP(const complex<T>& a, const T& b); \
  template<class T> complex<T> operator OP(const T& a, const complex<T>& b);
HAROS_COMPLEX_BINARY(+) HAROS_COMPLEX_BINARY(-) HAROS_COMPLEX_BINARY(*) HAROS_COMPLEX_BINARY(/)
#undef HAROS_COMPLEX_BINARY
template<class T> complex<T> operator+(const complex<T>& a);
template<class T> complex<T> operator-(const complex<T>& a);
template<class T> bool operator==(const complex<T>& a, const complex<T>& b);
template<class T> bool operator!=(const complex<T>& a, const complex<T>& b);
template<class T> T real(const complex<T>& z); template<class T> T imag(const complex<T>& z);
template<class T> T abs(const complex<T>& z); template<class T> T arg(const complex<T>& z);
template<class T> T norm(const complex<T>& z);
template<class T> complex<T> conj(const complex<T>& z);
template<class T> complex<T> polar(const T& r, const T& theta = T());
template<class T> complex<T> exp(const complex<T>& z);
template<class T> complex<T> log(const complex<T>& z);
template<class T> complex<T> sqrt(const complex<T>& z);
template<class T> complex<T> pow(const complex<T>& z, const T& y);
// <complex>'s imaginary literals (``using namespace std::complex_literals; exp(1i * a)``,
// corgi's gait generators): without them clang reads ``1i`` as GNU's ``_Complex int``
inline namespace literals { inline namespace complex_literals {
complex<double> operator""i(long double d);
complex<double> operator""i(unsigned long long d);
complex<float> operator""if(long double d);
complex<float> operator""if(unsigned long long d);
complex<long double> operator""il(long double d);
complex<long double> operator""il(unsigned long long d);
} }
// more of <type_traits>, on clang's builtins (robin_hood's hash map asks them of its
// keys and values)
template<class T> struct remove_volatile { typedef T type; };
template<class T> struct remove_volatile<volatile T> { typedef T type; };
template<class T> struct remove_cv { typedef typename remove_volatile<typename remove_const<T>::type>::type type; };
template<class T> using remove_cv_t = typename remove_cv<T>::type;
template<class T> struct remove_cvref { typedef typename remove_cv<typename remove_reference<T>::type>::type type; };
template<class T> using remove_cvref_t = typename remove_cvref<T>::type;
template<class T> using remove_const_t = typename remove_const<T>::type;
template<class T> struct add_const { typedef const T type; };
template<class T> struct add_pointer { typedef typename remove_reference<T>::type* type; };
template<class T> using add_pointer_t = typename add_pointer<T>::type;
template<class T> struct add_lvalue_reference { typedef T& type; };
template<> struct add_lvalue_reference<void> { typedef void type; };
template<class T> using add_lvalue_reference_t = typename add_lvalue_reference<T>::type;
template<class T> struct is_const : false_type {};
template<class T> struct is_const<const T> : true_type {};
template<class T> struct is_void : is_same<void, typename remove_cv<T>::type> {};
template<class T> constexpr bool is_void_v = is_void<T>::value;
template<class T> struct is_reference : false_type {};
template<class T> struct is_reference<T&> : true_type {};
template<class T> struct is_reference<T&&> : true_type {};
template<class T> constexpr bool is_reference_v = is_reference<T>::value;
template<class T> struct is_lvalue_reference : false_type {};
template<class T> struct is_lvalue_reference<T&> : true_type {};
template<class T> struct is_rvalue_reference : false_type {};
template<class T> struct is_rvalue_reference<T&&> : true_type {};
template<class T> struct is_volatile : false_type {};
template<class T> struct is_volatile<volatile T> : true_type {};
template<class T> constexpr bool is_const_v = is_const<T>::value;
template<class T> constexpr bool is_volatile_v = is_volatile<T>::value;
template<class T> constexpr bool is_lvalue_reference_v = is_lvalue_reference<T>::value;
template<class T> constexpr bool is_rvalue_reference_v = is_rvalue_reference<T>::value;
template<class T> struct is_array : false_type {};
template<class T> struct is_array<T[]> : true_type {};
template<class T, size_t N> struct is_array<T[N]> : true_type {};
template<class T> struct is_function : integral_constant<bool, __is_function(T)> {};
template<class T> struct is_object : integral_constant<bool, __is_object(T)> {};
template<class T> struct is_scalar : integral_constant<bool, __is_scalar(T)> {};
template<class T> struct is_fundamental : integral_constant<bool, __is_fundamental(T)> {};
template<class T> struct is_signed : integral_constant<bool, __is_signed(T)> {};
template<class T> struct is_unsigned : integral_constant<bool, __is_unsigned(T)> {};
template<class T> constexpr bool is_signed_v = __is_signed(T);
template<class T> constexpr bool is_unsigned_v = __is_unsigned(T);
template<class T> struct make_signed { typedef __make_signed(T) type; };
template<class T> struct make_unsigned { typedef __make_unsigned(T) type; };
template<class T> using make_signed_t = typename make_signed<T>::type;
template<class T> using make_unsigned_t = typename make_unsigned<T>::type;
template<class T> struct is_empty : integral_constant<bool, __is_empty(T)> {};
template<class T> struct is_polymorphic : integral_constant<bool, __is_polymorphic(T)> {};
template<class T> struct is_abstract : integral_constant<bool, __is_abstract(T)> {};
template<class T> struct is_final : integral_constant<bool, __is_final(T)> {};
template<class T> struct is_trivial : integral_constant<bool, __is_trivial(T)> {};
template<class T> struct is_standard_layout : integral_constant<bool, __is_standard_layout(T)> {};
template<class T> struct is_trivially_copyable : integral_constant<bool, __is_trivially_copyable(T)> {};
template<class T> constexpr bool is_trivially_copyable_v = __is_trivially_copyable(T);
template<class T> struct is_trivially_destructible : integral_constant<bool, __is_trivially_destructible(T)> {};
template<class T> constexpr bool is_trivially_destructible_v = __is_trivially_destructible(T);
template<class T, class... A> struct is_constructible : integral_constant<bool, __is_constructible(T, A...)> {};
template<class T, class... A> constexpr bool is_constructible_v = __is_constructible(T, A...);
template<class T> struct is_default_constructible : is_constructible<T> {};
template<class T> struct is_copy_constructible : is_constructible<T, const T&> {};
template<class T> struct is_move_constructible : is_constructible<T, T&&> {};
template<class T, class U> struct is_assignable : integral_constant<bool, __is_assignable(T, U)> {};
template<class T> struct is_copy_assignable : is_assignable<T&, const T&> {};
template<class T> struct is_move_assignable : is_assignable<T&, T&&> {};
template<class T, class U> constexpr bool is_assignable_v = __is_assignable(T, U);
template<class T, class... A> struct is_nothrow_constructible : integral_constant<bool, __is_nothrow_constructible(T, A...)> {};
template<class T> struct is_nothrow_move_constructible : is_nothrow_constructible<T, T&&> {};
template<class T> struct is_nothrow_move_assignable : integral_constant<bool, __is_nothrow_assignable(T&, T&&)> {};
template<class T> struct alignment_of : integral_constant<size_t, alignof(T)> {};
template<size_t N, size_t A = alignof(long double)> struct aligned_storage {
  struct type { alignas(A) unsigned char data[N]; };
};
template<class T> constexpr typename remove_reference<T>::type&& move(T&& t) noexcept;
template<class T> constexpr T&& forward(typename remove_reference<T>::type& t) noexcept;
template<class T> constexpr T&& forward(typename remove_reference<T>::type&& t) noexcept;
template<class T> void swap(T& a, T& b);
template<class T> T&& declval() noexcept;
template<class T> struct is_swappable : integral_constant<bool, true> {};
// std::swap's own condition (a type with a swap of its own aside)
template<class T> struct is_nothrow_swappable : integral_constant<bool,
  __is_nothrow_constructible(T, T&&) && __is_nothrow_assignable(T&, T&&)> {};
template<class T> constexpr bool is_nothrow_swappable_v = is_nothrow_swappable<T>::value;
// <utility>'s compile-time integer sequences and piecewise construction
template<class T, T... I> struct integer_sequence {
  typedef T value_type;
  static constexpr size_t size() noexcept { return sizeof...(I); }
};
template<size_t... I> using index_sequence = integer_sequence<size_t, I...>;
template<class T, T N> using make_integer_sequence = __make_integer_seq<integer_sequence, T, N>;
template<size_t N> using make_index_sequence = make_integer_sequence<size_t, N>;
template<class... T> using index_sequence_for = make_index_sequence<sizeof...(T)>;
struct piecewise_construct_t { explicit piecewise_construct_t() = default; };
constexpr piecewise_construct_t piecewise_construct{};
template<class... T> class tuple;
template<class... T> struct common_type {};
template<class T> struct common_type<T> { typedef typename decay<T>::type type; };
template<class A, class B, class... R> struct common_type<A, B, R...>
  : common_type<typename decay<decltype(true ? declval<A>() : declval<B>())>::type, R...> {};
template<class... T> using common_type_t = typename common_type<T...>::type;
template<class A, class B> struct pair {
  typedef A first_type;
  typedef B second_type;
  A first;
  B second;
  pair();
  pair(const A& a, const B& b);
  template<class U, class V> pair(U&& a, V&& b);
  template<class U, class V> pair(const pair<U, V>& p);
  template<class... U, class... V>
  pair(piecewise_construct_t, tuple<U...> first_args, tuple<V...> second_args);
};
template<class A, class B> pair<typename decay<A>::type, typename decay<B>::type> make_pair(A&& a, B&& b);
template<class A, class B> bool operator==(const pair<A, B>& x, const pair<A, B>& y);
template<class A, class B> bool operator<(const pair<A, B>& x, const pair<A, B>& y);
// and the other comparisons (realsense2_camera's ``sip != DEPTH`` of its stream pairs)
template<class A, class B> bool operator!=(const pair<A, B>& x, const pair<A, B>& y);
template<class A, class B> bool operator>(const pair<A, B>& x, const pair<A, B>& y);
template<class A, class B> bool operator<=(const pair<A, B>& x, const pair<A, B>& y);
template<class A, class B> bool operator>=(const pair<A, B>& x, const pair<A, B>& y);
template<class... T> class tuple {
public:
  tuple();
  template<class... U> tuple(U&&... args);
};
template<class... T> tuple<typename decay<T>::type...> make_tuple(T&&... args);
template<class... T> tuple<T&...> tie(T&... args);
// tuples compared item by item (consai_ros2's ControlParams::operator==, ``tie() ==
// other.tie()``)
template<class... T, class... U> bool operator==(const tuple<T...>& a, const tuple<U...>& b);
template<class... T, class... U> bool operator!=(const tuple<T...>& a, const tuple<U...>& b);
template<class... T, class... U> bool operator<(const tuple<T...>& a, const tuple<U...>& b);
template<class... T, class... U> bool operator<=(const tuple<T...>& a, const tuple<U...>& b);
template<class... T, class... U> bool operator>(const tuple<T...>& a, const tuple<U...>& b);
template<class... T, class... U> bool operator>=(const tuple<T...>& a, const tuple<U...>& b);
// std::ignore: anything is assigned to it (``std::ignore = handle.set_value(0.0);``)
struct haros_ignore_t { template<class T> const haros_ignore_t& operator=(const T&) const; };
static const haros_ignore_t ignore = {};
// the tuple protocol (structured bindings, std::get) of tuple and pair
template<class T> struct tuple_size;
template<class... T> struct tuple_size<tuple<T...>> { static constexpr size_t value = sizeof...(T); };
template<class A, class B> struct tuple_size<pair<A, B>> { static constexpr size_t value = 2; };
template<class T> struct tuple_size<const T> { static constexpr size_t value = tuple_size<T>::value; };
template<class T> constexpr size_t tuple_size_v = tuple_size<T>::value;
template<size_t I, class T> struct tuple_element;
template<size_t I, class H, class... R> struct tuple_element<I, tuple<H, R...>>
    : tuple_element<I - 1, tuple<R...>> {};
template<class H, class... R> struct tuple_element<0, tuple<H, R...>> { typedef H type; };
template<class A, class B> struct tuple_element<0, pair<A, B>> { typedef A type; };
template<class A, class B> struct tuple_element<1, pair<A, B>> { typedef B type; };
template<size_t I, class T> struct tuple_element<I, const T> {
  typedef const typename tuple_element<I, T>::type type;
};
template<size_t I, class T> using tuple_element_t = typename tuple_element<I, T>::type;
template<size_t I, class... T> typename tuple_element<I, tuple<T...>>::type& get(tuple<T...>& t);
template<size_t I, class... T> const typename tuple_element<I, tuple<T...>>::type& get(
    const tuple<T...>& t);
template<size_t I, class... T> typename tuple_element<I, tuple<T...>>::type&& get(tuple<T...>&& t);
template<size_t I, class A, class B> typename tuple_element<I, pair<A, B>>::type& get(pair<A, B>& p);
template<size_t I, class A, class B> const typename tuple_element<I, pair<A, B>>::type& get(
    const pair<A, B>& p);
template<size_t I, class A, class B> typename tuple_element<I, pair<A, B>>::type&& get(
    pair<A, B>&& p);
template<class X, class... T> X& get(tuple<T...>& t);
template<class X, class... T> const X& get(const tuple<T...>& t);
template<class... T> tuple<T&&...> forward_as_tuple(T&&... args);
template<class... T> auto tuple_cat(T&&... tuples) -> tuple<>;
template<class T> struct hash { size_t operator()(const T& v) const; };
template<class T> struct less { bool operator()(const T& a, const T& b) const; };
template<class T> struct greater { bool operator()(const T& a, const T& b) const; };
template<class T> struct equal_to { bool operator()(const T& a, const T& b) const; };
// the other comparisons of <functional> (tauv's ``boost::heap::compare<
// std::greater_equal<Ptr>>``)
template<class T> struct not_equal_to { bool operator()(const T& a, const T& b) const; };
template<class T> struct less_equal { bool operator()(const T& a, const T& b) const; };
template<class T> struct greater_equal { bool operator()(const T& a, const T& b) const; };
// the adaptable function bases (deprecated in C++11, still declared by libstdc++ in
// every mode): ``struct matrix_hash : std::unary_function<T, size_t>``
template<class A, class R> struct unary_function {
  typedef A argument_type; typedef R result_type; };
template<class A1, class A2, class R> struct binary_function {
  typedef A1 first_argument_type; typedef A2 second_argument_type; typedef R result_type; };
// arithmetic function objects (``std::plus<>{}`` as a reduction), invoke_result,
// apply, as_const, and reverse_iterator as a class template (C++14 / 17)
template<class T = void> struct plus {
  template<class A, class B> auto operator()(const A& a, const B& b) const -> decltype(a + b); };
template<class T = void> struct minus {
  template<class A, class B> auto operator()(const A& a, const B& b) const -> decltype(a - b); };
template<class T = void> struct multiplies {
  template<class A, class B> auto operator()(const A& a, const B& b) const -> decltype(a * b); };
template<class T = void> struct divides {
  template<class A, class B> auto operator()(const A& a, const B& b) const -> decltype(a / b); };
template<class F, class... A> struct invoke_result {
  typedef decltype(declval<F>()(declval<A>()...)) type; };
template<class F, class... A> using invoke_result_t = typename invoke_result<F, A...>::type;
template<class F, class... A> struct is_invocable {
  template<class G> static auto test(int) -> decltype(declval<G>()(declval<A>()...), true_type());
  template<class G> static false_type test(...);
  static constexpr bool value = decltype(test<F>(0))::value;
};
template<class F, class... A> constexpr bool is_invocable_v = is_invocable<F, A...>::value;
// is_invocable_r (C++17), result_of (C++11 to 17), addressof
template<class R, class F, class... A> struct is_invocable_r {
  template<class G> static auto test(int) -> decltype(
      static_cast<R>(declval<G>()(declval<A>()...)), true_type());
  template<class G> static false_type test(...);
  static constexpr bool value = decltype(test<F>(0))::value;
};
template<class R, class F, class... A> constexpr bool is_invocable_r_v =
    is_invocable_r<R, F, A...>::value;
template<class S> struct result_of;
template<class F, class... A> struct result_of<F(A...)> : invoke_result<F, A...> {};
template<class S> using result_of_t = typename result_of<S>::type;
template<class T> constexpr T* addressof(T& value) noexcept;
template<class T> const T* addressof(const T&&) = delete;
// std::invoke (C++17): a callable with its arguments (Autoware's ``const auto x =
// std::invoke([&]() { ... });``), or a member function on an object; std::exchange (C++14)
template<class F, class... A> auto invoke(F&& f, A&&... a) -> decltype(declval<F>()(declval<A>()...));
template<class R, class C, class... P, class O, class... A> R invoke(R (C::*m)(P...), O&& o, A&&... a);
template<class R, class C, class... P, class O, class... A> R invoke(R (C::*m)(P...) const, O&& o, A&&... a);
template<class T, class U = T> T exchange(T& obj, U&& value);
template<class T> struct remove_extent { typedef T type; };
template<class T> struct remove_extent<T[]> { typedef T type; };
template<class T, size_t N> struct remove_extent<T[N]> { typedef T type; };
template<class T> using remove_extent_t = typename remove_extent<T>::type;
template<class F, class T> decltype(auto) apply(F&& f, T&& t);
template<class T> const T& as_const(T& t) noexcept;
template<class It> struct reverse_iterator {
  reverse_iterator(); explicit reverse_iterator(It it);
  // the element before the one the iterator it holds points at (defined here: a
  // deduced type is known only from a body)
  decltype(auto) operator*() const { It before = current; --before; return *before; }
  auto operator->() const { return &**this; }
  reverse_iterator& operator++(); reverse_iterator operator++(int);
  reverse_iterator& operator--(); It base() const;
  bool operator==(const reverse_iterator& o) const; bool operator!=(const reverse_iterator& o) const;
  It current;
};
template<class It> reverse_iterator<It> make_reverse_iterator(It it);
template<class T> class allocator {
public:
  typedef T value_type;
  allocator();
  template<class U> allocator(const allocator<U>& other);
  // (to C++17; a gencpp message's ``typename ContainerAllocator::template
  // rebind<int32_t>::other`` of ``std::allocator<void>``)
  template<class U> struct rebind { typedef allocator<U> other; };
};
// what an allocator type gives (metavision_driver's ``typename
// std::allocator_traits<A>::template rebind_alloc<U>``)
template<class A> struct allocator_traits {
  typedef A allocator_type;
  typedef typename A::value_type value_type;
  typedef value_type* pointer;
  typedef const value_type* const_pointer;
  typedef unsigned long size_type;
  typedef long difference_type;
  template<class U> using rebind_alloc = allocator<U>;
  template<class U> using rebind_traits = allocator_traits<allocator<U>>;
  static pointer allocate(A& a, size_type n);
  static void deallocate(A& a, pointer p, size_type n);
  template<class T, class... Args> static void construct(A& a, T* p, Args&&... args);
  template<class T> static void destroy(A& a, T* p);
  static size_type max_size(const A& a) noexcept;
};
// what a stream of characters reads one at a time (nlohmann/json's input adapters:
// ``std::char_traits<char>::int_type c = ...; c == std::char_traits<char>::eof()``)
template<class C> struct char_traits {
  typedef C char_type;
  typedef int int_type;
  static constexpr int_type eof() noexcept;
  static constexpr int_type to_int_type(char_type c) noexcept;
  static constexpr char_type to_char_type(int_type i) noexcept;
  static constexpr bool eq_int_type(int_type a, int_type b) noexcept;
  static constexpr bool eq(char_type a, char_type b) noexcept;
  static constexpr bool lt(char_type a, char_type b) noexcept;
  static constexpr size_t length(const char_type* s);
  static constexpr int compare(const char_type* a, const char_type* b, size_t n);
  static constexpr const char_type* find(const char_type* s, size_t n, const char_type& c);
  static char_type* copy(char_type* d, const char_type* s, size_t n);
  static char_type* move(char_type* d, const char_type* s, size_t n);
  static char_type* assign(char_type* d, size_t n, char_type c);
  static constexpr void assign(char_type& d, const char_type& c) noexcept;
  static constexpr int_type not_eof(int_type i) noexcept;
};
struct input_iterator_tag {};
struct forward_iterator_tag : input_iterator_tag {};
struct random_access_iterator_tag : forward_iterator_tag {};
struct output_iterator_tag {};
struct bidirectional_iterator_tag : forward_iterator_tag {};
// what an iterator type holds (ros_controllers' trajectory_interface: ``typename
// std::iterator_traits<It>::value_type``, without which joint_trajectory_controller's
// class template lost its members' calls): a class's own types, a pointer's pointee
template<class It> struct iterator_traits {
  typedef typename It::value_type value_type;
  typedef long difference_type;
  typedef value_type* pointer;
  typedef value_type& reference;
  typedef random_access_iterator_tag iterator_category;
};
template<class T> struct iterator_traits<T*> {
  typedef T value_type;
  typedef long difference_type;
  typedef T* pointer;
  typedef T& reference;
  typedef random_access_iterator_tag iterator_category;
};
template<class T> struct iterator_traits<const T*> {
  typedef T value_type;
  typedef long difference_type;
  typedef const T* pointer;
  typedef const T& reference;
  typedef random_access_iterator_tag iterator_category;
};

// <string>
template<class C, class Tr = char_traits<C>, class A = allocator<C>> class basic_string {
public:
  typedef C value_type;
  typedef size_t size_type;
  typedef C* iterator;
  typedef const C* const_iterator;
  typedef C* reverse_iterator;  // as vector's: a pointer that walks (direction aside)
  typedef const C* const_reverse_iterator;
  static const size_t npos = static_cast<size_t>(-1);
  basic_string();
  basic_string(const C* s);
  basic_string(const C* s, size_t n);
  basic_string(size_t n, C c);
  basic_string(const basic_string& s);
  basic_string(basic_string&& s);
  basic_string(const basic_string& s, size_t pos, size_t n = npos);
  template<class It> basic_string(It first, It last);
  basic_string(initializer_list<C> chars);
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  explicit basic_string(const U& unknown);
  ~basic_string();
  basic_string& operator=(const basic_string& s);
  basic_string& operator=(basic_string&& s);
  basic_string& operator=(const C* s);
  basic_string& operator=(C c);
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  basic_string& operator=(const U& unknown);
  basic_string& operator+=(const basic_string& s);
  basic_string& operator+=(const C* s);
  basic_string& operator+=(C c);
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  basic_string& operator+=(const U& unknown);
  C& operator[](size_t i);
  const C& operator[](size_t i) const;
  C& at(size_t i);
  const C& at(size_t i) const;
  C& back();
  C& front();
  const C& back() const;
  const C& front() const;
  const C* c_str() const;
  const C* data() const;
  size_t size() const;
  size_t length() const;
  size_t capacity() const;
  bool empty() const;
  // C++20
  bool starts_with(const C* s) const;
  bool starts_with(C c) const;
  bool ends_with(const C* s) const;
  bool ends_with(C c) const;
  template<class S> bool starts_with(const S& s) const;
  template<class S> bool ends_with(const S& s) const;
  void clear();
  void reserve(size_t n);
  void resize(size_t n);
  void resize(size_t n, C c);
  void push_back(C c);
  void pop_back();
  basic_string& append(const basic_string& s);
  basic_string& append(const C* s);
  basic_string& append(size_t n, C c);
  // a value the parse declared permissively (a protobuf message's ``name()``, its headers
  // missing: robocup-pkg's robot_comm ``name.append(m.name())``), as ``+=`` takes one
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  basic_string& append(const U& unknown);
  basic_string& assign(const basic_string& s);
  basic_string& assign(const C* s);
  basic_string& assign(size_t n, C c);
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  basic_string& assign(const U& unknown);
  template<class It> basic_string& assign(It first, It last);
  basic_string& insert(size_t pos, const basic_string& s);
  // one character before a position (``s.insert(s.begin(), '/')``): a template, as
  // ``erase(It)`` below, since the iterator is a pointer here
  template<class It, class = typename enable_if<is_same<It, C*>::value
                                                || is_same<It, const C*>::value>::type>
  iterator insert(It position, C c);
  basic_string& erase(size_t pos = 0, size_t n = npos);
  // one position (``s.erase(s.begin())``): a template, since the iterator is a pointer
  // here and ``s.erase(0)`` (a count) would find a null iterator as good a match
  template<class It, class = typename enable_if<is_same<It, C*>::value
                                                || is_same<It, const C*>::value>::type>
  iterator erase(It position);
  iterator erase(const_iterator first, const_iterator last);
  basic_string& replace(size_t pos, size_t n, const basic_string& s);
  basic_string& replace(size_t pos, size_t n, const basic_string& s, size_t subpos,
                        size_t sublen = npos);
  basic_string& replace(size_t pos, size_t n, const C* s);
  basic_string& replace(size_t pos, size_t n, size_t count, C c);
  basic_string substr(size_t pos = 0, size_t n = npos) const;
  size_t find(const basic_string& s, size_t pos = 0) const;
  size_t find(const C* s, size_t pos = 0) const;
  size_t find(C c, size_t pos = 0) const;
  size_t rfind(const basic_string& s, size_t pos = npos) const;
  size_t rfind(C c, size_t pos = npos) const;
  size_t find_first_of(const basic_string& s, size_t pos = 0) const;
  size_t find_first_of(C c, size_t pos = 0) const;
  size_t find_last_of(const basic_string& s, size_t pos = npos) const;
  size_t find_last_of(C c, size_t pos = npos) const;
  size_t find_first_not_of(const basic_string& s, size_t pos = 0) const;
  size_t find_first_not_of(C c, size_t pos = 0) const;
  size_t find_last_not_of(const basic_string& s, size_t pos = npos) const;
  size_t find_last_not_of(C c, size_t pos = npos) const;
  int compare(const basic_string& s) const;
  int compare(size_t pos, size_t n, const basic_string& s) const;
  iterator begin();
  iterator end();
  const_iterator begin() const;
  const_iterator end() const;
  const_iterator cbegin() const;
  const_iterator cend() const;
  reverse_iterator rbegin();
  reverse_iterator rend();
  const_reverse_iterator rbegin() const;
  const_reverse_iterator rend() const;
  const_reverse_iterator crbegin() const;
  const_reverse_iterator crend() const;
};
typedef basic_string<char> string;
typedef basic_string<wchar_t> wstring;
typedef basic_string<char16_t> u16string;
typedef basic_string<char32_t> u32string;
template<class C> basic_string<C> operator+(const basic_string<C>& a, const basic_string<C>& b);
template<class C> basic_string<C> operator+(const basic_string<C>& a, const C* b);
template<class C> basic_string<C> operator+(const C* a, const basic_string<C>& b);
template<class C> basic_string<C> operator+(const basic_string<C>& a, C b);
template<class C> basic_string<C> operator+(C a, const basic_string<C>& b);
template<class C> bool operator==(const basic_string<C>& a, const basic_string<C>& b);
template<class C> bool operator==(const basic_string<C>& a, const C* b);
template<class C> bool operator==(const C* a, const basic_string<C>& b);
template<class C> bool operator!=(const basic_string<C>& a, const basic_string<C>& b);
template<class C> bool operator!=(const basic_string<C>& a, const C* b);
template<class C> bool operator!=(const C* a, const basic_string<C>& b);
template<class C> bool operator<(const basic_string<C>& a, const basic_string<C>& b);
template<class C> bool operator>(const basic_string<C>& a, const basic_string<C>& b);
template<> struct hash<string> { size_t operator()(const string& s) const; };
string to_string(int v);
string to_string(long v);
string to_string(long long v);
string to_string(unsigned v);
string to_string(unsigned long v);
string to_string(unsigned long long v);
string to_string(float v);
string to_string(double v);
string to_string(long double v);
wstring to_wstring(int v);
wstring to_wstring(long v);
wstring to_wstring(long long v);
wstring to_wstring(unsigned v);
wstring to_wstring(unsigned long v);
wstring to_wstring(unsigned long long v);
wstring to_wstring(float v);
wstring to_wstring(double v);
int stoi(const string& s, size_t* pos = nullptr, int base = 10);
long stol(const string& s, size_t* pos = nullptr, int base = 10);
unsigned long stoul(const string& s, size_t* pos = nullptr, int base = 10);
long long stoll(const string& s, size_t* pos = nullptr, int base = 10);
unsigned long long stoull(const string& s, size_t* pos = nullptr, int base = 10);
long double stold(const string& s, size_t* pos = nullptr);
float stof(const string& s, size_t* pos = nullptr);
double stod(const string& s, size_t* pos = nullptr);
class string_view {
  const char* data_ = nullptr;
  size_t size_ = 0;
public:
  constexpr string_view() {}
  constexpr string_view(const char* s) : data_(s), size_(__builtin_strlen(s)) {}
  constexpr string_view(const char* s, size_t n) : data_(s), size_(n) {}
  string_view(const string& s);
  constexpr size_t size() const { return size_; }
  constexpr size_t length() const { return size_; }
  constexpr const char* data() const { return data_; }
  constexpr bool empty() const { return size_ == 0; }
  static constexpr size_t npos = size_t(-1);
  constexpr const char& operator[](size_t pos) const { return data_[pos]; }
  constexpr const char* begin() const { return data_; }
  constexpr const char* end() const { return data_ + size_; }
  constexpr char front() const { return data_[0]; }
  constexpr char back() const { return data_[size_ - 1]; }
  void remove_prefix(size_t n);
  void remove_suffix(size_t n);
  string_view substr(size_t pos = 0, size_t n = npos) const;
  size_t find(string_view s, size_t pos = 0) const;
  size_t find(char c, size_t pos = 0) const;
  size_t find(const char* s, size_t pos = 0) const;
  size_t rfind(string_view s, size_t pos = npos) const;
  size_t rfind(char c, size_t pos = npos) const;
  size_t find_first_of(string_view s, size_t pos = 0) const;
  size_t find_first_of(char c, size_t pos = 0) const;
  size_t find_last_of(string_view s, size_t pos = npos) const;
  size_t find_last_of(char c, size_t pos = npos) const;
  size_t find_first_not_of(string_view s, size_t pos = 0) const;
  size_t find_first_not_of(char c, size_t pos = 0) const;
  size_t find_last_not_of(string_view s, size_t pos = npos) const;
  size_t find_last_not_of(char c, size_t pos = npos) const;
  int compare(string_view s) const;
  bool starts_with(string_view s) const;
  bool starts_with(char c) const;
  bool ends_with(string_view s) const;
  bool ends_with(char c) const;
  operator string() const;
};
bool operator==(string_view a, string_view b);
bool operator!=(string_view a, string_view b);
bool operator<(string_view a, string_view b);
inline namespace literals { inline namespace string_literals {
string operator""s(const char* s, size_t n);
} }

// <bitset> (ur_robot_driver's robot mode bits)
template<size_t N> class bitset {
public:
  class reference {
  public:
    reference& operator=(bool value);
    reference& operator=(const reference& other);
    operator bool() const;
    bool operator~() const;
    reference& flip();
  };
  constexpr bitset() {}
  constexpr bitset(unsigned long long value) {}
  explicit bitset(const string& text, size_t pos = 0, size_t n = size_t(-1));
  explicit bitset(const char* text);
  constexpr bool operator[](size_t pos) const { return false; }
  reference operator[](size_t pos);
  bool test(size_t pos) const;
  bool all() const; bool any() const; bool none() const;
  size_t count() const;
  constexpr size_t size() const { return N; }
  bitset& set(); bitset& set(size_t pos, bool value = true);
  bitset& reset(); bitset& reset(size_t pos);
  bitset& flip(); bitset& flip(size_t pos);
  unsigned long to_ulong() const;
  unsigned long long to_ullong() const;
  string to_string(char zero = '0', char one = '1') const;
  bitset& operator&=(const bitset& other); bitset& operator|=(const bitset& other);
  bitset& operator^=(const bitset& other);
  bitset operator~() const;
  bitset operator<<(size_t pos) const; bitset operator>>(size_t pos) const;
  bitset& operator<<=(size_t pos); bitset& operator>>=(size_t pos);
  bool operator==(const bitset& other) const; bool operator!=(const bitset& other) const;
};
template<size_t N> bitset<N> operator&(const bitset<N>& a, const bitset<N>& b);
template<size_t N> bitset<N> operator|(const bitset<N>& a, const bitset<N>& b);
template<size_t N> bitset<N> operator^(const bitset<N>& a, const bitset<N>& b);

// <vector>, <deque>, <list>, <array>, <set>, <map>, <unordered_map>, <queue>
template<class T, class A = allocator<T>> class vector {
public:
  typedef T value_type;
  typedef A allocator_type;
  typedef size_t size_type;
  typedef T& reference;
  typedef const T& const_reference;
  typedef T* iterator;
  typedef const T* const_iterator;
  typedef T* reverse_iterator;
  typedef const T* const_reverse_iterator;
  vector();
  explicit vector(size_t n);
  vector(size_t n, const T& v);
  vector(initializer_list<T> items);
  template<class It> vector(It first, It last);
  vector(const vector& v);
  vector(vector&& v);
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  explicit vector(const U& unknown);  // built from a value of an unknown name, as string is
  ~vector();
  vector& operator=(const vector& v);
  vector& operator=(vector&& v);
  vector& operator=(initializer_list<T> items);
  // a value of the permissive class of unknown names (``names = hw->getNames();``):
  // without it the three assignments above are equally good and the use ambiguous
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  vector& operator=(const U& unknown);
  T& operator[](size_t i);
  const T& operator[](size_t i) const;
  T& at(size_t i);
  const T& at(size_t i) const;
  T& front();
  const T& front() const;
  T& back();
  const T& back() const;
  T* data();
  const T* data() const;
  size_t size() const;
  size_t capacity() const;
  bool empty() const;
  void clear();
  void reserve(size_t n);
  void resize(size_t n);
  void resize(size_t n, const T& v);
  void push_back(const T& v);
  void push_back(T&& v);
  template<class... Args> T& emplace_back(Args&&... args);
  void pop_back();
  iterator insert(const_iterator pos, const T& v);
  template<class It> iterator insert(const_iterator pos, It first, It last);
  iterator erase(const_iterator pos);
  iterator erase(const_iterator first, const_iterator last);
  void assign(size_t n, const T& v);
  template<class It> void assign(It first, It last);
  void swap(vector& other);
  iterator begin();
  iterator end();
  const_iterator begin() const;
  const_iterator end() const;
  const_iterator cbegin() const;
  const_iterator cend() const;
  reverse_iterator rbegin();
  reverse_iterator rend();
  const_reverse_iterator rbegin() const;
  const_reverse_iterator rend() const;
  const_reverse_iterator crbegin() const;
  const_reverse_iterator crend() const;
};
template<class T> bool operator==(const vector<T>& a, const vector<T>& b);
template<class T> bool operator!=(const vector<T>& a, const vector<T>& b);
template<class T, class A = allocator<T>> class deque : public vector<T, A> {
public:
  using vector<T, A>::vector;
  void push_front(const T& v);
  void pop_front();
};
template<class T, class A = allocator<T>> class list : public vector<T, A> {
public:
  using vector<T, A>::vector;
  typedef typename vector<T, A>::const_iterator const_iterator;
  void push_front(const T& v);
  void push_front(T&& v);
  template<class... Args> T& emplace_front(Args&&... args);
  void pop_front();
  void sort();
  template<class C> void sort(C comp);
  void remove(const T& v);
  template<class P> void remove_if(P pred);
  void unique();
  template<class P> void unique(P pred);
  void reverse() noexcept;
  void merge(list& other);
  void merge(list&& other);
  template<class C> void merge(list& other, C comp);
  template<class C> void merge(list&& other, C comp);
  // moves elements of ``other`` before ``pos`` (an LRU cache's move to the front:
  // yasmin's demangle cache, autoware_utils' lru_cache; MoveIt's trajectory generation)
  void splice(const_iterator pos, list& other);
  void splice(const_iterator pos, list&& other);
  void splice(const_iterator pos, list& other, const_iterator it);
  void splice(const_iterator pos, list&& other, const_iterator it);
  void splice(const_iterator pos, list& other, const_iterator first, const_iterator last);
  void splice(const_iterator pos, list&& other, const_iterator first, const_iterator last);
};
template<class T, size_t N> struct array {
  T elems_[N ? N : 1];
  typedef T value_type;
  typedef T* iterator;
  typedef const T* const_iterator;
  T& operator[](size_t i);
  const T& operator[](size_t i) const;
  T& at(size_t i);
  const T& at(size_t i) const;
  constexpr size_t size() const;
  bool empty() const;
  T* data();
  const T* data() const;
  T& front(); const T& front() const;
  T& back(); const T& back() const;
  void fill(const T& v);
  T* begin();
  T* end();
  const T* begin() const;
  const T* end() const;
  const T* cbegin() const;
  const T* cend() const;
};
template<class T, size_t N> bool operator==(const array<T, N>& a, const array<T, N>& b);
template<class T, size_t N> bool operator!=(const array<T, N>& a, const array<T, N>& b);
template<class T, size_t N> bool operator<(const array<T, N>& a, const array<T, N>& b);
template<class K, class V> class haros_map_iterator {
public:
  typedef pair<const K, V> value_type;
  value_type& operator*() const;
  value_type* operator->() const;
  haros_map_iterator& operator++();
  haros_map_iterator operator++(int);
  haros_map_iterator& operator--();
  bool operator==(const haros_map_iterator& o) const;
  bool operator!=(const haros_map_iterator& o) const;
};
template<class K, class V, class C = less<K>, class A = allocator<pair<const K, V>>>
class map {
public:
  typedef K key_type;
  typedef V mapped_type;
  typedef pair<const K, V> value_type;
  typedef haros_map_iterator<K, V> iterator;
  typedef haros_map_iterator<K, V> const_iterator;
  map();
  map(initializer_list<value_type> items);
  map(const map& m);
  map& operator=(const map& m);
  V& operator[](const K& k);
  V& at(const K& k);
  const V& at(const K& k) const;
  size_t size() const;
  bool empty() const;
  void clear();
  size_t count(const K& k) const;
  iterator find(const K& k);
  const_iterator find(const K& k) const;
  pair<iterator, bool> insert(const value_type& v);
  iterator insert(const_iterator hint, const value_type& v);
  // the elements of a range (``m.insert(other.begin(), other.end())``, edu_robot's
  // diagnostics merging their entries)
  template<class It> void insert(It first, It last);
  template<class... Args> pair<iterator, bool> emplace(Args&&... args);
  template<class M> pair<iterator, bool> insert_or_assign(const K& k, M&& value);
  template<class... Args> pair<iterator, bool> try_emplace(const K& k, Args&&... args);
  bool contains(const K& k) const;
  iterator lower_bound(const K& k);
  iterator upper_bound(const K& k);
  size_t erase(const K& k);
  iterator erase(iterator pos);
  iterator erase(iterator first, iterator last);
  iterator begin();
  iterator end();
  const_iterator begin() const;
  const_iterator end() const;
  const_iterator cbegin() const;
  const_iterator cend() const;
  // walked backwards (a map's last key: ``m.rbegin()->first``)
  typedef std::reverse_iterator<iterator> reverse_iterator;
  typedef std::reverse_iterator<const_iterator> const_reverse_iterator;
  reverse_iterator rbegin();
  reverse_iterator rend();
  const_reverse_iterator rbegin() const;
  const_reverse_iterator rend() const;
};
template<class K, class V, class C, class A>
bool operator==(const map<K, V, C, A>& a, const map<K, V, C, A>& b);
template<class K, class V, class C, class A>
bool operator!=(const map<K, V, C, A>& a, const map<K, V, C, A>& b);
template<class K, class V, class H = hash<K>, class E = equal_to<K>,
         class A = allocator<pair<const K, V>>>
class unordered_map : public map<K, V> {
public:
  using map<K, V>::map;
  // a hash table's own members, which the ordered map it stands in as lacks
  typedef H hasher;
  typedef E key_equal;
  void reserve(size_t n);
  void rehash(size_t n);
  size_t bucket_count() const;
  size_t bucket(const K& k) const;
  float load_factor() const;
  float max_load_factor() const;
  void max_load_factor(float f);
  hasher hash_function() const;
  key_equal key_eq() const;
};
template<class K, class V, class C = less<K>> class multimap : public map<K, V, C> {
public:
  // every key kept: an insertion gives the element's iterator, not a pair
  typedef typename map<K, V, C>::iterator iterator;
  typedef typename map<K, V, C>::value_type value_type;
  iterator insert(const value_type& v);
  template<class... Args> iterator emplace(Args&&... args);
  pair<iterator, iterator> equal_range(const K& k);
};
template<class K, class C = less<K>, class A = allocator<K>> class set {
public:
  typedef K key_type;
  typedef K value_type;
  typedef const K* iterator;
  typedef const K* const_iterator;
  set();
  set(initializer_list<K> items);
  template<class It> set(It first, It last);
  size_t size() const;
  bool empty() const;
  void clear();
  size_t count(const K& k) const;
  iterator find(const K& k) const;
  pair<iterator, bool> insert(const K& k);
  template<class It> void insert(It first, It last);
  template<class... Args> pair<iterator, bool> emplace(Args&&... args);
  size_t erase(const K& k);
  // by position too (leg_detector's ``matches.erase(matched_iter)`` of a multiset), for
  // an iterator alone: a value the parse declared permissively (``haros_any``, which
  // converts to anything) is a key, as before (fuse's ``set.erase(uuid)``)
  template<class It, class = typename enable_if<is_same<It, const_iterator>::value>::type>
  iterator erase(It position);
  iterator erase(const_iterator first, const_iterator last);
  iterator lower_bound(const K& k) const;
  iterator upper_bound(const K& k) const;
  iterator begin() const;
  iterator end() const;
  iterator cbegin() const;
  iterator cend() const;
};
template<class K, class C, class A> bool operator==(const set<K, C, A>& a, const set<K, C, A>& b);
template<class K, class C, class A> bool operator!=(const set<K, C, A>& a, const set<K, C, A>& b);
template<class K, class C = less<K>, class A = allocator<K>>
class multiset : public set<K, C, A> {
public:
  using set<K, C, A>::set;
  // every key kept: an insertion gives the element's iterator, not a pair
  typedef typename set<K, C, A>::iterator iterator;
  iterator insert(const K& k);
  template<class... Args> iterator emplace(Args&&... args);
  pair<iterator, iterator> equal_range(const K& k) const;
};
template<class K, class H = hash<K>, class E = equal_to<K>, class A = allocator<K>>
class unordered_set : public set<K> {
public:
  using set<K>::set;
  // a hash table's own members, which the ordered set it stands in as lacks
  typedef H hasher;
  typedef E key_equal;
  void reserve(size_t n);
  void rehash(size_t n);
  size_t bucket_count() const;
  size_t bucket(const K& k) const;
  float load_factor() const;
  float max_load_factor() const;
  void max_load_factor(float f);
  hasher hash_function() const;
  key_equal key_eq() const;
};
// the container adaptors' member types and their protected container ``c`` (and
// priority_queue's ``comp``), which a derived class reads: robocup-pkg's path_finder
// derives an ``AStarQueue`` from priority_queue that walks ``this->c`` through
// ``container_type::const_iterator``
template<class T, class S = deque<T>> class queue {
public:
  typedef S container_type;
  typedef typename S::value_type value_type;
  typedef typename S::size_type size_type;
  typedef typename S::reference reference;
  typedef typename S::const_reference const_reference;
  queue();
  explicit queue(const S& container);
  T& front();
  T& back();
  void push(const T& v);
  template<class... Args> void emplace(Args&&... args);
  void pop();
  size_t size() const;
  bool empty() const;
  void swap(queue& other);
protected:
  S c;
};
template<class T, class S = vector<T>, class C = less<T>> class priority_queue {
public:
  typedef S container_type;
  typedef C value_compare;
  typedef typename S::value_type value_type;
  typedef typename S::size_type size_type;
  typedef typename S::reference reference;
  typedef typename S::const_reference const_reference;
  priority_queue();
  explicit priority_queue(const C& compare, const S& container = S());
  const T& top() const;
  void push(const T& v);
  template<class... A> void emplace(A&&... args);
  void pop();
  size_t size() const;
  bool empty() const;
  void swap(priority_queue& other);
protected:
  S c;
  C comp;
};
template<class T, class S = deque<T>> class stack {
public:
  typedef S container_type;
  typedef typename S::value_type value_type;
  typedef typename S::size_type size_type;
  typedef typename S::reference reference;
  typedef typename S::const_reference const_reference;
  stack();
  explicit stack(const S& container);
  T& top();
  void push(const T& v);
  void pop();
  size_t size() const;
  bool empty() const;
protected:
  S c;
};

// <algorithm>, <numeric>, <iterator>, <limits>
template<class T> const T& min(const T& a, const T& b);
template<class T> const T& max(const T& a, const T& b);
template<class T> T min(initializer_list<T> items);
template<class T> T max(initializer_list<T> items);
template<class T, class C> T min(initializer_list<T> items, C compare);
template<class T, class C> T max(initializer_list<T> items, C compare);
template<class T> const T& clamp(const T& v, const T& lo, const T& hi);
template<class It> void sort(It first, It last);
template<class It, class G> void shuffle(It first, It last, G&& g);
template<class It, class C> void sort(It first, It last, C compare);
template<class It, class T> It find(It first, It last, const T& v);
template<class It, class P> It find_if(It first, It last, P pred);
template<class It, class T> size_t count(It first, It last, const T& v);
template<class It, class P> size_t count_if(It first, It last, P pred);
template<class It, class F> F for_each(It first, It last, F f);
template<class It, class O> O copy(It first, It last, O out);
template<class It, class O, class F> O transform(It first, It last, O out, F f);
template<class It, class T> void fill(It first, It last, const T& v);
template<class It, class N, class T> It fill_n(It first, N count, const T& v);
template<class It, class N, class O> O copy_n(It first, N count, O out);
template<class It, class T> It lower_bound(It first, It last, const T& v);
template<class It, class T, class C> It lower_bound(It first, It last, const T& v, C compare);
template<class It, class T> It upper_bound(It first, It last, const T& v);
template<class It, class T, class C> It upper_bound(It first, It last, const T& v, C compare);
template<class It, class T> bool binary_search(It first, It last, const T& v);
template<class It, class P> It find_if_not(It first, It last, P pred);
template<class It, class P> bool none_of(It first, It last, P pred);
template<class It> It unique(It first, It last);
template<class It, class P> It unique(It first, It last, P pred);
template<class It> void stable_sort(It first, It last);
template<class It> void nth_element(It first, It nth, It last);
template<class It, class C> void nth_element(It first, It nth, It last, C compare);
template<class It> void partial_sort(It first, It middle, It last);
template<class It, class C> void partial_sort(It first, It middle, It last, C compare);
template<class It, class O> O partial_sum(It first, It last, O out);
template<class It, class O, class Op> O partial_sum(It first, It last, O out, Op op);
template<class It, class O> O inclusive_scan(It first, It last, O out);
template<class It, class O, class T> O exclusive_scan(It first, It last, O out, T init);
template<class It, class O> O adjacent_difference(It first, It last, O out);
template<class It, class C> void stable_sort(It first, It last, C compare);
template<class It> void reverse(It first, It last);
template<class It> It min_element(It first, It last);
template<class It> It max_element(It first, It last);
template<class It, class C> It min_element(It first, It last, C compare);
template<class It, class C> It max_element(It first, It last, C compare);
template<class It, class T> It remove(It first, It last, const T& v);
template<class It, class P> It remove_if(It first, It last, P pred);
template<class It, class T> void replace(It first, It last, const T& old_value, const T& new_value);
template<class It, class P, class T> void replace_if(It first, It last, P pred, const T& new_value);
template<class It> It unique(It first, It last);
template<class It, class P> It unique(It first, It last, P pred);
template<class It, class P> bool any_of(It first, It last, P pred);
template<class It, class P> bool all_of(It first, It last, P pred);
template<class It, class T> T accumulate(It first, It last, T init);
template<class It, class T, class Op> T accumulate(It first, It last, T init, Op op);
template<class It> auto reduce(It first, It last) -> typename decay<decltype(*first)>::type;
template<class It, class T> T reduce(It first, It last, T init);
template<class It, class T, class Op> T reduce(It first, It last, T init, Op op);
template<class It, class T, class R, class U>
T transform_reduce(It first, It last, T init, R reduce, U transform);
template<class It, class T> void iota(It first, It last, T value);
template<class It> It adjacent_find(It first, It last);
template<class It, class P> It adjacent_find(It first, It last, P pred);
template<class It> It rotate(It first, It middle, It last);
template<class It, class O> O rotate_copy(It first, It middle, It last, O out);
template<class It, class O> O reverse_copy(It first, It last, O out);
template<class It, class O, class P> O copy_if(It first, It last, O out, P pred);
template<class It, class O> O copy_backward(It first, It last, O out);
template<class It, class O> O move_backward(It first, It last, O out);
template<class It, class O, class P> O remove_copy_if(It first, It last, O out, P pred);
template<class It, class O> O unique_copy(It first, It last, O out);
template<class It, class G> void generate(It first, It last, G g);
template<class It, class N, class G> It generate_n(It first, N count, G g);
template<class It> bool is_sorted(It first, It last);
template<class It, class C> bool is_sorted(It first, It last, C compare);
template<class It> pair<It, It> minmax_element(It first, It last);
template<class It, class C> pair<It, It> minmax_element(It first, It last, C compare);
template<class T> pair<const T&, const T&> minmax(const T& a, const T& b);
template<class It, class T> pair<It, It> equal_range(It first, It last, const T& v);
template<class A, class B> bool equal(A first1, A last1, B first2);
template<class A, class B> bool equal(A first1, A last1, B first2, B last2);
template<class A, class B, class P> bool equal(A first1, A last1, B first2, P pred);
template<class A, class B, class P> bool equal(A first1, A last1, B first2, B last2, P pred);
template<class A, class B> pair<A, B> mismatch(A first1, A last1, B first2);
template<class A, class B> A search(A first, A last, B s_first, B s_last);
template<class A, class B> A find_end(A first, A last, B s_first, B s_last);
template<class A, class B> bool includes(A first1, A last1, B first2, B last2);
template<class A, class B> bool lexicographical_compare(A first1, A last1, B first2, B last2);
template<class A, class B, class O> O merge(A first1, A last1, B first2, B last2, O out);
template<class A, class B, class O> O set_union(A first1, A last1, B first2, B last2, O out);
template<class A, class B, class O> O set_intersection(A first1, A last1, B first2, B last2, O out);
template<class A, class B, class O> O set_difference(A first1, A last1, B first2, B last2, O out);
template<class It, class P> It partition(It first, It last, P pred);
template<class It, class P> It stable_partition(It first, It last, P pred);
// C++20's constrained algorithms (std::ranges::for_each(v, f), std::ranges::transform(a,
// b, out, f), std::ranges::find_if(v, p), ...), declared loosely: each of a range or of
// iterators, the projections and comparators any further arguments; an algorithm that
// gives a position gives the range's iterator (or the first argument's type when that
// is an iterator: the range form is then no candidate, ``r.begin()`` failing)
namespace ranges {
template<class R> auto begin(R&& r) -> decltype(r.begin());
template<class R> auto end(R&& r) -> decltype(r.end());
template<class R> auto size(R&& r) -> decltype(r.size());
template<class R> bool empty(R&& r);
template<class R> auto data(R&& r) -> decltype(r.data());
template<class R> using iterator_t = decltype(declval<R&>().begin());
template<class R> using range_value_t =
    typename decay<decltype(*declval<R&>().begin())>::type;
#define HAROS_RANGES_VOID(name) template<class... A> void name(A&&... args);
#define HAROS_RANGES_BOOL(name) template<class... A> bool name(A&&... args);
#define HAROS_RANGES_POSITION(name) \
  template<class R, class... A> auto name(R&& r, A&&... args) -> decltype(r.begin()); \
  template<class I, class... A> I name(I first, I last, A&&... args);
HAROS_RANGES_VOID(for_each) HAROS_RANGES_VOID(for_each_n) HAROS_RANGES_VOID(transform)
HAROS_RANGES_VOID(copy) HAROS_RANGES_VOID(copy_if) HAROS_RANGES_VOID(copy_n)
HAROS_RANGES_VOID(copy_backward) HAROS_RANGES_VOID(move) HAROS_RANGES_VOID(fill)
HAROS_RANGES_VOID(fill_n) HAROS_RANGES_VOID(generate) HAROS_RANGES_VOID(generate_n)
HAROS_RANGES_VOID(sort) HAROS_RANGES_VOID(stable_sort) HAROS_RANGES_VOID(partial_sort)
HAROS_RANGES_VOID(nth_element) HAROS_RANGES_VOID(reverse) HAROS_RANGES_VOID(reverse_copy)
HAROS_RANGES_VOID(shuffle) HAROS_RANGES_VOID(replace) HAROS_RANGES_VOID(replace_if)
HAROS_RANGES_VOID(iota) HAROS_RANGES_VOID(merge) HAROS_RANGES_VOID(set_union)
HAROS_RANGES_VOID(set_intersection) HAROS_RANGES_VOID(set_difference)
HAROS_RANGES_BOOL(any_of) HAROS_RANGES_BOOL(all_of) HAROS_RANGES_BOOL(none_of)
HAROS_RANGES_BOOL(equal) HAROS_RANGES_BOOL(contains) HAROS_RANGES_BOOL(includes)
HAROS_RANGES_BOOL(is_sorted) HAROS_RANGES_BOOL(binary_search)
HAROS_RANGES_BOOL(lexicographical_compare) HAROS_RANGES_BOOL(is_permutation)
HAROS_RANGES_POSITION(find) HAROS_RANGES_POSITION(find_if) HAROS_RANGES_POSITION(find_if_not)
HAROS_RANGES_POSITION(min_element) HAROS_RANGES_POSITION(max_element)
HAROS_RANGES_POSITION(lower_bound) HAROS_RANGES_POSITION(upper_bound)
HAROS_RANGES_POSITION(adjacent_find) HAROS_RANGES_POSITION(find_first_of)
HAROS_RANGES_POSITION(is_sorted_until) HAROS_RANGES_POSITION(partition_point)
#undef HAROS_RANGES_VOID
#undef HAROS_RANGES_BOOL
#undef HAROS_RANGES_POSITION
template<class... A> ptrdiff_t count(A&&... args);
template<class... A> ptrdiff_t count_if(A&&... args);
template<class T, class... A> const T& min(const T& a, const T& b, A&&... args);
template<class T, class... A> const T& max(const T& a, const T& b, A&&... args);
template<class R, class... A> auto min(R&& r, A&&... args) -> range_value_t<R>;
template<class R, class... A> auto max(R&& r, A&&... args) -> range_value_t<R>;
template<class T, class... A> const T& clamp(const T& v, const T& lo, const T& hi, A&&...);
}  // namespace ranges
template<class It, class P> It partition_point(It first, It last, P pred);
template<class It> bool next_permutation(It first, It last);
template<class It> bool prev_permutation(It first, It last);
template<class A, class B> B swap_ranges(A first1, A last1, B first2);
template<class A, class B> void iter_swap(A a, B b);
template<class It> void make_heap(It first, It last);
template<class It> void push_heap(It first, It last);
template<class It> void pop_heap(It first, It last);
template<class It> void sort_heap(It first, It last);
template<class It, class C> void make_heap(It first, It last, C compare);
template<class It, class C> void push_heap(It first, It last, C compare);
template<class It, class C> void pop_heap(It first, It last, C compare);
template<class A, class B, class T> T inner_product(A first1, A last1, B first2, T init);
template<class M, class N> constexpr auto gcd(M m, N n) -> decltype(m + n);
template<class M, class N> constexpr auto lcm(M m, N n) -> decltype(m + n);
template<class It> It prev(It it, ptrdiff_t n = 1);
template<class C> auto begin(C& c) -> decltype(c.begin());
template<class C> auto end(C& c) -> decltype(c.end());
template<class C> auto cbegin(const C& c) -> decltype(c.begin());
template<class C> auto cend(const C& c) -> decltype(c.end());
template<class It> It make_move_iterator(It it);
template<class T, size_t N> T* begin(T (&a)[N]);
template<class T, size_t N> T* end(T (&a)[N]);
template<class It> ptrdiff_t distance(It first, It last);
template<class It> It next(It it, ptrdiff_t n = 1);
template<class It> void advance(It& it, ptrdiff_t n);
template<class C> struct back_insert_iterator {
  back_insert_iterator& operator*();
  back_insert_iterator& operator++();
  template<class V> back_insert_iterator& operator=(const V& v);
};
template<class C> back_insert_iterator<C> back_inserter(C& c);
template<class C> struct front_insert_iterator {
  front_insert_iterator& operator*();
  front_insert_iterator& operator++();
  front_insert_iterator operator++(int);
  template<class V> front_insert_iterator& operator=(const V& v);
};
template<class C> front_insert_iterator<C> front_inserter(C& c);
// std::inserter(c, it): inserts at a position (into a set or map: moveit_task_constructor)
template<class C> struct insert_iterator {
  insert_iterator& operator*();
  insert_iterator& operator++();
  insert_iterator operator++(int);
  template<class V> insert_iterator& operator=(const V& v);
};
template<class C, class I> insert_iterator<C> inserter(C& c, I it);
// the limits' values as constants (an array sized by one: igvc's
// ``std::array<uint8_t, std::numeric_limits<char>::max()>`` member), from the type's size
// and signedness, or the compiler's floating-point macros
template<class T, bool = __is_integral(T), bool = __is_floating_point(T)>
struct haros_limits {
  static constexpr T max() noexcept { return T(); }
  static constexpr T min() noexcept { return T(); }
  static constexpr T lowest() noexcept { return T(); }
  static constexpr T epsilon() noexcept { return T(); }
  static constexpr T infinity() noexcept { return T(); }
  static constexpr T quiet_NaN() noexcept { return T(); }
  static constexpr T denorm_min() noexcept { return T(); }
};
template<class T> struct haros_limits<T, true, false> {
  static constexpr T max() noexcept {
    return __is_signed(T) ? T((((unsigned long long)1) << (sizeof(T) * 8 - 1)) - 1)
                          : T(~T(0));
  }
  static constexpr T min() noexcept { return __is_signed(T) ? T(-max() - 1) : T(0); }
  static constexpr T lowest() noexcept { return min(); }
  static constexpr T epsilon() noexcept { return T(0); }
  static constexpr T infinity() noexcept { return T(0); }
  static constexpr T quiet_NaN() noexcept { return T(0); }
  static constexpr T denorm_min() noexcept { return T(0); }
};
template<class T> struct haros_limits<T, false, true> {
  static constexpr bool single = sizeof(T) == sizeof(float);
  static constexpr bool dual = sizeof(T) == sizeof(double);
  static constexpr T max() noexcept {
    return single ? __FLT_MAX__ : dual ? __DBL_MAX__ : __LDBL_MAX__;
  }
  static constexpr T min() noexcept {
    return single ? __FLT_MIN__ : dual ? __DBL_MIN__ : __LDBL_MIN__;
  }
  static constexpr T lowest() noexcept { return -max(); }
  static constexpr T epsilon() noexcept {
    return single ? __FLT_EPSILON__ : dual ? __DBL_EPSILON__ : __LDBL_EPSILON__;
  }
  static constexpr T infinity() noexcept { return __builtin_huge_vall(); }
  static constexpr T quiet_NaN() noexcept { return __builtin_nanl(""); }
  static constexpr T denorm_min() noexcept {
    return single ? __FLT_DENORM_MIN__ : dual ? __DBL_DENORM_MIN__ : __LDBL_DENORM_MIN__;
  }
};
template<class T> struct numeric_limits {
  static constexpr bool is_specialized = true;
  static constexpr T min() noexcept { return haros_limits<T>::min(); }
  static constexpr T max() noexcept { return haros_limits<T>::max(); }
  static constexpr T lowest() noexcept { return haros_limits<T>::lowest(); }
  static constexpr T epsilon() noexcept { return haros_limits<T>::epsilon(); }
  static constexpr T infinity() noexcept { return haros_limits<T>::infinity(); }
  static constexpr T quiet_NaN() noexcept { return haros_limits<T>::quiet_NaN(); }
  static constexpr T signaling_NaN() noexcept { return haros_limits<T>::quiet_NaN(); }
  static constexpr T denorm_min() noexcept { return haros_limits<T>::denorm_min(); }
  static constexpr T round_error() noexcept { return T(); }
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = false;
  static constexpr bool has_infinity = true;
  static constexpr bool has_quiet_NaN = true;
  static constexpr bool has_signaling_NaN = true;
  static constexpr bool is_iec559 = true;
  static constexpr bool is_bounded = true;
  static constexpr bool is_modulo = false;
  static constexpr bool traps = false;
  static constexpr bool tinyness_before = false;
  static constexpr int digits = 53;
  static constexpr int digits10 = 15;
  static constexpr int max_digits10 = 17;
  static constexpr int radix = 2;
  static constexpr int min_exponent = -1021;
  static constexpr int min_exponent10 = -307;
  static constexpr int max_exponent = 1024;
  static constexpr int max_exponent10 = 308;
};

// <memory>
template<class T> struct default_delete { void operator()(T* p) const; };
template<class T> class weak_ptr;
template<class T, class D> class unique_ptr;
template<class T> class auto_ptr;
// whether a shared_ptr<Y> converts to a shared_ptr<T>: as the real one, when Y* converts
// to T* (so overloads on shared_ptr<A> and shared_ptr<B> of unrelated classes are not
// ambiguous: MoveIt's PlanningScene(RobotModelConstPtr) beside its
// PlanningScene(PlanningSceneConstPtr)); also, as before, from a base to a class derived
// from it (the stand-ins return a base where the real API returns the derived class:
// rclcpp::create_timer's TimerBase for GenericTimer<F>, nav2's lifecycle node), and when
// either class is one the parse declared permissively (``haros_any``) or is not complete
// here (its definition in a header not found)
template<class... A> struct haros_sp_void { typedef void type; };
template<class Y, class T, class = void> struct haros_sp_converts : true_type {};
template<class Y, class T> struct haros_sp_converts<Y, T,
    typename haros_sp_void<decltype(sizeof(Y)), decltype(sizeof(T))>::type>
    : integral_constant<bool, __is_convertible_to(Y*, T*) || __is_base_of(Y, T)
                              || __is_base_of(::haros_any, Y)
                              || __is_base_of(::haros_any, T)> {};
template<class T> class shared_ptr {
public:
  typedef T element_type;
  constexpr shared_ptr() noexcept;
  constexpr shared_ptr(nullptr_t) noexcept;
  template<class Y> explicit shared_ptr(Y* p);
  template<class Y, class D> shared_ptr(Y* p, D d);
  template<class Y, class D, class A> shared_ptr(Y* p, D d, A a);
  template<class D> shared_ptr(nullptr_t p, D d);
  shared_ptr(const shared_ptr& other) noexcept;
  template<class Y, class = typename enable_if<haros_sp_converts<Y, T>::value>::type>
  shared_ptr(const shared_ptr<Y>& other) noexcept;
  // aliasing: shares ownership with ``other``, points at ``p`` (MoveIt's robot models)
  template<class Y> shared_ptr(const shared_ptr<Y>& other, element_type* p) noexcept;
  template<class Y, class D> shared_ptr(unique_ptr<Y, D>&& other);
  template<class Y> shared_ptr(auto_ptr<Y>&& other);  // C++11-14; libstdc++ keeps it
  // what a function the parse declared permissively returns, a pointer in the real code
  // (vrpn_client_ros' ``std::shared_ptr<vrpn_Connection>(vrpn_get_connection_by_name(
  // host))``, vrpn's headers missing): not ambiguous among the constructors above, each
  // reachable through the value's conversion to any type
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  explicit shared_ptr(const U& unknown);
  shared_ptr& operator=(const shared_ptr& other) noexcept;
  template<class Y, class = typename enable_if<haros_sp_converts<Y, T>::value>::type>
  shared_ptr& operator=(const shared_ptr<Y>& other) noexcept;
  T* operator->() const noexcept;
  T& operator*() const noexcept;
  // an array's element (C++17 ``shared_ptr<T[]>``: usb_cam's ``m_buffers[i].start``)
  typename remove_extent<T>::type& operator[](ptrdiff_t i) const;
  T* get() const noexcept;
  void reset() noexcept;
  template<class Y> void reset(Y* p);
  template<class Y, class D> void reset(Y* p, D d);
  template<class Y, class D, class A> void reset(Y* p, D d, A a);
  template<class U, class = typename enable_if<__is_base_of(::haros_any, U)>::type>
  void reset(const U& unknown);  // (as the constructor above)
  long use_count() const noexcept;
  explicit operator bool() const noexcept;
};
// shared_ptr<void> (rclcpp's type-erased messages, timer data, wait set entities) has no
// dereference: the primary template's T& would make a complete shared_ptr<void> an error
template<> class shared_ptr<void> {
public:
  typedef void element_type;
  constexpr shared_ptr() noexcept;
  constexpr shared_ptr(nullptr_t) noexcept;
  template<class Y> explicit shared_ptr(Y* p);
  template<class Y, class D> shared_ptr(Y* p, D d);
  template<class Y, class D, class A> shared_ptr(Y* p, D d, A a);
  template<class D> shared_ptr(nullptr_t p, D d);
  shared_ptr(const shared_ptr& other) noexcept;
  template<class Y> shared_ptr(const shared_ptr<Y>& other) noexcept;
  // aliasing: shares ownership with ``other``, points at ``p`` (MoveIt's robot models)
  template<class Y> shared_ptr(const shared_ptr<Y>& other, element_type* p) noexcept;
  template<class Y, class D> shared_ptr(unique_ptr<Y, D>&& other);
  template<class Y> shared_ptr(auto_ptr<Y>&& other);  // C++11-14; libstdc++ keeps it
  shared_ptr& operator=(const shared_ptr& other) noexcept;
  template<class Y> shared_ptr& operator=(const shared_ptr<Y>& other) noexcept;
  void* get() const noexcept;
  void reset() noexcept;
  template<class Y> void reset(Y* p);
  template<class Y, class D> void reset(Y* p, D d);
  template<class Y, class D, class A> void reset(Y* p, D d, A a);
  long use_count() const noexcept;
  explicit operator bool() const noexcept;
};
template<class T, class U> bool operator==(const shared_ptr<T>& a, const shared_ptr<U>& b);
template<class T, class U> bool operator!=(const shared_ptr<T>& a, const shared_ptr<U>& b);
template<class T, class U> bool operator<(const shared_ptr<T>& a, const shared_ptr<U>& b);
template<class T> bool operator==(const shared_ptr<T>& a, nullptr_t);
template<class T> bool operator!=(const shared_ptr<T>& a, nullptr_t);
template<class T> bool operator==(nullptr_t, const shared_ptr<T>& a);
template<class T> bool operator!=(nullptr_t, const shared_ptr<T>& a);
template<class T> class weak_ptr {
public:
  constexpr weak_ptr() noexcept;
  weak_ptr(const weak_ptr& other) noexcept;
  // from a pointer of another class: when it converts, as shared_ptr's (an overload on
  // weak_ptr<A> beside one on weak_ptr<B> of an unrelated class is no ambiguity:
  // nav2_core's configure of Humble's and of Kilted's node, cabot's planner test)
  template<class Y, class = typename enable_if<haros_sp_converts<Y, T>::value>::type>
  weak_ptr(const weak_ptr<Y>& other) noexcept;
  template<class Y, class = typename enable_if<haros_sp_converts<Y, T>::value>::type>
  weak_ptr(const shared_ptr<Y>& other) noexcept;
  weak_ptr& operator=(const weak_ptr& other) noexcept;
  template<class Y, class = typename enable_if<haros_sp_converts<Y, T>::value>::type>
  weak_ptr& operator=(const weak_ptr<Y>& other) noexcept;
  template<class Y, class = typename enable_if<haros_sp_converts<Y, T>::value>::type>
  weak_ptr& operator=(const shared_ptr<Y>& other) noexcept;
  long use_count() const noexcept;
  shared_ptr<T> lock() const noexcept;
  bool expired() const noexcept;
  void reset() noexcept;
  template<class Y> bool owner_before(const shared_ptr<Y>& other) const noexcept;
  template<class Y> bool owner_before(const weak_ptr<Y>& other) const noexcept;
};
// ordering by owner: the comparator of maps keyed by weak pointers (foxglove_bridge's
// ``std::map<ConnectionHandle, Subscription, std::owner_less<>>``)
template<class T = void> struct owner_less;
template<class T> struct owner_less<shared_ptr<T>> {
  bool operator()(const shared_ptr<T>& a, const shared_ptr<T>& b) const noexcept;
  bool operator()(const shared_ptr<T>& a, const weak_ptr<T>& b) const noexcept;
  bool operator()(const weak_ptr<T>& a, const shared_ptr<T>& b) const noexcept;
};
template<class T> struct owner_less<weak_ptr<T>> {
  bool operator()(const weak_ptr<T>& a, const weak_ptr<T>& b) const noexcept;
  bool operator()(const shared_ptr<T>& a, const weak_ptr<T>& b) const noexcept;
  bool operator()(const weak_ptr<T>& a, const shared_ptr<T>& b) const noexcept;
};
template<> struct owner_less<void> {
  template<class T, class U> bool operator()(const T& a, const U& b) const noexcept;
};
// C++98's auto_ptr (removed in C++17; ROS 1 code still builds it as C++11 / 14)
template<class T> class auto_ptr {
public:
  typedef T element_type;
  explicit auto_ptr(T* p = 0) noexcept;
  auto_ptr(const auto_ptr& other) noexcept;
  template<class Y> auto_ptr(const auto_ptr<Y>& other) noexcept;
  auto_ptr& operator=(const auto_ptr& other) noexcept;
  template<class Y> auto_ptr& operator=(const auto_ptr<Y>& other) noexcept;
  T& operator*() const noexcept;
  T* operator->() const noexcept;
  T* get() const noexcept;
  T* release() noexcept;
  void reset(T* p = 0) noexcept;
};
template<class T, class D = default_delete<T>> class unique_ptr;
template<class T, class D> class unique_ptr {
public:
  typedef T element_type;
  typedef T* pointer;
  constexpr unique_ptr() noexcept;
  constexpr unique_ptr(nullptr_t) noexcept;
  explicit unique_ptr(T* p) noexcept;
  template<class E> unique_ptr(T* p, E&& deleter) noexcept;  // a pointer and its deleter
  unique_ptr(unique_ptr&& other) noexcept;
  template<class U, class E> unique_ptr(unique_ptr<U, E>&& other) noexcept;
  template<class U> unique_ptr(auto_ptr<U>&& other) noexcept;  // C++11-14, as above
  unique_ptr& operator=(unique_ptr&& other) noexcept;
  template<class U, class E> unique_ptr& operator=(unique_ptr<U, E>&& other) noexcept;
  unique_ptr& operator=(nullptr_t) noexcept;
  // a permissive value (a vendor's ``Arm::create(config)``, its header missing), which
  // converts to a unique_ptr and to nullptr_t alike: the factory's pointer, moved in
  template<class A, class = typename remove_reference<A>::type::haros_permissive>
  unique_ptr& operator=(A&& value) noexcept;
  T* operator->() const noexcept;
  T& operator*() const;
  T* get() const noexcept;
  T* release() noexcept;
  void reset(T* p = nullptr) noexcept;
  explicit operator bool() const noexcept;
  D& get_deleter() noexcept;
};
template<class T, class D> class unique_ptr<T[], D> {  // an array's: a member left empty
public:
  typedef T element_type;
  typedef T* pointer;
  constexpr unique_ptr() noexcept;
  constexpr unique_ptr(nullptr_t) noexcept;
  explicit unique_ptr(T* p) noexcept;
  unique_ptr(unique_ptr&& other) noexcept;
  unique_ptr& operator=(unique_ptr&& other) noexcept;
  unique_ptr& operator=(nullptr_t) noexcept;
  T& operator[](size_t i) const;
  T* get() const noexcept;
  T* release() noexcept;
  void reset(T* p = nullptr) noexcept;
  void reset(nullptr_t) noexcept;
  explicit operator bool() const noexcept;
  D& get_deleter() noexcept;
};
template<class T, class D> bool operator==(const unique_ptr<T, D>& a, nullptr_t) noexcept;
template<class T, class D> bool operator!=(const unique_ptr<T, D>& a, nullptr_t) noexcept;
template<class T, class D> bool operator==(nullptr_t, const unique_ptr<T, D>& a) noexcept;
template<class T, class D> bool operator!=(nullptr_t, const unique_ptr<T, D>& a) noexcept;
template<class T1, class D1, class T2, class D2>
bool operator==(const unique_ptr<T1, D1>& a, const unique_ptr<T2, D2>& b);
template<class T1, class D1, class T2, class D2>
bool operator!=(const unique_ptr<T1, D1>& a, const unique_ptr<T2, D2>& b);
template<class T, class... Args> shared_ptr<T> make_shared(Args&&... args);
template<class T, class A, class... Args> shared_ptr<T> allocate_shared(const A& a, Args&&... args);
template<class T, class... Args> unique_ptr<T> make_unique(Args&&... args);
template<class T, class U> shared_ptr<T> static_pointer_cast(const shared_ptr<U>& p) noexcept;
template<class T, class U> shared_ptr<T> dynamic_pointer_cast(const shared_ptr<U>& p) noexcept;
template<class T, class U> shared_ptr<T> const_pointer_cast(const shared_ptr<U>& p) noexcept;
// the atomic access to a shared_ptr (<memory>)
template<class T> shared_ptr<T> atomic_load(const shared_ptr<T>* p);
template<class T> void atomic_store(shared_ptr<T>* p, shared_ptr<T> r);
template<class T> shared_ptr<T> atomic_exchange(shared_ptr<T>* p, shared_ptr<T> r);
template<class T> class enable_shared_from_this {
protected:
  enable_shared_from_this() noexcept;
public:
  shared_ptr<T> shared_from_this();
  shared_ptr<const T> shared_from_this() const;
  weak_ptr<T> weak_from_this() noexcept;
};

// <functional>
// what std::function's converting constructor refuses, as the library's callable
// constraint does: numbers, enumerators, pointers to objects (text) and strings
template<class F> struct haros_not_callable
    : integral_constant<bool, __is_arithmetic(F) || __is_enum(F)> {};
template<class T> struct haros_not_callable<T*> : integral_constant<bool, !__is_function(T)> {};
template<class C, class Tr, class A> struct haros_not_callable<basic_string<C, Tr, A>>
    : true_type {};
// and smart pointers, which have no operator(): realtime_tools' box of a
// shared_ptr<const T>, whose set(value) and set(function) overloads both took a
// shared_ptr<T> (sawyer_simulator's controllers)
template<class T> struct haros_not_callable<shared_ptr<T>> : true_type {};
template<class T> struct haros_not_callable<weak_ptr<T>> : true_type {};
template<class T, class D> struct haros_not_callable<unique_ptr<T, D>> : true_type {};
// and a function object whose one call operator, not a template, cannot take the
// signature's arguments: the library's constraint, which a set of overloads on
// std::function types relies on (Autoware's vector_map: ``findByFilter(Filter<Lane>)``,
// ``findByFilter(Filter<Point>)``, ... given a lambda of one of them); a generic lambda
// or an overloaded call operator is taken, as before (its body is not instantiated)
template<class F, class Signature, class = void> struct haros_refuses_call : false_type {};
template<class F, class R, class... A>
struct haros_refuses_call<F, R(A...), decltype((void)&F::operator())>
    : integral_constant<bool, !is_invocable<F&, A...>::value> {};
template<class Signature> class function;
template<class R, class... A> class function<R(A...)> {
public:
  typedef R result_type;
  function() noexcept;
  function(nullptr_t) noexcept;
  function(const function& f);
  function(function&& f) noexcept;
  template<class F, class = typename enable_if<!haros_not_callable<F>::value &&
                                               !haros_refuses_call<F, R(A...)>::value>::type>
  function(F f);
  function& operator=(const function& f);
  function& operator=(nullptr_t) noexcept;
  template<class F> function& operator=(F&& f);
  R operator()(A... args) const;
  explicit operator bool() const noexcept;
};
template<class R, class... A> bool operator==(const function<R(A...)>& f, nullptr_t) noexcept;
template<class R, class... A> bool operator!=(const function<R(A...)>& f, nullptr_t) noexcept;
template<class R, class... A> bool operator==(nullptr_t, const function<R(A...)>& f) noexcept;
template<class R, class... A> bool operator!=(nullptr_t, const function<R(A...)>& f) noexcept;
namespace placeholders {
template<int I> struct haros_placeholder {};
extern const haros_placeholder<1> _1;
extern const haros_placeholder<2> _2;
extern const haros_placeholder<3> _3;
extern const haros_placeholder<4> _4;
extern const haros_placeholder<5> _5;
extern const haros_placeholder<6> _6;
extern const haros_placeholder<7> _7;
extern const haros_placeholder<8> _8;
extern const haros_placeholder<9> _9;
}
template<class F> struct haros_bind_t {
  template<class... A> void operator()(A&&... args) const;
};
template<class F, class... A> haros_bind_t<F> bind(F&& f, A&&... args);
#if __cplusplus > 201703L
// C++20's bind_front, C++23's bind_back (ateam's nodes: rclcpp::on_shutdown(
// std::bind_front(&JoystickControlNode::SendStop, this)))
template<class F, class... A> haros_bind_t<F> bind_front(F&& f, A&&... args);
#endif
#if __cplusplus > 202002L
template<class F, class... A> haros_bind_t<F> bind_back(F&& f, A&&... args);
#endif
template<class M> haros_bind_t<M> mem_fn(M member) noexcept;
template<class T> struct reference_wrapper {
  reference_wrapper(T& t) noexcept;
  operator T&() const noexcept;
  T& get() const noexcept;
};
template<class T> reference_wrapper<T> ref(T& t) noexcept;
template<class T> reference_wrapper<const T> cref(const T& t) noexcept;

// <optional>, <any>
struct nullopt_t { explicit constexpr nullopt_t(int) {} };
extern const nullopt_t nullopt;
template<class T> class optional {
public:
  constexpr optional() noexcept;
  constexpr optional(nullopt_t) noexcept;
  template<class U = T> optional(U&& v);
  optional& operator=(nullopt_t) noexcept;
  template<class U = T> optional& operator=(U&& v);
  T* operator->();
  const T* operator->() const;
  // ref-qualified as the standard's: an rvalue optional gives its value to move from
  // (kalman_robot's ``MissionState{PanelLayout::read_yaml(...).value()}``, a
  // constructor taking ``PanelLayout&&``)
  T& operator*() &;
  const T& operator*() const&;
  T&& operator*() &&;
  const T&& operator*() const&&;
  T& value() &;
  const T& value() const&;
  T&& value() &&;
  const T&& value() const&&;
  template<class U> T value_or(U&& v) const&;
  template<class U> T value_or(U&& v) &&;
  bool has_value() const noexcept;
  explicit operator bool() const noexcept;
  void reset() noexcept;
  template<class... A> T& emplace(A&&... args);
  void swap(optional& other) noexcept;
};
#if __cplusplus >= 201703L
template<class T> optional(T) -> optional<T>;  // std::optional{value}
#endif
template<class T> bool operator==(const optional<T>& o, nullopt_t) noexcept;
template<class T> bool operator==(nullopt_t, const optional<T>& o) noexcept;
template<class T> bool operator!=(const optional<T>& o, nullopt_t) noexcept;
template<class T> bool operator!=(nullopt_t, const optional<T>& o) noexcept;
template<class T, class U> bool operator==(const optional<T>& a, const optional<U>& b);
template<class T, class U> bool operator!=(const optional<T>& a, const optional<U>& b);
// an optional compared with a value, either side (vesc_driver's ``value < lower`` of a
// std::experimental::optional<double> limit), and two optionals ordered
#define HAROS_OPTIONAL_COMPARE(op) \
  template<class T, class U> bool operator op(const optional<T>& o, const U& v); \
  template<class T, class U> bool operator op(const U& v, const optional<T>& o);
HAROS_OPTIONAL_COMPARE(==) HAROS_OPTIONAL_COMPARE(!=) HAROS_OPTIONAL_COMPARE(<)
HAROS_OPTIONAL_COMPARE(>) HAROS_OPTIONAL_COMPARE(<=) HAROS_OPTIONAL_COMPARE(>=)
#undef HAROS_OPTIONAL_COMPARE
template<class T, class U> bool operator<(const optional<T>& a, const optional<U>& b);
template<class T, class U> bool operator>(const optional<T>& a, const optional<U>& b);
template<class T, class U> bool operator<=(const optional<T>& a, const optional<U>& b);
template<class T, class U> bool operator>=(const optional<T>& a, const optional<U>& b);
template<class T> optional<typename decay<T>::type> make_optional(T&& v);
template<class T, class... A> optional<T> make_optional(A&&... args);

// <typeinfo>: what ``typeid`` gives (clang refuses typeid with no std::type_info)
class type_info {
public:
  virtual ~type_info();
  const char* name() const noexcept;
  bool before(const type_info& other) const noexcept;
  size_t hash_code() const noexcept;
  bool operator==(const type_info& other) const noexcept;
  bool operator!=(const type_info& other) const noexcept;
};
// <typeindex>: a type_info as a value (a map key: yasmin's clients cache)
class type_index {
public:
  type_index(const type_info& info) noexcept;
  size_t hash_code() const noexcept;
  const char* name() const noexcept;
  bool operator==(const type_index& other) const noexcept;
  bool operator!=(const type_index& other) const noexcept;
  bool operator<(const type_index& other) const noexcept;
  bool operator<=(const type_index& other) const noexcept;
  bool operator>(const type_index& other) const noexcept;
  bool operator>=(const type_index& other) const noexcept;
};
template<> struct hash<type_index> { size_t operator()(const type_index& t) const noexcept; };

// <exception>, <stdexcept>
class exception {
public:
  exception() noexcept;
  virtual ~exception();
  virtual const char* what() const noexcept;
};
class exception_ptr {
public:
  exception_ptr() noexcept;
  exception_ptr(decltype(nullptr)) noexcept;
  explicit operator bool() const noexcept;
};
exception_ptr current_exception() noexcept;
[[noreturn]] void rethrow_exception(exception_ptr p);
[[noreturn]] void terminate() noexcept;
template<class E> exception_ptr make_exception_ptr(E e) noexcept;
class runtime_error : public exception {
public:
  explicit runtime_error(const string& what);
  explicit runtime_error(const char* what);
};
class logic_error : public exception {
public:
  explicit logic_error(const string& what);
  explicit logic_error(const char* what);
};
class invalid_argument : public logic_error { public: using logic_error::logic_error; };
class out_of_range : public logic_error { public: using logic_error::logic_error; };
class domain_error : public logic_error { public: using logic_error::logic_error; };
class length_error : public logic_error { public: using logic_error::logic_error; };
class range_error : public runtime_error { public: using runtime_error::runtime_error; };
class overflow_error : public runtime_error { public: using runtime_error::runtime_error; };
// <system_error>
class error_category {
public:
  virtual const char* name() const noexcept;
  virtual string message(int ev) const;
};
const error_category& system_category() noexcept;
const error_category& generic_category() noexcept;
class error_code {
public:
  error_code() noexcept;
  error_code(int ev, const error_category& category) noexcept;
  int value() const noexcept;
  const error_category& category() const noexcept;
  string message() const;
  explicit operator bool() const noexcept;
};
class system_error : public runtime_error {
public:
  system_error(error_code ec);
  system_error(error_code ec, const string& what);
  system_error(error_code ec, const char* what);
  system_error(int ev, const error_category& category);
  system_error(int ev, const error_category& category, const string& what);
  system_error(int ev, const error_category& category, const char* what);
  const error_code& code() const noexcept;
};
class bad_alloc : public exception {};
class bad_cast : public exception {};

// <locale>: a stream's imbue with a locale (a facet's format: rovio's bag file names)
class locale {
public:
  class facet {
  protected:
    explicit facet(size_t refs = 0);
    virtual ~facet();
  };
  locale();
  locale(const locale& other);
  explicit locale(const char* name);
  explicit locale(const string& name);
  template <class Facet> locale(const locale& other, Facet* f);
  static const locale& classic();
  static locale global(const locale& loc);
  string name() const;
};
// <codecvt> and <locale>'s conversion between UTF-8 and wide strings (deprecated, still
// used: navigation2_tutorials' SMS behaviour)
enum codecvt_mode { consume_header = 4, generate_header = 2, little_endian = 1 };
template<class Elem, unsigned long Maxcode = 0x10ffff, codecvt_mode Mode = (codecvt_mode)0>
class codecvt_utf8 : public locale::facet {};
template<class Elem, unsigned long Maxcode = 0x10ffff, codecvt_mode Mode = (codecvt_mode)0>
class codecvt_utf16 : public locale::facet {};
template<class Elem, unsigned long Maxcode = 0x10ffff, codecvt_mode Mode = (codecvt_mode)0>
class codecvt_utf8_utf16 : public locale::facet {};
template<class Codecvt, class Elem = wchar_t> class wstring_convert {
public:
  typedef basic_string<char> byte_string;
  typedef basic_string<Elem> wide_string;
  wstring_convert();
  explicit wstring_convert(Codecvt* pcvt);
  wstring_convert(const byte_string& byte_err, const wide_string& wide_err = wide_string());
  wide_string from_bytes(char byte);
  wide_string from_bytes(const char* ptr);
  wide_string from_bytes(const byte_string& str);
  wide_string from_bytes(const char* first, const char* last);
  byte_string to_bytes(Elem wchar);
  byte_string to_bytes(const Elem* wptr);
  byte_string to_bytes(const wide_string& wstr);
  byte_string to_bytes(const Elem* first, const Elem* last);
  size_t converted() const noexcept;
};
// <iostream>, <sstream>, <fstream>, <iomanip>
class ios_base {
public:
  typedef int fmtflags;
  typedef int openmode;
  static const openmode in = 1, out = 2, app = 4, binary = 8, trunc = 16, ate = 32;
  static const fmtflags fixed = 1, scientific = 2, boolalpha = 4, hex = 8, dec = 16,
    oct = 32, left = 64, right = 128, internal = 256, showpos = 512, showpoint = 1024,
    showbase = 2048, uppercase = 4096, skipws = 8192, unitbuf = 16384,
    floatfield = fixed | scientific, adjustfield = left | right | internal,
    basefield = dec | oct | hex;
  typedef int seekdir;
  typedef long pos_type;
  typedef long off_type;
  static const seekdir beg = 0, cur = 1, end = 2;
  fmtflags setf(fmtflags f);
  fmtflags setf(fmtflags f, fmtflags mask);
  void unsetf(fmtflags mask);
  fmtflags flags() const;
  fmtflags flags(fmtflags f);
  long width() const;
  long width(long w);
  char fill() const;
  char fill(char c);
  int precision(int p);
  class streambuf* rdbuf() const;
  typedef int iostate;
  static const iostate goodbit = 0, badbit = 1, eofbit = 2, failbit = 4;
  void clear(iostate state = goodbit);
  iostate rdstate() const;
  void setstate(iostate state);
  bool bad() const;
  // basic_ios' state, one for a stream that reads and writes (std::stringstream's
  // ``ss.good()`` is no ambiguity between its input and output sides)
  bool good() const;
  bool fail() const;
  bool eof() const;
  explicit operator bool() const;
  locale imbue(const locale& loc);
  locale getloc() const;
};
typedef ios_base ios;
typedef long streamsize;
typedef long streamoff;
class streambuf {
public:
  virtual ~streambuf();
};
class ostream : virtual public ios_base {
public:
  ostream& operator<<(bool v);
  ostream& operator<<(short v);
  ostream& operator<<(unsigned short v);
  ostream& operator<<(int v);
  ostream& operator<<(unsigned v);
  ostream& operator<<(long v);
  ostream& operator<<(unsigned long v);
  ostream& operator<<(long long v);
  ostream& operator<<(unsigned long long v);
  ostream& operator<<(float v);
  ostream& operator<<(double v);
  ostream& operator<<(long double v);
  ostream& operator<<(const void* v);
  ostream& operator<<(ostream& (*manip)(ostream&));
  ostream& flush();
  ostream& write(const char* s, long n);
};
ostream& operator<<(ostream& os, char c);
ostream& operator<<(ostream& os, const char* s);
ostream& operator<<(ostream& os, const string& s);
template<class T> ostream& operator<<(ostream& os, const T& v);
// a stream written while a temporary, ``(std::ostringstream() << a << b).str()``: the
// stream itself comes back (realsense2_camera's STREAM_NAME)
template<class S, class T, class = typename enable_if<__is_base_of(ostream, S)>::type>
S&& operator<<(S&& os, const T& v);
class istream : virtual public ios_base {
public:
  istream& operator>>(bool& v);
  istream& operator>>(int& v);
  istream& operator>>(unsigned& v);
  istream& operator>>(long& v);
  istream& operator>>(unsigned long& v);
  istream& operator>>(float& v);
  istream& operator>>(double& v);
  istream& operator>>(string& s);
  istream& operator>>(char& c);
  istream& ignore(long n = 1, int delim = -1);
  int get();
  istream& get(char& c);
  int peek();
  istream& putback(char c);
  istream& unget();
  istream& read(char* s, long n);
  istream& seekg(long pos);
  istream& seekg(long off, ios_base::seekdir dir);
  long tellg();
  long gcount() const;
  istream& operator>>(istream& (*manip)(istream&));
  // the format flags, which the stand-in declares as output manipulators
  // (``std::istringstream(text) >> std::boolalpha >> flag``)
  istream& operator>>(ostream& (*manip)(ostream&));
};
class iostream : public ostream, public istream {};
// <iterator>'s stream iterators
template<class C, class Tr = char_traits<C>> class istreambuf_iterator {
public:
  typedef C value_type;
  istreambuf_iterator() noexcept;
  istreambuf_iterator(istream& is) noexcept;
  istreambuf_iterator(streambuf* sb) noexcept;
  C operator*() const;
  istreambuf_iterator& operator++();
  istreambuf_iterator operator++(int);
  bool operator==(const istreambuf_iterator& other) const;
  bool operator!=(const istreambuf_iterator& other) const;
};
template<class T, class C = char> class istream_iterator {
public:
  typedef T value_type;
  istream_iterator();
  istream_iterator(istream& is);
  const T& operator*() const;
  const T* operator->() const;
  istream_iterator& operator++();
  istream_iterator operator++(int);
  bool operator==(const istream_iterator& other) const;
  bool operator!=(const istream_iterator& other) const;
};
template<class T, class C = char> class ostream_iterator {
public:
  ostream_iterator(ostream& os);
  ostream_iterator(ostream& os, const C* delimiter);
  ostream_iterator& operator=(const T& value);
  ostream_iterator& operator*();
  ostream_iterator& operator++();
  ostream_iterator& operator++(int);
};
istream& getline(istream& is, string& s);
istream& getline(istream& is, string& s, char delim);
istream& ws(istream& is);
istream& skipws(istream& is);
istream& noskipws(istream& is);
ostream& endl(ostream& os);
ostream& flush(ostream& os);
ostream& fixed(ostream& os);
ostream& scientific(ostream& os);
ostream& boolalpha(ostream& os);
ostream& hex(ostream& os);
ostream& dec(ostream& os);
ostream& oct(ostream& os);
ostream& hexfloat(ostream& os);
ostream& uppercase(ostream& os);
ostream& nouppercase(ostream& os);
ostream& showbase(ostream& os);
ostream& noshowbase(ostream& os);
ostream& showpoint(ostream& os);
ostream& noshowpoint(ostream& os);
ostream& noshowpos(ostream& os);
ostream& ends(ostream& os);
ostream& left(ostream& os);
ostream& right(ostream& os);
ostream& internal(ostream& os);
ostream& noboolalpha(ostream& os);
ostream& showpos(ostream& os);
ostream& defaultfloat(ostream& os);
extern ostream cout;
extern ostream cerr;
extern ostream clog;
extern istream cin;
struct haros_manip {};
haros_manip setprecision(int n);
haros_manip setw(int n);
haros_manip setfill(char c);
haros_manip setiosflags(ios_base::fmtflags mask);
haros_manip resetiosflags(ios_base::fmtflags mask);
haros_manip setbase(int base);
haros_manip put_time(const tm* t, const char* format);
// C++14: a string written between delimiters (MoveIt's ``<< std::quoted(group)``)
template<class S> haros_manip quoted(const S& s, char delim = '"', char escape = '\\');
haros_manip get_time(tm* t, const char* format);
ostream& operator<<(ostream& os, haros_manip m);
istream& operator>>(istream& is, haros_manip m);
istream& operator>>(istream&& is, haros_manip m);
class stringstream : public iostream {
public:
  stringstream();
  explicit stringstream(openmode mode);  // ``ostringstream log(ostringstream::out)``
  explicit stringstream(const string& s, openmode mode = in | out);
  string str() const;
  void str(const string& s);
  void clear();
};
class ostringstream : public ostream {
public:
  ostringstream();
  explicit ostringstream(openmode mode);  // ``ostringstream log(ostringstream::out)``
  explicit ostringstream(const string& s, openmode mode = out);
  string str() const;
  void str(const string& s);
  void clear();
};
class istringstream : public istream {
public:
  istringstream();
  explicit istringstream(openmode mode);  // ``ostringstream log(ostringstream::out)``
  explicit istringstream(const string& s, openmode mode = in);
  string str() const;
  void str(const string& s);
  void clear();
};
// the wide streams (<sstream>, <iostream>, <fstream> over wchar_t: bcap_service's
// ``std::wstringstream ss; ss << L",WDT=" << m_wdt; ss.str().c_str()``), each its own
// class as the narrow ones are
class wostream : virtual public ios_base {
public:
  wostream& operator<<(bool v);
  wostream& operator<<(short v);
  wostream& operator<<(unsigned short v);
  wostream& operator<<(int v);
  wostream& operator<<(unsigned v);
  wostream& operator<<(long v);
  wostream& operator<<(unsigned long v);
  wostream& operator<<(long long v);
  wostream& operator<<(unsigned long long v);
  wostream& operator<<(float v);
  wostream& operator<<(double v);
  wostream& operator<<(long double v);
  wostream& operator<<(const void* v);
  wostream& operator<<(wostream& (*manip)(wostream&));
  wostream& operator<<(ostream& (*manip)(ostream&));
  wostream& flush();
  wostream& write(const wchar_t* s, long n);
};
wostream& operator<<(wostream& os, wchar_t c);
wostream& operator<<(wostream& os, char c);
wostream& operator<<(wostream& os, const wchar_t* s);
wostream& operator<<(wostream& os, const char* s);
wostream& operator<<(wostream& os, const wstring& s);
wostream& operator<<(wostream& os, haros_manip m);
class wistream : virtual public ios_base {
public:
  wistream& operator>>(bool& v);
  wistream& operator>>(int& v);
  wistream& operator>>(unsigned& v);
  wistream& operator>>(long& v);
  wistream& operator>>(unsigned long& v);
  wistream& operator>>(float& v);
  wistream& operator>>(double& v);
  wistream& operator>>(wstring& s);
  wistream& operator>>(wchar_t& c);
  wistream& ignore(long n = 1, int delim = -1);
  int get();
  wistream& get(wchar_t& c);
  int peek();
  wistream& read(wchar_t* s, long n);
  long gcount() const;
};
class wiostream : public wostream, public wistream {};
wistream& getline(wistream& is, wstring& s);
wistream& getline(wistream& is, wstring& s, wchar_t delim);
extern wostream wcout;
extern wostream wcerr;
extern wostream wclog;
extern wistream wcin;
class wstringstream : public wiostream {
public:
  wstringstream();
  explicit wstringstream(const wstring& s, openmode mode = in | out);
  wstring str() const;
  void str(const wstring& s);
  void clear();
};
class wostringstream : public wostream {
public:
  wostringstream();
  explicit wostringstream(const wstring& s, openmode mode = out);
  wstring str() const;
  void str(const wstring& s);
  void clear();
};
class wistringstream : public wistream {
public:
  wistringstream();
  explicit wistringstream(const wstring& s, openmode mode = in);
  wstring str() const;
  void str(const wstring& s);
  void clear();
};
class ifstream : public istream {
public:
  ifstream();
  explicit ifstream(const string& path, openmode mode = in);
  explicit ifstream(const char* path, openmode mode = in);
  void open(const string& path, openmode mode = in);
  bool is_open() const;
  void close();
};
class ofstream : public ostream {
public:
  ofstream();
  explicit ofstream(const string& path, openmode mode = out);
  explicit ofstream(const char* path, openmode mode = out);
  void open(const string& path, openmode mode = out);
  bool is_open() const;
  void close();
};
class fstream : public iostream {
public:
  fstream();
  explicit fstream(const string& path, openmode mode = in | out);
  void open(const string& path, openmode mode = in | out);
  bool is_open() const;
  void close();
};

// <chrono>, <thread>, <mutex>, <condition_variable>, <atomic>, <future>
template<long N, long D = 1> struct ratio {
  static constexpr long num = N;
  static constexpr long den = D;
};
typedef ratio<1, 1000000000> nano;
typedef ratio<1, 1000000> micro;
typedef ratio<1, 1000> milli;
namespace chrono {
template<class R, class P = ratio<1>> class duration {
  R haros_count_;
public:
  typedef R rep;
  typedef P period;
  // defined, so that a constexpr duration can be initialised with them
  // (constexpr auto period = std::chrono::duration<double>(1.0 / 40.0);)
  constexpr duration() : haros_count_() {}
  template<class R2> constexpr explicit duration(const R2& count) : haros_count_(count) {}
  // implicit where the standard allows it: to a floating-point count, or from a count
  // of a period that is a whole multiple of this one (seconds to milliseconds, not back,
  // so that a conditional between the two has one type); from a floating-point count
  // too, which the standard refuses, as this file's arithmetic gives double counts
  template<class R2, class P2, class = typename enable_if<
      __is_floating_point(R) || __is_floating_point(R2) ||
      (P2::num * P::den) % (P2::den * P::num) == 0>::type>
  constexpr duration(const duration<R2, P2>& d) : haros_count_(d.count()) {}
  constexpr R count() const { return haros_count_; }
  static constexpr duration zero() { return duration(); }
  static constexpr duration max() { return duration(); }
  static constexpr duration min() { return duration(); }
  duration operator-() const;
  duration& operator+=(const duration& d);
  duration& operator-=(const duration& d);
};
template<class R1, class P1, class R2, class P2>
duration<double, P1> operator+(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2, class P2>
duration<double, P1> operator-(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2>
duration<R1, P1> operator*(const duration<R1, P1>& a, const R2& s);
template<class R1, class R2, class P2>
duration<R2, P2> operator*(const R1& s, const duration<R2, P2>& a);
template<class R1, class P1, class R2>
duration<R1, P1> operator/(const duration<R1, P1>& a, const R2& s);
// a duration over a duration is a count (how many periods of b fit in a)
template<class R1, class P1, class R2, class P2>
decltype(R1() / R2()) operator/(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2, class P2>
bool operator<(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2, class P2>
bool operator>(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2, class P2>
bool operator<=(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2, class P2>
bool operator>=(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2, class P2>
bool operator==(const duration<R1, P1>& a, const duration<R2, P2>& b);
template<class R1, class P1, class R2, class P2>
bool operator!=(const duration<R1, P1>& a, const duration<R2, P2>& b);
typedef duration<long, nano> nanoseconds;
typedef duration<long, micro> microseconds;
typedef duration<long, milli> milliseconds;
typedef duration<long> seconds;
typedef duration<long, ratio<60>> minutes;
typedef duration<long, ratio<3600>> hours;
template<class To, class R, class P> constexpr To duration_cast(const duration<R, P>& d) {
  return To(d.count());
}
template<class C, class D = typename C::duration> class time_point {
public:
  typedef D duration;
  time_point();
  explicit time_point(const D& d);
  D time_since_epoch() const;
  time_point& operator+=(const D& d);
  time_point& operator-=(const D& d);
};
template<class To, class C, class D>
constexpr time_point<C, To> time_point_cast(const time_point<C, D>& t);
template<class C, class D1, class D2>
D1 operator-(const time_point<C, D1>& a, const time_point<C, D2>& b);
template<class C, class D, class R, class P>
time_point<C, D> operator+(const time_point<C, D>& a, const duration<R, P>& d);
template<class C, class D, class R, class P>
time_point<C, D> operator-(const time_point<C, D>& a, const duration<R, P>& d);
template<class C, class D1, class D2>
bool operator<(const time_point<C, D1>& a, const time_point<C, D2>& b);
template<class C, class D1, class D2>
bool operator>(const time_point<C, D1>& a, const time_point<C, D2>& b);
template<class C, class D1, class D2>
bool operator>=(const time_point<C, D1>& a, const time_point<C, D2>& b);
// equality and the rest (lidar_localization_ros2's ``last_log_time_ !=
// std::chrono::steady_clock::time_point{}``, a time not set yet)
template<class C, class D1, class D2>
bool operator<=(const time_point<C, D1>& a, const time_point<C, D2>& b);
template<class C, class D1, class D2>
bool operator==(const time_point<C, D1>& a, const time_point<C, D2>& b);
template<class C, class D1, class D2>
bool operator!=(const time_point<C, D1>& a, const time_point<C, D2>& b);
template<class R, class P, class C, class D>
time_point<C, D> operator+(const duration<R, P>& d, const time_point<C, D>& a);
struct system_clock {
  typedef nanoseconds duration;
  typedef chrono::time_point<system_clock> time_point;
  static time_point now() noexcept;
  static time_t to_time_t(const time_point& t) noexcept;
};
struct steady_clock {
  typedef nanoseconds duration;
  typedef chrono::time_point<steady_clock> time_point;
  static time_point now() noexcept;
};
typedef steady_clock high_resolution_clock;
}  // namespace chrono
inline namespace literals { inline namespace chrono_literals {
constexpr chrono::hours operator""h(unsigned long long v) { return chrono::hours(v); }
constexpr chrono::minutes operator""min(unsigned long long v) { return chrono::minutes(v); }
constexpr chrono::seconds operator""s(unsigned long long v) { return chrono::seconds(v); }
constexpr chrono::milliseconds operator""ms(unsigned long long v) { return chrono::milliseconds(v); }
constexpr chrono::microseconds operator""us(unsigned long long v) { return chrono::microseconds(v); }
constexpr chrono::nanoseconds operator""ns(unsigned long long v) { return chrono::nanoseconds(v); }
constexpr chrono::duration<double> operator""s(long double v) { return chrono::duration<double>(v); }
constexpr chrono::duration<double, milli> operator""ms(long double v) { return chrono::duration<double, milli>(v); }
} }
namespace chrono { using namespace literals::chrono_literals; }
class thread {
public:
  class id {};
  thread() noexcept;
  template<class F, class... A> explicit thread(F&& f, A&&... args);
  thread(thread&& other) noexcept;
  thread& operator=(thread&& other) noexcept;
  ~thread();
  bool joinable() const noexcept;
  void join();
  void detach();
  id get_id() const noexcept;
  // the platform's handle (a pthread_t here): examples_rclcpp_cbg_executor sets a
  // thread's priority and affinity through it
  typedef unsigned long native_handle_type;
  native_handle_type native_handle();
  static unsigned hardware_concurrency() noexcept;
};
namespace this_thread {
template<class R, class P> void sleep_for(const chrono::duration<R, P>& d);
template<class C, class D> void sleep_until(const chrono::time_point<C, D>& t);
void yield() noexcept;
thread::id get_id() noexcept;
}
class mutex {
public:
  mutex();
  void lock();
  bool try_lock();
  void unlock();
};
class recursive_mutex : public mutex {};
class timed_mutex : public mutex {};
class shared_mutex : public mutex {
public:
  void lock_shared();
  void unlock_shared();
};
class shared_timed_mutex : public shared_mutex {};
struct defer_lock_t {};
struct adopt_lock_t {};
struct try_to_lock_t {};
extern const defer_lock_t defer_lock;
extern const adopt_lock_t adopt_lock;
extern const try_to_lock_t try_to_lock;
template<class M> class lock_guard {
public:
  explicit lock_guard(M& m);
  lock_guard(M& m, adopt_lock_t t);
  ~lock_guard();
};
template<class... M> class scoped_lock {
public:
  explicit scoped_lock(M&... m);
};
template<class M> class unique_lock {
public:
  unique_lock();
  explicit unique_lock(M& m);
  unique_lock(M& m, defer_lock_t t);
  unique_lock(M& m, try_to_lock_t t);
  unique_lock(M& m, adopt_lock_t t);
  void lock();
  void unlock();
  bool try_lock();
  bool owns_lock() const;
  explicit operator bool() const noexcept;
  M* mutex() const noexcept;
  M* release() noexcept;
};
template<class M> class shared_lock {
public:
  shared_lock() noexcept;
  explicit shared_lock(M& m);
  shared_lock(M& m, defer_lock_t t);
  shared_lock(M& m, try_to_lock_t t);
  shared_lock(M& m, adopt_lock_t t);
  void lock();
  void unlock();
  bool try_lock();
  bool owns_lock() const noexcept;
  explicit operator bool() const noexcept;
  M* mutex() const noexcept;
  M* release() noexcept;
};
class condition_variable {
public:
  condition_variable();
  void notify_one() noexcept;
  void notify_all() noexcept;
  void wait(unique_lock<mutex>& lock);
  template<class P> void wait(unique_lock<mutex>& lock, P pred);
  template<class R, class Pe> int wait_for(unique_lock<mutex>& lock, const chrono::duration<R, Pe>& d);
  template<class R, class Pe, class P>
  bool wait_for(unique_lock<mutex>& lock, const chrono::duration<R, Pe>& d, P pred);
};
typedef condition_variable condition_variable_any;
struct once_flag { once_flag(); };
template<class F, class... A> void call_once(once_flag& flag, F&& f, A&&... args);
enum memory_order { memory_order_relaxed, memory_order_consume, memory_order_acquire,
                    memory_order_release, memory_order_acq_rel, memory_order_seq_cst };
template<class T> struct atomic {
  atomic() noexcept;
  constexpr atomic(T v) noexcept;
  T operator=(T v) noexcept;
  // a permissive value (a vendor SDK's ``state.main_code``, its header missing), which
  // converts to T and to atomic alike: stored as a T (unique_ptr's above the same)
  template<class A, class = typename remove_reference<A>::type::haros_permissive>
  atomic(A&& value) noexcept;
  template<class A, class = typename remove_reference<A>::type::haros_permissive>
  T operator=(A&& value) noexcept;
  operator T() const noexcept;
  T load(memory_order order = memory_order_seq_cst) const noexcept;
  void store(T v, memory_order order = memory_order_seq_cst) noexcept;
  T exchange(T v, memory_order order = memory_order_seq_cst) noexcept;
  bool compare_exchange_strong(T& expected, T desired,
                               memory_order order = memory_order_seq_cst) noexcept;
  T operator++() noexcept;
  T operator++(int) noexcept;
  T operator--() noexcept;
  T operator--(int) noexcept;
  T operator+=(T v) noexcept;
  T operator-=(T v) noexcept;
  T operator&=(T v) noexcept;
  T operator|=(T v) noexcept;
  T operator^=(T v) noexcept;
  T fetch_add(T v, memory_order order = memory_order_seq_cst) noexcept;
  T fetch_sub(T v, memory_order order = memory_order_seq_cst) noexcept;
  T fetch_and(T v, memory_order order = memory_order_seq_cst) noexcept;
  T fetch_or(T v, memory_order order = memory_order_seq_cst) noexcept;
  T fetch_xor(T v, memory_order order = memory_order_seq_cst) noexcept;
  bool compare_exchange_weak(T& expected, T desired,
                             memory_order order = memory_order_seq_cst) noexcept;
  bool is_lock_free() const noexcept;
};
typedef atomic<bool> atomic_bool;
typedef atomic<char> atomic_char;
typedef atomic<signed char> atomic_schar;
typedef atomic<unsigned char> atomic_uchar;
typedef atomic<short> atomic_short;
typedef atomic<unsigned short> atomic_ushort;
typedef atomic<int> atomic_int;
typedef atomic<unsigned int> atomic_uint;
typedef atomic<long> atomic_long;
typedef atomic<unsigned long> atomic_ulong;
typedef atomic<long long> atomic_llong;
typedef atomic<unsigned long long> atomic_ullong;
typedef atomic<int8_t> atomic_int8_t;
typedef atomic<uint8_t> atomic_uint8_t;
typedef atomic<int16_t> atomic_int16_t;
typedef atomic<uint16_t> atomic_uint16_t;
typedef atomic<int32_t> atomic_int32_t;
typedef atomic<uint32_t> atomic_uint32_t;
typedef atomic<int64_t> atomic_int64_t;
typedef atomic<uint64_t> atomic_uint64_t;
typedef atomic<size_t> atomic_size_t;
typedef atomic<ptrdiff_t> atomic_ptrdiff_t;
typedef atomic<intptr_t> atomic_intptr_t;
typedef atomic<uintptr_t> atomic_uintptr_t;
enum class future_status { ready, timeout, deferred };
template<class T> class shared_future;
template<class T> class future {
public:
  future() noexcept;
  T get();
  bool valid() const noexcept;
  void wait() const;
  template<class R, class P> future_status wait_for(const chrono::duration<R, P>& d) const;
  shared_future<T> share() noexcept;
};
template<class T> class shared_future {
public:
  shared_future() noexcept;
  shared_future(future<T>&& f) noexcept;
  template<class U> shared_future(future<U>&& f) noexcept;  // std::async's result
  shared_future share() const noexcept;
  const T& get() const;
  bool valid() const noexcept;
  void wait() const;
  template<class R, class P> future_status wait_for(const chrono::duration<R, P>& d) const;
};
template<class T> class promise {
public:
  promise();
  future<T> get_future();
  void set_value(const T& v);
  template<class E> void set_exception(E e);
};
template<> class promise<void> {
public:
  promise();
  future<void> get_future();
  void set_value();
  template<class E> void set_exception(E e);
};
template<class S> class packaged_task;
template<class R, class... A> class packaged_task<R(A...)> {
public:
  packaged_task() noexcept;
  template<class F> explicit packaged_task(F&& f);
  packaged_task(packaged_task&& other) noexcept;
  packaged_task& operator=(packaged_task&& other) noexcept;
  bool valid() const noexcept;
  future<R> get_future();
  void operator()(A... args);
  void reset();
};
enum class launch { async = 1, deferred = 2 };
// std::async's future holds what the function returns (``future<void>`` of a void member
// function: robocup-pkg's path_finder, ``std::async(launch::async, &Graph::search, g, ...)``);
// int when invoke cannot tell (a callable the parse does not know)
template<class F, class... A> struct __haros_async_result {
  template<class G> static auto test(int) -> decltype(invoke(declval<G>(), declval<A>()...));
  template<class G> static int test(...);
  typedef decltype(test<F>(0)) type;
};
template<class F, class... A>
future<typename __haros_async_result<F, A...>::type> async(launch policy, F&& f, A&&... args);
template<class F, class... A>
future<typename __haros_async_result<F, A...>::type> async(F&& f, A&&... args);
// <variant>, <random>
template<class... T> class variant {
public:
  variant();
  template<class U> variant(U&& value);
  template<class U> variant& operator=(U&& value);
  template<class X, class... A> X& emplace(A&&... args);
  size_t index() const noexcept;
};
template<class T, class... V> bool holds_alternative(const variant<V...>& v) noexcept;
template<class T, class... V> T& get(variant<V...>& v);
template<class T, class... V> const T& get(const variant<V...>& v);
template<class T, class... V> T* get_if(variant<V...>* v) noexcept;
// the visitor called with each variant's first alternative (a generic lambda's body is
// read as written: ``[&](auto & var) { ... }``)
template<class V> struct haros_first_alternative;
template<class T0, class... T> struct haros_first_alternative<variant<T0, T...>> {
  typedef T0 type; };
template<class F, class... V> auto visit(F&& f, V&&... v) -> decltype(f(
    declval<typename haros_first_alternative<typename decay<V>::type>::type&>()...));
struct monostate {};
inline constexpr size_t variant_npos = static_cast<size_t>(-1);
template<class T> struct variant_size;
template<class... T> struct variant_size<variant<T...>> {
  static constexpr size_t value = sizeof...(T); };
template<class T> constexpr size_t variant_size_v = variant_size<T>::value;
template<size_t I, class... V> auto& get(variant<V...>& v);
template<size_t I, class... V> const auto& get(const variant<V...>& v);
class bad_variant_access : public exception {};
// <any>
class bad_any_cast : public bad_cast {};
class any {
public:
  any() noexcept;
  template<class T> any(T&& value);
  template<class T> any& operator=(T&& value);
  bool has_value() const noexcept;
  void reset() noexcept;
  const type_info& type() const noexcept;
};
template<class T> T any_cast(const any& operand);
template<class T> T any_cast(any& operand);
template<class T> const T* any_cast(const any* operand) noexcept;
template<class T> T* any_cast(any* operand) noexcept;
class random_device { public: random_device(); unsigned int operator()(); };
template<class U> class haros_engine {
public:
  typedef U result_type;
  static constexpr U min() { return 0; }
  static constexpr U max() { return U(-1); }
  haros_engine();
  explicit haros_engine(U seed);
  void seed(U value);
  U operator()();
};
typedef haros_engine<unsigned int> mt19937;
typedef haros_engine<unsigned long long> mt19937_64;
template<class E, size_t W, class U> class independent_bits_engine : public haros_engine<U> {
public: independent_bits_engine(); explicit independent_bits_engine(U seed); };
typedef haros_engine<unsigned int> default_random_engine;
typedef haros_engine<unsigned int> minstd_rand;
template<class T = double> class uniform_real_distribution {
public: uniform_real_distribution(T a = 0, T b = 1); template<class G> T operator()(G& g); };
template<class T = int> class uniform_int_distribution {
public: uniform_int_distribution(T a = 0, T b = 2147483647); template<class G> T operator()(G& g); };
template<class T = double> class normal_distribution {
public:
  typedef T result_type;
  struct param_type { param_type(T mean = 0, T stddev = 1); T mean() const; T stddev() const; };
  normal_distribution(T mean = 0, T stddev = 1);
  explicit normal_distribution(const param_type& params);
  template<class G> T operator()(G& g);
  template<class G> T operator()(G& g, const param_type& params);
  param_type param() const;
  void param(const param_type& params);
  T mean() const;
  T stddev() const;
};
class bernoulli_distribution { public: bernoulli_distribution(double p = 0.5); template<class G> bool operator()(G& g); };
namespace pmr {  // <memory_resource>
class memory_resource {
public:
  virtual ~memory_resource();
  void* allocate(size_t bytes, size_t alignment = alignof(long double));
  void deallocate(void* p, size_t bytes, size_t alignment = alignof(long double));
protected:
  virtual void* do_allocate(size_t bytes, size_t alignment) = 0;
  virtual void do_deallocate(void* p, size_t bytes, size_t alignment) = 0;
  virtual bool do_is_equal(const memory_resource& other) const noexcept = 0;
};
memory_resource* new_delete_resource() noexcept;
memory_resource* get_default_resource() noexcept;
memory_resource* set_default_resource(memory_resource* r) noexcept;
template<class T = unsigned char> class polymorphic_allocator {
public:
  typedef T value_type;
  polymorphic_allocator() noexcept;
  polymorphic_allocator(memory_resource* r);
  template<class U> polymorphic_allocator(const polymorphic_allocator<U>& o) noexcept;
  T* allocate(size_t n);
  void deallocate(T* p, size_t n);
  memory_resource* resource() const;
};
class monotonic_buffer_resource : public memory_resource {
public:
  monotonic_buffer_resource();
  explicit monotonic_buffer_resource(memory_resource* upstream);
  monotonic_buffer_resource(void* buffer, size_t size, memory_resource* upstream = get_default_resource());
protected:
  void* do_allocate(size_t bytes, size_t alignment) override;
  void do_deallocate(void* p, size_t bytes, size_t alignment) override;
  bool do_is_equal(const memory_resource& other) const noexcept override;
};
class unsynchronized_pool_resource : public monotonic_buffer_resource {};
class synchronized_pool_resource : public monotonic_buffer_resource {};
}  // namespace pmr
}  // namespace std
namespace __gnu_cxx {}
// C++20's mathematical constants: libstdc++ reaches <numbers> from <string>, <memory>
// and the other headers built on its ranges (bits/max_size_type.h), so a C++20 source
// may use std::numbers::pi with no #include of its own (kyubic_ros' localization)
#if __cplusplus > 201703L
#include "numbers"
#endif
#endif
