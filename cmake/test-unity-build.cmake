# quat_unity_test_build(<target> <tests dir>): compile a program of quat's test files as a unity
# build, eight files a translation unit. Most of a test file's compile time is quat's templates and
# Catch2's, instantiated and optimized again in every file (g++ 12 -O3, quat_tests: 549 CPU seconds
# against 726 file by file). Each test file keeps its names in a namespace of its own
# (test_<file>), so that the files cannot see each other's helpers; Catch2 still tags each test
# case with its own file. Used by tests/CMakeLists.txt and tests/single_include.
function(quat_unity_test_build target tests_dir)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
    # Compiled alone: Catch2's main; test_glm_namespace.cpp, whose file-scope `using namespace glm;`
    # before quat's headers is the case it tests; test_align_points.cpp, whose pragmas silence g++'s
    # false -Warray-bounds in Eigen::umeyama only where they precede Eigen's headers.
    set_source_files_properties("${tests_dir}/support/catch_main.cpp"
                                "${tests_dir}/test_glm_namespace.cpp"
                                "${tests_dir}/test_align_points.cpp"
                                PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()
