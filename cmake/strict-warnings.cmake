# Users compile with more warnings than quat's own build: every public header must compile alone,
# and every function template must instantiate, cleanly under these flags with each compiler and
# language standard given. Run by the strict_warnings.* CTest tests, one per compiler and standard
# (so that CTest runs them side by side), and one per compiler for the batch code's instruction sets:
#   cmake -DCOMPILERS="g++;clang++" -DSTANDARDS="17;20" -DSOURCE_DIR=<quat> -DEXTRA_INCLUDES="<dirs>"
#         -DWORK_DIR=<dir> [-DALONE=ON] -P strict-warnings.cmake
#   (STANDARDS empty: the instruction sets only)
# A header's warnings are the same alone or beside the others, so the headers are compiled one
# translation unit each (proving each compiles alone) only with ALONE=ON, which one of the tests
# passes; the others compile them all in one unit, and the instantiation units one by one.
set(_flags -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wdouble-promotion -Wshadow
           -Wold-style-cast -Werror -fsyntax-only)
set(_includes "-I${SOURCE_DIR}/include")
foreach(_dir IN LISTS EXTRA_INCLUDES)
    # A compiler's own default directories must not become -isystem (it breaks #include_next).
    if(_dir AND NOT _dir MATCHES "^/usr(/local)?/include/?$")
        list(APPEND _includes "-isystem${_dir}")
    endif()
endforeach()

file(GLOB_RECURSE _headers RELATIVE "${SOURCE_DIR}/include" "${SOURCE_DIR}/include/quat/*.hpp")
list(SORT _headers)
file(MAKE_DIRECTORY "${WORK_DIR}")
file(GLOB _units "${SOURCE_DIR}/tests/warnings/*.cpp")  # instantiate*.cpp: one per area
list(SORT _units)
set(_instantiations ${_units})
set(_all_headers "")  # the headers' includes, for the unit that has them all (ALONE off)
foreach(_header IN LISTS _headers)
    # An old include path (docs/architecture.md) is a comment and one #include of the header that
    # moved, which is compiled alone here under its own name; old_include_paths compiles the old one.
    file(STRINGS "${SOURCE_DIR}/include/${_header}" _code REGEX "^[^/]")
    if(_code MATCHES "^#include \"[^\"]+\"  // IWYU pragma: export$")
        continue()
    endif()
    string(APPEND _all_headers "#include <${_header}>\n")
    if(ALONE)
        string(MAKE_C_IDENTIFIER "${_header}" _name)
        set(_unit "${WORK_DIR}/${_name}.cpp")
        file(WRITE "${_unit}" "#include <${_header}>\n")
        list(APPEND _units "${_unit}")
    endif()
endforeach()
if(NOT ALONE)
    set(_unit "${WORK_DIR}/all_headers.cpp")
    file(WRITE "${_unit}" "${_all_headers}")
    list(APPEND _units "${_unit}")
endif()

set(_failures 0)
set(_checked 0)
foreach(_compiler IN LISTS COMPILERS)
    foreach(_standard IN LISTS STANDARDS)
        foreach(_unit IN LISTS _units)
            execute_process(COMMAND "${_compiler}" -std=c++${_standard} ${_flags} ${_includes}
                                    "${_unit}"
                            RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
            math(EXPR _checked "${_checked} + 1")
            if(NOT _result EQUAL 0)
                math(EXPR _failures "${_failures} + 1")
                message("FAIL ${_compiler} -std=c++${_standard} ${_unit}\n${_out}")
            endif()
        endforeach()
    endforeach()
endforeach()
# The batch code has paths of its own for AVX and AVX-512 (vector extensions in
# detail/interleaved_points_avx.hpp): instantiate it for those too, in one language standard. AVX2
# and FMA select no code of their own (only the instruction-set namespace's name,
# detail/isa_namespace.inc), so -mavx covers them. Only the batch headers test the instruction set
# (include/quat/batch/), so only the instantiation units that include them (directly or through
# quat.hpp) are compiled again.
# CMAKE_HOST_SYSTEM_PROCESSOR is not set in script mode (cmake -P); ask the host.
cmake_host_system_information(RESULT _host_processor QUERY OS_PLATFORM)
if(NOT STANDARDS AND _host_processor MATCHES "x86_64|AMD64")
    set(_batch_units "")
    foreach(_unit IN LISTS _instantiations)
        file(STRINGS "${_unit}" _batch REGEX "#include <quat/(batch/|quat\\.hpp)")
        if(_batch)
            list(APPEND _batch_units "${_unit}")
        endif()
    endforeach()
    foreach(_compiler IN LISTS COMPILERS)
        foreach(_arch -mavx -march=skylake-avx512)
            foreach(_unit IN LISTS _batch_units)
                execute_process(COMMAND "${_compiler}" -std=c++17 ${_arch} ${_flags} ${_includes}
                                        "${_unit}"
                                RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
                math(EXPR _checked "${_checked} + 1")
                if(NOT _result EQUAL 0)
                    math(EXPR _failures "${_failures} + 1")
                    message("FAIL ${_compiler} -std=c++17 ${_arch} ${_unit}\n${_out}")
                endif()
            endforeach()
        endforeach()
    endforeach()
endif()
message("strict warnings: ${_checked} compilations, ${_failures} failed")
if(_checked EQUAL 0)
    message(FATAL_ERROR "strict warnings: nothing was compiled (no compiler, standard or x86 host)")
endif()
if(_failures GREATER 0)
    message(FATAL_ERROR "quat must compile cleanly with: ${_flags}")
endif()
