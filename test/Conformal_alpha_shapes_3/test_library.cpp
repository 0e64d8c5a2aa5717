// The test runner of test_library: Boost.Test's main, for the suites of the
// test files compiled into it (test/Conformal_alpha_shapes_3/CMakeLists.txt).
#define BOOST_TEST_MODULE test_library
#include <boost/test/unit_test.hpp>
