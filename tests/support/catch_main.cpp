// The one translation unit that holds Catch2's main(), shared by every tests/test_*.cpp.
#if __has_include(<catch2/catch_session.hpp>)
// Catch2 v3: the session is a library class; run it ourselves so Catch2::Catch2 suffices.
#include <catch2/catch_session.hpp>

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
#else
// Catch2 v2: the single header generates main() when this macro is set.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
#endif
