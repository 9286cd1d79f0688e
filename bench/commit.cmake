# Writes build_commit.hpp: the commit quat_bench is built from, at build time (a configure-time
# value goes stale as soon as a commit or edit follows the configure). Run by the quat_bench_commit
# target on every build; configure_file leaves the file untouched, so nothing recompiles, while the
# commit stays the same.
#   cmake -DSOURCE_DIR=<quat> -DOUTPUT=<file> -P commit.cmake
set(QUAT_BENCH_COMMIT "unknown")  # outside a git checkout
find_package(Git QUIET)
if(GIT_FOUND)
    # "+" after the hash: the work tree had uncommitted changes.
    execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty=+ --abbrev=7
                    WORKING_DIRECTORY "${SOURCE_DIR}" OUTPUT_VARIABLE _commit
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _result)
    if(_result EQUAL 0 AND _commit)
        set(QUAT_BENCH_COMMIT "${_commit}")
    endif()
endif()
file(WRITE "${OUTPUT}.new"
     "// Generated at build time by bench/commit.cmake: the commit quat_bench was built from.\n"
     "#pragma once\n\n"
     "namespace bench::build_info {\n"
     "inline constexpr const char* commit = \"${QUAT_BENCH_COMMIT}\";\n"
     "}  // namespace bench::build_info\n")
configure_file("${OUTPUT}.new" "${OUTPUT}" COPYONLY)
file(REMOVE "${OUTPUT}.new")
