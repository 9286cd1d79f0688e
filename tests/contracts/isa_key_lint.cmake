# The habits the instruction-set key (include/quat/detail/math.hpp) depends on, which the isa_mix
# programs only check on the paths they run. Usage: cmake -DSOURCE_DIR=<repository> -P this file.
# - Every header that defines anything in namespace quat opens the key (includes
#   detail/isa_namespace.inc), except those holding only value types and constants.
# - No std::numeric_limits<T>::epsilon() and the like outside detail/math.hpp: at run time (as at
#   -O0) it is a call to the standard library's inline function, not keyed; use detail::epsilon<T>().
# - No range-for over a braced list: std::initializer_list's members are not keyed either.
cmake_minimum_required(VERSION 3.21)
set(_unkeyed_allowed quat/axis_angle.hpp quat/config.hpp quat/constants.hpp quat/quat.hpp)
file(GLOB_RECURSE _headers RELATIVE "${SOURCE_DIR}/include" "${SOURCE_DIR}/include/quat/*.hpp")
list(SORT _headers)
set(_problems "")
foreach(_header IN LISTS _headers)
    file(READ "${SOURCE_DIR}/include/${_header}" _text)
    if(_text MATCHES "namespace quat" AND NOT _text MATCHES "#include \"[./a-z]*isa_namespace.inc\""
       AND NOT _header IN_LIST _unkeyed_allowed)
        string(APPEND _problems "${_header}: no instruction-set key (see detail/math.hpp)\n")
    endif()
    if(NOT _header STREQUAL "quat/detail/math.hpp"
       AND _text MATCHES "std::numeric_limits<[A-Za-z_:]+>::[a-z_A-Z]+\\(\\)")
        string(APPEND _problems "${_header}: ${CMAKE_MATCH_0} (use detail::epsilon<T>() and the like)\n")
    endif()
    if(_text MATCHES "for \\([^;)]*: {")
        string(APPEND _problems "${_header}: range-for over a braced list: ${CMAKE_MATCH_0}\n")
    endif()
endforeach()
if(_problems)
    message(FATAL_ERROR "instruction-set key:\n${_problems}")
endif()
list(LENGTH _headers _count)
message("instruction-set key: ${_count} headers checked")
