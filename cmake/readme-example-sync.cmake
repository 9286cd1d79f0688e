# The README's code sample must be the one tests/test_readme_example.cpp compiles and checks: the
# README block (section "example", #include lines dropped) equals the test's lines between
# "// --- README begin" and "// --- README end", dedented by four spaces.
#   cmake -DSOURCE_DIR=<quat> -P readme-example-sync.cmake
function(text_between text start_marker end_marker result)
    string(FIND "${text}" "${start_marker}" _start)
    if(_start EQUAL -1)
        message(FATAL_ERROR "marker not found: ${start_marker}")
    endif()
    string(LENGTH "${start_marker}" _length)
    math(EXPR _start "${_start} + ${_length}")
    string(SUBSTRING "${text}" ${_start} -1 _rest)
    string(FIND "${_rest}" "${end_marker}" _end)
    if(_end EQUAL -1)
        message(FATAL_ERROR "marker not found: ${end_marker}")
    endif()
    string(SUBSTRING "${_rest}" 0 ${_end} _between)
    set(${result} "${_between}" PARENT_SCOPE)
endfunction()

file(READ "${SOURCE_DIR}/README.md" _readme)
text_between("${_readme}" "<!-- section:example -->\n```cpp\n" "```\n" _block)
string(REGEX REPLACE "#include[^\n]*\n" "" _block "${_block}")
string(REGEX REPLACE "^\n+" "" _block "${_block}")

file(READ "${SOURCE_DIR}/tests/test_readme_example.cpp" _test)
text_between("${_test}" "// --- README begin\n" "    // --- README end" _tested)
string(REGEX REPLACE "(^|\n)    " "\\1" _tested "${_tested}")

if(_block STREQUAL "" OR NOT _block STREQUAL _tested)
    file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/readme-block.txt" "${_block}")
    file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/tested-block.txt" "${_tested}")
    message(FATAL_ERROR "The README example differs from tests/test_readme_example.cpp; compare "
                        "readme-block.txt with tested-block.txt in ${CMAKE_CURRENT_BINARY_DIR}")
endif()
message("README example is the tested one")
