# CTest test old_include_paths: every include path a user of quat 1.0 can have written keeps
# compiling. Each old path is a one-line header that forwards to the header's place in its family
# (docs/architecture.md, "Include paths before 1.1"); this compiles each alone, against include/
# and, where the single-header edition has it, against single_include/, and checks that it brought
# the header it names (its include guard is defined).
#   cmake -DCXX=<compiler> -DSTANDARD=<17|20> -DSOURCE_DIR=<quat> -DWORK_DIR=<dir> -P this
file(GLOB _candidates RELATIVE "${SOURCE_DIR}/include/quat" "${SOURCE_DIR}/include/quat/*.hpp")
list(SORT _candidates)
file(MAKE_DIRECTORY "${WORK_DIR}")
set(_checked 0)
set(_failures 0)
foreach(_old IN LISTS _candidates)
    file(READ "${SOURCE_DIR}/include/quat/${_old}" _text)
    if(NOT _text MATCHES "This header moved to quat/([a-z_/0-9]+\\.hpp)")
        continue()
    endif()
    set(_new "${CMAKE_MATCH_1}")
    if(NOT EXISTS "${SOURCE_DIR}/include/quat/${_new}")
        message("FAIL quat/${_old} forwards to quat/${_new}, which does not exist")
        math(EXPR _failures "${_failures} + 1")
        continue()
    endif()
    string(MAKE_C_IDENTIFIER "${_new}" _guard)
    string(TOUPPER "QUAT_${_guard}_INCLUDED" _guard)
    string(MAKE_C_IDENTIFIER "${_old}" _name)
    # Against include/, the guard of the header it names must be defined; the single-header edition
    # inlines that header, so there the old path only has to compile.
    set(_unit_include "${WORK_DIR}/${_name}.cpp")
    file(WRITE "${_unit_include}" "#include <quat/${_old}>\n#ifndef ${_guard}\n#error quat/${_old} did not bring quat/${_new}\n#endif\nint main() { return 0; }\n")
    set(_roots include)
    if(EXISTS "${SOURCE_DIR}/single_include/quat/${_old}")
        set(_unit_single_include "${WORK_DIR}/${_name}_single.cpp")
        file(WRITE "${_unit_single_include}" "#include <quat/${_old}>\nint main() { return 0; }\n")
        list(APPEND _roots single_include)
    endif()
    foreach(_root IN LISTS _roots)
        set(_unit "${_unit_${_root}}")
        execute_process(COMMAND "${CXX}" -std=c++${STANDARD} -Wall -Wextra -Wpedantic -Werror
                                -fsyntax-only "-I${SOURCE_DIR}/${_root}" "${_unit}"
                        RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
        math(EXPR _checked "${_checked} + 1")
        if(NOT _result EQUAL 0)
            math(EXPR _failures "${_failures} + 1")
            message("FAIL quat/${_old} against ${_root}/\n${_out}")
        endif()
    endforeach()
endforeach()
if(_checked EQUAL 0)
    message(FATAL_ERROR "no old include path found: the forwarding headers' wording changed?")
endif()
if(_failures GREATER 0)
    message(FATAL_ERROR "${_failures} of ${_checked} old include paths fail")
endif()
message(STATUS "${_checked} old include paths compile alone")
