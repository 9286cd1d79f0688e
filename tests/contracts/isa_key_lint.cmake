# The habits the instruction-set key (include/quat/detail/math.hpp) depends on, which the isa_mix
# programs only check on the paths they run. Usage: cmake -DSOURCE_DIR=<repository> -P this file.
# - Every header that defines anything in namespace quat opens the key (includes
#   detail/isa_namespace.inc), except those holding only value types and constants.
# - No std::numeric_limits<T>::epsilon() and the like outside detail/math.hpp: at run time (as at
#   -O0) it is a call to the standard library's inline function, not keyed; use detail::epsilon<T>().
# - No range-for over a braced list: std::initializer_list's members are not keyed either.
# - Every member function written in a type defined outside the key (the value types, and the
#   std::formatter and fmt::formatter specializations and their bases) is [[gnu::always_inline]]
#   or defaulted: a copy emitted out of line would have one name for every instruction set.
# - No type outside the key derives from one inside it (detail::..., or a quat class defined in
#   the key): the derived class would differ from one instruction set to the next.
# The types are read from clang-format's layout: the definition at column 0, its members' first
# lines indented by 4; the key spans from the include of isa_namespace.inc to the line
# `}  // inline namespace isa_...`.
cmake_minimum_required(VERSION 3.21)
# Reads the types that _text defines outside the key, checks their member functions and bases,
# and appends to _quat_unkeyed_types (their names, specializations left out), _quat_bases
# (header|name of each quat class they derive from, checked once every header is read), and
# counts them and their member functions in _quat_type_count and _quat_member_count.
function(_quat_check_unkeyed_types _header _text)
    # One list element per line: the characters a CMake list treats specially are swapped out.
    string(REPLACE "\\" "<backslash>" _text "${_text}")
    string(REPLACE ";" "<semicolon>" _text "${_text}")
    string(REPLACE "[" "<open>" _text "${_text}")
    string(REPLACE "]" "<close>" _text "${_text}")
    string(REPLACE "\n" ";" _lines "${_text}")
    set(_keyed FALSE)
    set(_namespace "")
    set(_type "")       # the type whose definition is being read
    set(_in_body FALSE)
    set(_head "")       # its first lines, up to the brace that opens its body
    set(_statement "")  # a member's first lines, up to its name and parameters
    foreach(_line IN LISTS _lines)
        string(REPLACE "<semicolon>" ";" _line "${_line}")
        string(REPLACE "<open>" "[" _line "${_line}")
        string(REPLACE "<close>" "]" _line "${_line}")
        string(REPLACE "<backslash>" "\\" _line "${_line}")
        if(_line MATCHES "^namespace (quat|std|fmt) {")
            set(_namespace "${CMAKE_MATCH_1}")
        endif()
        if(_line MATCHES "^#include \"[./a-z]*isa_namespace.inc\"")
            set(_keyed TRUE)
        elseif(_line MATCHES "^}  // inline namespace isa_")
            set(_keyed FALSE)
        endif()
        if(_type STREQUAL "")
            if(NOT _keyed AND _line MATCHES "^(struct|class) ([A-Za-z_0-9]+)"
               AND (_line MATCHES "{" OR NOT _line MATCHES ";"))
                set(_type "${CMAKE_MATCH_2}")
                set(_head "")
                set(_in_body FALSE)
                set(_statement "")
                math(EXPR _quat_type_count "${_quat_type_count} + 1")
                if(NOT _line MATCHES "^(struct|class) [A-Za-z_0-9]+<")  # not a specialization
                    list(APPEND _quat_unkeyed_types "${_type}")
                endif()
            else()
                continue()
            endif()
        endif()
        if(NOT _in_body)
            string(APPEND _head " ${_line}")
            if(NOT _head MATCHES "{")
                continue()
            endif()
            # The bases: after the first colon that is not part of a "::", up to the body.
            string(REPLACE "::" "@@" _bases "${_head}")
            string(REGEX REPLACE "{.*$" "" _bases "${_bases}")
            if(_bases MATCHES "^[^:]*:(.*)$")
                set(_bases "${CMAKE_MATCH_1}")
                if(_bases MATCHES "(detail|isa_[a-z0-9_]+)@@")
                    string(STRIP "${_bases}" _bases)
                    string(REPLACE "@@" "::" _bases "${_bases}")
                    string(APPEND _problems
                           "${_header}: ${_type} derives from a keyed class: ${_bases}\n")
                else()
                    # The classes themselves, not their template arguments.
                    while(_bases MATCHES "<[^<>]*>")
                        string(REGEX REPLACE "<[^<>]*>" "" _bases "${_bases}")
                    endwhile()
                    string(REGEX REPLACE "(public|protected|private|virtual) " "" _bases
                                         "${_bases}")
                    string(REPLACE "," ";" _bases "${_bases}")
                    foreach(_name IN LISTS _bases)
                        string(STRIP "${_name}" _name)
                        # quat's own classes: named quat::x, or x in a type defined in quat.
                        if(_name MATCHES "^(@@)?quat@@([A-Za-z_0-9]+)$")
                            list(APPEND _quat_bases "${_header} (${_type})|${CMAKE_MATCH_2}")
                        elseif(_name MATCHES "^[A-Za-z_0-9]+$" AND _namespace STREQUAL "quat")
                            list(APPEND _quat_bases "${_header} (${_type})|${_name}")
                        endif()
                    endforeach()
                endif()
            endif()
            set(_in_body TRUE)
            if(_head MATCHES "}[ ]*;")  # the whole definition on one line: struct x : y {};
                set(_type "")
            endif()
            continue()
        endif()
        if(_line MATCHES "^};")
            set(_type "")
            continue()
        endif()
        # A member begins on a line indented by 4 (deeper lines continue it or are bodies).
        if(_statement STREQUAL "")
            if(NOT _line MATCHES "^    [^ /}]" OR _line MATCHES "^    template <.*>$")
                continue()
            endif()
        endif()
        string(REGEX REPLACE "//.*$" "" _line "${_line}")
        string(APPEND _statement " ${_line}")
        if(NOT _statement MATCHES "[({;]")
            continue()
        endif()
        # Its declarator: up to the body, the end or an initializer, without [[attributes]] and
        # array bounds; a parenthesis left there makes it a function.
        string(REGEX REPLACE "[{;].*$" "" _declarator "${_statement}")
        string(REGEX REPLACE " = .*$" "" _declarator "${_declarator}")
        string(REGEX REPLACE "\\[[^][]*\\]" "" _declarator "${_declarator}")
        string(REGEX REPLACE "\\[[^][]*\\]" "" _declarator "${_declarator}")
        if(_declarator MATCHES "\\("
           AND NOT _declarator MATCHES "^ *(static_assert|using |typedef )")
            math(EXPR _quat_member_count "${_quat_member_count} + 1")
            if(NOT _statement MATCHES "always_inline"
               AND NOT _statement MATCHES "= *(default|delete)")
                string(REGEX REPLACE "[{;].*$" "" _declarator "${_statement}")
                string(REGEX REPLACE "\\[\\[[^]]*\\]\\] *" "" _declarator "${_declarator}")
                string(STRIP "${_declarator}" _declarator)
                string(APPEND _problems "${_header}: ${_type}'s member is not always inline "
                                        "([[gnu::always_inline]]): ${_declarator}\n")
            endif()
        endif()
        set(_statement "")
    endforeach()
    set(_problems "${_problems}" PARENT_SCOPE)
    set(_quat_unkeyed_types "${_quat_unkeyed_types}" PARENT_SCOPE)
    set(_quat_bases "${_quat_bases}" PARENT_SCOPE)
    set(_quat_member_count "${_quat_member_count}" PARENT_SCOPE)
    set(_quat_type_count "${_quat_type_count}" PARENT_SCOPE)
endfunction()

set(_quat_unkeyed_types "")
set(_quat_bases "")
set(_quat_member_count 0)
set(_quat_type_count 0)
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
    _quat_check_unkeyed_types("${_header}" "${_text}")
endforeach()
foreach(_base IN LISTS _quat_bases)
    string(REPLACE "|" ";" _base "${_base}")
    list(GET _base 0 _where)
    list(GET _base 1 _name)
    if(NOT _name IN_LIST _quat_unkeyed_types)
        string(APPEND _problems "${_where}: derives from quat::${_name}, which is keyed\n")
    endif()
endforeach()
if(_problems)
    message(FATAL_ERROR "instruction-set key:\n${_problems}")
endif()
list(LENGTH _headers _count)
message("instruction-set key: ${_count} headers checked, ${_quat_type_count} types outside the "
        "key with ${_quat_member_count} member functions")
