// haros_arch stand-in: googletest (declarations only). A test's body parses as a
// function (TEST) or a member of a class derived from its fixture (TEST_F, TEST_P); the
// checks are calls that take any arguments and any streamed message, so the ROS calls
// written inside them and in the bodies are read like any other.
#ifndef HAROS_STANDIN_GTEST_H
#define HAROS_STANDIN_GTEST_H
#include <string>
namespace testing {
struct haros_sink {
  template<class T> haros_sink& operator<<(const T& value);
};
template<class... A> haros_sink haros_check(A&&... args);
class Test {
public:
  virtual ~Test();
  virtual void TestBody();
protected:
  virtual void SetUp();
  virtual void TearDown();
  static void SetUpTestCase();
  static void TearDownTestCase();
  static void SetUpTestSuite();
  static void TearDownTestSuite();
};
template<class T> class WithParamInterface {
public:
  const T& GetParam() const;
};
template<class T> class TestWithParam : public Test, public WithParamInterface<T> {};
class Environment {
public:
  virtual ~Environment();
  virtual void SetUp();
  virtual void TearDown();
};
Environment* AddGlobalTestEnvironment(Environment* env);
void InitGoogleTest(int* argc, char** argv);
void InitGoogleMock(int* argc, char** argv);
template<class... A> int haros_values(A&&... args);
// a test's registration, made before main() as googletest's is (what it names runs)
template<class T> int haros_register();
int haros_register(void (*test)());
}  // namespace testing
int RUN_ALL_TESTS();
#define HAROS_GTEST_STATEMENT(statement) \
  if (true) { statement; } else ::testing::haros_sink()
#define TEST(suite, name) \
  void suite##_##name##_Test(); \
  static const int suite##_##name##_registered = ::testing::haros_register(&suite##_##name##_Test); \
  void suite##_##name##_Test()
#define HAROS_GTEST_MEMBER(fixture, name) \
  class fixture##_##name##_Test : public fixture { public: void TestBody(); }; \
  static const int fixture##_##name##_registered = \
    ::testing::haros_register<fixture##_##name##_Test>(); \
  void fixture##_##name##_Test::TestBody()
#define TEST_F(fixture, name) HAROS_GTEST_MEMBER(fixture, name)
#define TEST_P(fixture, name) HAROS_GTEST_MEMBER(fixture, name)
#define INSTANTIATE_TEST_SUITE_P(prefix, fixture, ...) \
  static int prefix##_##fixture##_values = ::testing::haros_values(__VA_ARGS__)
#define INSTANTIATE_TEST_CASE_P(prefix, fixture, ...) \
  INSTANTIATE_TEST_SUITE_P(prefix, fixture, __VA_ARGS__)
#define ADD_FAILURE() ::testing::haros_sink()
#define FAIL() ::testing::haros_sink()
#define SUCCEED() ::testing::haros_sink()
#define GTEST_SKIP() ::testing::haros_sink()
#define SCOPED_TRACE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_TRUE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_FALSE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_EQ(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_NE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_LT(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_LE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_GT(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_GE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_STREQ(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_STRNE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_STRCASEEQ(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_STRCASENE(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_FLOAT_EQ(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_DOUBLE_EQ(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_NEAR(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_PRED1(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_PRED2(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_PRED_FORMAT2(...) ::testing::haros_check(__VA_ARGS__)
#define EXPECT_THROW(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define EXPECT_ANY_THROW(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define EXPECT_NO_THROW(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define EXPECT_DEATH(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define EXPECT_EXIT(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define ASSERT_TRUE(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_FALSE(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_EQ(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_NE(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_LT(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_LE(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_GT(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_GE(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_STREQ(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_STRNE(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_STRCASEEQ(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_STRCASENE(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_FLOAT_EQ(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_DOUBLE_EQ(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_NEAR(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_PRED1(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_PRED2(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_PRED_FORMAT2(...) ::testing::haros_check(__VA_ARGS__)
#define ASSERT_THROW(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define ASSERT_ANY_THROW(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define ASSERT_NO_THROW(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define ASSERT_DEATH(statement, ...) HAROS_GTEST_STATEMENT(statement)
#define ASSERT_EXIT(statement, ...) HAROS_GTEST_STATEMENT(statement)
#endif
