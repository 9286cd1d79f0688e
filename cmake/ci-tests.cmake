# CI steps as CTest tests, so `ctest` is the whole of CI. Included from tests/CMakeLists.txt (before
# tests/contracts, which reads QUAT_TEST_STRICT_WARNINGS). The cheap checks are on by default, and
# so are the ones whose result does not depend on the configuration (consumers, strict warnings,
# std::format), so that a single preset runs everything; the CI presets in CMakePresets.json switch
# those off in all but one configuration and switch the slow once-per-matrix ones on (each preset
# runs a different subset, see docs/ci.md).
option(QUAT_TEST_CONSUMERS "Test the installed package, add_subdirectory and the install without developer tools" ON)
option(QUAT_TEST_STRICT_WARNINGS "Compile every header alone with g++ and clang++ under strict warnings" ON)
option(QUAT_TEST_STD_FORMAT "Build the printing tests with clang++ and libc++ to test std::format" ON)
option(QUAT_TEST_SINGLE_INCLUDE "Compile the test suite against single_include/ only" OFF)
option(QUAT_TEST_FORMAT "Check formatting with clang-format" OFF)
option(QUAT_TEST_TIDY "Run clang-tidy over representative translation units" OFF)
option(QUAT_TEST_VALGRIND "Run quat_tests under valgrind memcheck" OFF)

find_package(Python3 COMPONENTS Interpreter)

# The committed single header must equal a fresh generation from include/quat.
if(Python3_Interpreter_FOUND)
    add_test(NAME single_header_sync
             COMMAND "${Python3_EXECUTABLE}" "${PROJECT_SOURCE_DIR}/tools/amalgamate.py" --check)
    set_tests_properties(single_header_sync PROPERTIES LABELS "ci")
endif()

# The layers of include/quat (docs/architecture.md): no lower header includes an upper one.
if(Python3_Interpreter_FOUND)
    add_test(NAME include_layers
             COMMAND "${Python3_EXECUTABLE}" "${PROJECT_SOURCE_DIR}/tools/check_layers.py")
    set_tests_properties(include_layers PROPERTIES LABELS "ci")
endif()

# Every include path of quat 1.0 still compiles alone and brings its header: a check of the
# headers, not of the configuration, so it runs with the strict-warnings checks.
if(QUAT_TEST_STRICT_WARNINGS)
    set(_quat_standard 17)
    if(CMAKE_CXX_STANDARD)
        set(_quat_standard ${CMAKE_CXX_STANDARD})
    endif()
    add_test(NAME old_include_paths
             COMMAND "${CMAKE_COMMAND}" "-DCXX=${CMAKE_CXX_COMPILER}" "-DSTANDARD=${_quat_standard}"
                     "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
                     "-DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/old-include-paths"
                     -P "${PROJECT_SOURCE_DIR}/cmake/old-include-paths.cmake")
    set_tests_properties(old_include_paths PROPERTIES LABELS "ci")
endif()

# The consumer projects are built with this configuration's compiler, standard and flags, so the
# sanitizer and -Werror settings of the preset apply to them too.
set(_quat_consumer_options
    "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
    "-DCMAKE_CXX_FLAGS=${CMAKE_CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${CMAKE_EXE_LINKER_FLAGS}"
    "-DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}")
if(CMAKE_CXX_STANDARD)
    list(APPEND _quat_consumer_options "-DCMAKE_CXX_STANDARD=${CMAKE_CXX_STANDARD}")
endif()

function(quat_add_consumer_test name source_dir)
    add_test(NAME ${name}
             COMMAND "${CMAKE_CTEST_COMMAND}"
                     --build-and-test "${source_dir}" "${CMAKE_CURRENT_BINARY_DIR}/${name}"
                     --build-generator "${CMAKE_GENERATOR}"
                     --build-makeprogram "${CMAKE_MAKE_PROGRAM}"
                     --build-options ${_quat_consumer_options} ${ARGN}
                     --test-command "${CMAKE_CTEST_COMMAND}" --output-on-failure)
    # COST: with no timings recorded yet (a clean clone), CTest starts the highest cost first, so
    # the tests that build whole projects do not end up alone at the end of a parallel run.
    set_tests_properties(${name} PROPERTIES LABELS "ci;consumer" COST 50)
endfunction()

if(QUAT_TEST_CONSUMERS)
    set(_quat_prefix "${CMAKE_CURRENT_BINARY_DIR}/package-prefix")
    add_test(NAME package_install
             COMMAND "${CMAKE_COMMAND}" "-DBUILD_DIR=${PROJECT_BINARY_DIR}" "-DPREFIX=${_quat_prefix}"
                     -P "${PROJECT_SOURCE_DIR}/cmake/test-install.cmake")
    set_tests_properties(package_install PROPERTIES LABELS "ci;consumer" FIXTURES_SETUP quat_installed)

    quat_add_consumer_test(package_consumer "${PROJECT_SOURCE_DIR}/tests/package"
                           "-DCMAKE_PREFIX_PATH=${_quat_prefix}"
                           "-DQUAT_EXPECTED_VERSION=${PROJECT_VERSION}")
    set_tests_properties(package_consumer PROPERTIES FIXTURES_REQUIRED quat_installed)

    quat_add_consumer_test(add_subdirectory_consumer "${PROJECT_SOURCE_DIR}/tests/add_subdirectory"
                           "-DQUAT_SOURCE_DIR=${PROJECT_SOURCE_DIR}")

    # `cmake -S . -B build && cmake --install build` with no option, GLM, Eigen, Catch2, Google
    # Benchmark, Doxygen and Python hidden: nothing of the developer build may run or be looked for.
    add_test(NAME install_without_developer_tools
             COMMAND "${CMAKE_COMMAND}" "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
                     "-DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/install-without-developer-tools"
                     "-DGENERATOR=${CMAKE_GENERATOR}" "-DMAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}"
                     "-DCXX_COMPILER=${CMAKE_CXX_COMPILER}"
                     -P "${PROJECT_SOURCE_DIR}/cmake/test-install-without-developer-tools.cmake")
    set_tests_properties(install_without_developer_tools PROPERTIES LABELS "ci;consumer")
endif()

# docs/integration.md "With GLM in the same file": after `using namespace glm;` the unqualified
# `quat::` is ambiguous (glm::quat against namespace quat), which is why the docs write `::quat::`;
# after `using namespace quat;` as well, so are vec3, euler and radians/degrees. Each test compiles
# an unqualified spelling and passes only if the compiler reports that ambiguity; the documented
# spellings are compiled by tests/test_glm_namespace.cpp. The quat:: test is clang only: g++ 12
# does not diagnose that ambiguity ([namespace.udir]/6 makes it ill-formed) and accepts the code.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang|GNU")
    if(CMAKE_CXX_STANDARD)
        set(_quat_glm_flags "-std=c++${CMAKE_CXX_STANDARD}")
    else()
        set(_quat_glm_flags "-std=c++17")
    endif()
    # -isystem /usr/include would break the standard library's #include_next; name only other dirs.
    if(NOT QUAT_GLM_INCLUDE_DIR IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
        list(APPEND _quat_glm_flags -isystem "${QUAT_GLM_INCLUDE_DIR}")
    endif()
    if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
        add_test(NAME glm_unqualified_quat_is_ambiguous
                 COMMAND "${CMAKE_CXX_COMPILER}" ${_quat_glm_flags} -fsyntax-only
                         -I "${PROJECT_SOURCE_DIR}/include"
                         "${PROJECT_SOURCE_DIR}/tests/compile_fail/glm_unqualified_quat.cpp")
        set_tests_properties(glm_unqualified_quat_is_ambiguous PROPERTIES
            LABELS "ci" PASS_REGULAR_EXPRESSION "reference to [^ ]*quat[^ ]* is ambiguous")
    endif()
    # g++: "reference to 'vec3' is ambiguous", "call of overloaded 'radians(double)' is ambiguous";
    # clang: "reference to 'vec3' is ambiguous", "call to 'radians' is ambiguous".
    foreach(_name vec3 euler radians)
        add_test(NAME glm_and_quat_unqualified_${_name}_is_ambiguous
                 COMMAND "${CMAKE_CXX_COMPILER}" ${_quat_glm_flags} -fsyntax-only
                         -I "${PROJECT_SOURCE_DIR}/include"
                         "${PROJECT_SOURCE_DIR}/tests/compile_fail/glm_and_quat_${_name}.cpp")
        set_tests_properties(glm_and_quat_unqualified_${_name}_is_ambiguous PROPERTIES LABELS "ci"
            PASS_REGULAR_EXPRESSION "(reference|call) (to|of overloaded) [^ ]*${_name}[^ ]* is ambiguous")
    endforeach()
endif()

if(QUAT_TEST_SINGLE_INCLUDE)
    # The suite again, against the single header: that it compiles under this configuration's
    # compiler, standard and warnings and passes. The code is the headers' own, which quat_tests
    # has run under the sanitizers already, so this copy is built without them and without debug
    # information (the later -D options win): clang 14, 167 s with ASan, UBSan and -g.
    string(REGEX REPLACE "-f(no-)?sanitize[^ ]*" "" _quat_plain_flags "${CMAKE_CXX_FLAGS}")
    quat_add_consumer_test(single_include_consumer "${PROJECT_SOURCE_DIR}/tests/single_include"
                           "-DQUAT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
                           "-DCMAKE_CXX_FLAGS=${_quat_plain_flags}" "-DCMAKE_EXE_LINKER_FLAGS="
                           "-DCMAKE_BUILD_TYPE=")
    # It builds most of the test suite again: start it first.
    set_tests_properties(single_include_consumer PROPERTIES COST 200)
endif()

if(QUAT_TEST_FORMAT)
    find_program(QUAT_CLANG_FORMAT NAMES clang-format clang-format-14 REQUIRED)
    add_test(NAME format_check
             COMMAND "${CMAKE_COMMAND}" "-DCLANG_FORMAT=${QUAT_CLANG_FORMAT}"
                     "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
                     -P "${PROJECT_SOURCE_DIR}/cmake/format-check.cmake")
    set_tests_properties(format_check PROPERTIES LABELS "ci;lint")
endif()

if(QUAT_TEST_TIDY)
    find_program(QUAT_CLANG_TIDY NAMES clang-tidy clang-tidy-14 REQUIRED)
    if(NOT CMAKE_EXPORT_COMPILE_COMMANDS)
        message(FATAL_ERROR "QUAT_TEST_TIDY needs CMAKE_EXPORT_COMPILE_COMMANDS=ON")
    endif()
    # A few translation units that instantiate most of the library; clang-tidy takes ~30 s each.
    set(_quat_tidy_sources "")
    foreach(_tu tests/test_quaternion.cpp tests/test_euler.cpp tests/test_conversions.cpp
                tests/test_nearest_rotation.cpp tests/test_interpolation.cpp)
        if(EXISTS "${PROJECT_SOURCE_DIR}/${_tu}")
            list(APPEND _quat_tidy_sources "${PROJECT_SOURCE_DIR}/${_tu}")
        endif()
    endforeach()
    # clang-tidy reads each file's command from compile_commands.json, which a unity build lists
    # only by its combined units: these files are compiled alone.
    set_source_files_properties(${_quat_tidy_sources} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    # Without CMAKE_CXX_STANDARD the compile commands may carry no -std (g++ defaults to C++17,
    # clang-tidy 14 to C++14), so state it.
    set(_quat_tidy_std "")
    if(NOT CMAKE_CXX_STANDARD)
        set(_quat_tidy_std "--extra-arg=-std=c++17")
    endif()
    add_test(NAME tidy_check
             COMMAND "${QUAT_CLANG_TIDY}" -p "${PROJECT_BINARY_DIR}" --quiet ${_quat_tidy_std}
                     "--warnings-as-errors=*" ${_quat_tidy_sources})
    set_tests_properties(tidy_check PROPERTIES LABELS "ci;lint" TIMEOUT 600 COST 100)
endif()

if(QUAT_TEST_VALGRIND)
    find_program(QUAT_VALGRIND valgrind REQUIRED)
    # The test judges memory errors only: valgrind computes x87 long double at double precision, so
    # assertions that compare against long double references fail under it by design (they are
    # checked natively by the unit tests). A memory error or leak makes valgrind print a non-zero
    # ERROR SUMMARY, and that is what fails the test.
    # Under valgrind the whole suite is the longest test of the matrix, so it runs in
    # QUAT_MEMCHECK_SHARDS parts (test files dealt round-robin; Catch2's "[#a],[#b]" is a or b),
    # which CTest runs side by side; together they cover every test file once, all but the test
    # cases tagged [sweep]: statistical and reference sweeps that repeat, thousands of times, code
    # the other cases run (about half the suite's native run time; they run in every other
    # configuration, the sanitized ones included). A file without test cases in this configuration
    # (test_io_format.cpp without <format>) only makes Catch2 say "No test cases matched" for its
    # part of the filter.
    set(QUAT_MEMCHECK_SHARDS 8 CACHE STRING "Number of CTest tests the valgrind run is split into")
    get_target_property(_quat_memcheck_files quat_tests SOURCES)
    list(FILTER _quat_memcheck_files EXCLUDE REGEX "catch_main\\.cpp$")
    set(_shard 0)
    foreach(_file IN LISTS _quat_memcheck_files)
        get_filename_component(_stem "${_file}" NAME_WE)
        math(EXPR _shard "(${_shard} % ${QUAT_MEMCHECK_SHARDS}) + 1")
        list(APPEND _quat_memcheck_spec_${_shard} "[#${_stem}]~[.]~[sweep]")
    endforeach()
    foreach(_shard RANGE 1 ${QUAT_MEMCHECK_SHARDS})
        if(NOT _quat_memcheck_spec_${_shard})
            continue()
        endif()
        list(JOIN _quat_memcheck_spec_${_shard} "," _spec)
        add_test(NAME memcheck_${_shard}
                 COMMAND "${QUAT_VALGRIND}" --error-exitcode=1 --leak-check=full
                         --errors-for-leak-kinds=definite,indirect $<TARGET_FILE:quat_tests>
                         "-#" "${_spec}" --reporter compact)
        set_tests_properties(memcheck_${_shard} PROPERTIES
            LABELS "ci;valgrind" TIMEOUT 1800 COST 100
            PASS_REGULAR_EXPRESSION "ERROR SUMMARY: 0 errors from 0 contexts"
            FAIL_REGULAR_EXPRESSION "ERROR SUMMARY: [1-9]")
    endforeach()
endif()

if(QUAT_BUILD_TESTS AND CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    # Users build with -O1 -fsanitize=address (the sanitizers' recommended setting) and -Werror;
    # there clang cannot honour the batch loops' vectorize pragmas and would warn (-Wpass-failed).
    # This compiles the batch tests that way, with the library's headers as user code sees them.
    add_test(NAME clang_o1_sanitize_werror
             COMMAND "${CMAKE_CXX_COMPILER}" -std=c++17 -O1 -fsanitize=address,undefined
                     -Wall -Wextra -Wpedantic -Werror -I "${PROJECT_SOURCE_DIR}/include"
                     -I "${PROJECT_SOURCE_DIR}/tests" -c "${PROJECT_SOURCE_DIR}/tests/test_rotations.cpp"
                     -o "${PROJECT_BINARY_DIR}/clang_o1_sanitize_werror.o")
    set_tests_properties(clang_o1_sanitize_werror PROPERTIES LABELS "ci;lint")
endif()
